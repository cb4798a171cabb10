"""Shared fixtures of the Python tests: where the repository and the command line are, running
the command line, and reading its SVG back.

CTest sets LW_SOURCE_DIR, LW_LINEWORK_EXE, PYTHONPATH (build/python) and LINEWORK_VALIDATION=1
(CMakeLists.txt); run by hand, the defaults below find a build in build/.
"""
import os
import pathlib
import subprocess
import xml.etree.ElementTree as ET

import numpy as np
import pytest

SOURCE = pathlib.Path(os.environ.get("LW_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
LINEWORK = os.environ.get("LW_LINEWORK_EXE", str(SOURCE / "build" / "linework"))
BENCH = os.environ.get("LW_BENCH_EXE", str(SOURCE / "build" / "linework-bench"))


def run_cli(*args, check=True):
    """Runs `linework ARGS` from the repository root; returns the CompletedProcess."""
    done = subprocess.run([LINEWORK, *map(str, args)], cwd=SOURCE, capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"linework {' '.join(map(str, args))} failed ({done.returncode}):\n{done.stderr}")
    return done


def cli_error(*args):
    """The one-line message `linework ARGS` fails with (without its 'linework: error: ' prefix)."""
    done = run_cli(*args, check=False)
    assert done.returncode != 0, f"linework {' '.join(map(str, args))} should fail"
    lines = [l for l in done.stderr.splitlines() if l.startswith("linework: error: ")]
    assert lines, done.stderr
    return lines[-1][len("linework: error: "):]


def svg_groups(path):
    """{line set: [N×2 float64 array per <polyline>]} of an SVG `linework render --svg` wrote."""
    ns = {"svg": "http://www.w3.org/2000/svg"}
    groups = {}
    for g in ET.parse(path).getroot().findall("svg:g", ns):
        # The drawing is <g id=NAME> (filled shapes); its paths are <g id=NAME-centerlines>.
        if not g.get("id", "").endswith("-centerlines"):
            continue
        polylines = []
        for p in g.findall("svg:polyline", ns):
            pts = [tuple(map(float, xy.split(","))) for xy in p.get("points").split()]
            polylines.append(np.array(pts))
        groups[g.get("id")[: -len("-centerlines")]] = polylines
    return groups


def assert_lines_match_svg(lines, svg, tolerance=1e-3):
    """The Session's lines are the SVG's polylines: same groups, same paths in the same order,
    every point within `tolerance` pixels (a closed loop's SVG repeats its first point)."""
    assert list(lines) == list(svg), (list(lines), list(svg))
    total = 0
    for name, paths in lines.items():
        assert len(paths) == len(svg[name]), f"{name}: {len(paths)} paths against the SVG's {len(svg[name])}"
        for mine, theirs in zip(paths, svg[name]):
            points = np.vstack([mine.points, mine.points[:1]]) if mine.closed else mine.points
            assert points.shape == theirs.shape, f"{name}: {points.shape} against {theirs.shape}"
            assert np.abs(points - theirs).max() <= tolerance, f"{name}: off by {np.abs(points - theirs).max()}"
            total += len(points)
    return total


@pytest.fixture
def repo():
    return SOURCE
