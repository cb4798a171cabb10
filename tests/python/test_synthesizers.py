"""linework's synthesizers from Python (python/synthesizers.cpp, synthesizers_2d.cpp) against
the command line: the same inputs give the same SLAM, the same ribbon PNG and the same stroke
files, the same seed the same output, and bad input the command line's message as ValueError.

Run by CTest with PYTHONPATH=build/python, LW_SOURCE_DIR (the repository) and LW_LINEWORK_EXE
(the `linework` binary); small inputs so that the file takes a few seconds on lavapipe.
"""
import json
import math
import os
import struct
import subprocess
import threading
import time
import warnings
import xml.etree.ElementTree as ET
import zlib
from pathlib import Path

import numpy as np
import pytest

import linework

SOURCE = Path(os.environ.get("LW_SOURCE_DIR", Path(__file__).resolve().parents[2]))
EXE = os.environ.get("LW_LINEWORK_EXE", str(SOURCE / "build" / "linework"))
EXEMPLARS = SOURCE / "scenes" / "exemplars"
CURVES = SOURCE / "scenes" / "curves"
PATTERNS = SOURCE / "scenes" / "patterns"

# A short open curve (output pixels) for ribbons: 11 pieces of a 64×20 exemplar.
RIBBON_CURVE = [[10.0, 30.0], [40.0, 25.0], [70.0, 35.0], [100.0, 30.0]]


# ---- Helpers: the command line, PNG files, SVG stroke files ----------------------------

def cli(*args):
    """Runs `linework ARGS`; returns stdout, failing the test on a non-zero exit."""
    r = subprocess.run([EXE, *map(str, args)], capture_output=True, text=True)
    assert r.returncode == 0, f"linework {' '.join(map(str, args))} failed:\n{r.stderr}"
    return r.stdout


def cli_error(*args):
    """Runs `linework ARGS`, which must fail; returns its one-line message."""
    r = subprocess.run([EXE, *map(str, args)], capture_output=True, text=True)
    assert r.returncode != 0, f"linework {' '.join(map(str, args))} succeeded"
    lines = [line for line in r.stderr.splitlines() if line.startswith("linework: error: ")]
    assert lines, r.stderr
    return lines[-1][len("linework: error: "):]


def _paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)


def read_png(path):
    """An 8-bit, non-interlaced PNG (grey, grey+alpha, RGB or RGBA) as H×W×4 uint8."""
    data = Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat, header = 8, b"", None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and interlace == 0 and colour in (0, 2, 4, 6), header
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            predictor = (0, a, b, (a + b) // 2, _paeth(a, b, c))[kind]
            line[i] = (line[i] + predictor) & 0xFF
        rows.append(bytes(line))
        previous = line
    pixels = np.frombuffer(b"".join(rows), np.uint8).reshape(height, width, channels)
    if channels == 4:
        return pixels.copy()
    rgba = np.full((height, width, 4), 255, np.uint8)
    if channels in (1, 2):
        rgba[..., :3] = pixels[..., :1]
        if channels == 2:
            rgba[..., 3] = pixels[..., 1]
    else:
        rgba[..., :3] = pixels
    return rgba


def write_png(path, rgba):
    """H×W×4 uint8 as an RGBA PNG (filter 0)."""
    h, w, _ = rgba.shape
    raw = b"".join(b"\x00" + rgba[y].tobytes() for y in range(h))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)) +
                           chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def svg_strokes(path):
    """The point lists of a stroke SVG as `linework` writes it (<polyline points>, <path d="M … Z">)."""
    strokes = []
    for element in ET.parse(path).getroot().iter():
        tag = element.tag.split("}")[-1]
        if tag == "polyline":
            strokes.append(np.array([[float(v) for v in p.split(",")] for p in element.get("points").split()]))
        elif tag == "path":
            tokens = element.get("d").replace("M", " ").replace("L", " ").replace("Z", " ").split()
            strokes.append(np.array([float(v) for v in tokens]).reshape(-1, 2))
    return strokes


def assert_strokes_match_svg(strokes, svg_path):
    expected = svg_strokes(svg_path)
    assert len(strokes) == len(expected)
    for s, e in zip(strokes, expected):
        points = s["points"]
        if len(points) == 1 and not s["closed"]:
            points = np.repeat(points, 2, axis=0)  # the writer repeats a lone point
        assert points.shape == e.shape
        # The SVG keeps six significant digits (%.6g): 0.005 at x over 1000.
        np.testing.assert_allclose(points, e, rtol=1e-5, atol=1e-3)


def assert_strokes_equal_json(strokes, json_path):
    expected = json.loads(Path(json_path).read_text())["strokes"]
    assert len(strokes) == len(expected)
    for s, e in zip(strokes, expected):
        np.testing.assert_array_equal(s["points"], np.float32(e["points"]))
        np.testing.assert_array_equal(s["widths"], np.float32(e["widths"]))
        assert s["color"] == pytest.approx(tuple(e["color"]), abs=1e-7)
        assert s["closed"] == e.get("closed", False)


def curve_points(path):
    return np.array(json.loads(Path(path).read_text())["points"], dtype=np.float64)


# ---- SLAMs ------------------------------------------------------------------------------

SLAM_SMALL = dict(levels=3, length=128, iterations=2)


def test_slam_equals_the_command_line(tmp_path):
    exemplar = EXEMPLARS / "slam-dots.png"
    cli("slam", exemplar, "-o", tmp_path / "cli.exr", "--levels", 3, "--length", 128, "--iterations", 2,
        "--seed", 3, "--threads", 2)
    expected = linework.read_slam(tmp_path / "cli.exr")
    assert expected.shape == (3, 32, 128) and expected.dtype == np.float32

    from_array = linework.slam(read_png(exemplar), seed=3, threads=2, **SLAM_SMALL)
    assert from_array.dtype == np.float32 and from_array.shape == (3, 32, 128)
    np.testing.assert_array_equal(from_array, expected)
    np.testing.assert_array_equal(linework.slam(str(exemplar), seed=3, **SLAM_SMALL), expected)
    # Self-similar by construction: A_1.0[x] = A_0.5[2x mod length].
    np.testing.assert_allclose(from_array[2], from_array[0][:, (2 * np.arange(128)) % 128], atol=1e-6)

    # Written from Python, read back by the engine: the same ink.
    linework.write_slam(tmp_path / "py.exr", from_array, exemplar_name="dots", seed=3)
    np.testing.assert_array_equal(linework.read_slam(tmp_path / "py.exr"), from_array)


def test_slam_is_deterministic_per_seed():
    exemplar = read_png(EXEMPLARS / "slam-dashes.png")
    a = linework.slam(exemplar, seed=5, **SLAM_SMALL)
    np.testing.assert_array_equal(a, linework.slam(exemplar, seed=5, **SLAM_SMALL))
    assert np.abs(a - linework.slam(exemplar, seed=6, **SLAM_SMALL)).max() > 0.05


def test_slam_releases_the_gil():
    # Another Python thread runs while a SLAM is synthesized.
    exemplar = read_png(EXEMPLARS / "slam-scribble.png")
    done, ticks = threading.Event(), []

    def work():
        linework.slam(exemplar, levels=3, length=512, iterations=6, threads=1)
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
        time.sleep(0.002)
    worker.join()
    assert len(ticks) >= 10, f"{len(ticks)} ticks while synthesizing"


def test_slam_pattern_equals_the_command_line(tmp_path):
    cli("slam-pattern", "pencil", "-o", tmp_path / "p.exr", "--levels", 4, "--length", 64, "--height", 8,
        "--seed", 2)
    ink = linework.slam_pattern("pencil", levels=4, length=64, height=8, seed=2)
    assert ink.shape == (4, 8, 64)
    np.testing.assert_array_equal(ink, linework.read_slam(tmp_path / "p.exr"))


def test_slam_bad_input_gives_the_command_lines_message(tmp_path):
    exemplar = EXEMPLARS / "slam-dots.png"
    # A length the pyramid cannot hold: the engine's message, the flag named as the argument.
    message = cli_error("slam", exemplar, "-o", tmp_path / "a.exr", "--length", 1000)
    assert message.startswith("--length: 1000 is not a multiple of 64")
    with pytest.raises(ValueError) as e:
        linework.slam(exemplar, length=1000)
    assert str(e.value) == message[2:]
    # An exemplar too narrow across the stroke: the same message naming the file.
    thin = tmp_path / "thin.png"
    write_png(thin, np.zeros((3, 128, 4), np.uint8))
    message = cli_error("slam", thin, "-o", tmp_path / "a.exr")
    with pytest.raises(ValueError) as e:
        linework.slam(str(thin))
    assert str(e.value) == message
    with pytest.raises(ValueError) as e:
        linework.slam(np.zeros((3, 128), np.uint8))
    assert str(e.value) == message.replace(str(thin), "exemplar")
    # Ranges of the command line's flags, named as arguments; wrong arrays.
    with pytest.raises(ValueError, match="^levels: 1 is not in the range 2 to 256$"):
        linework.slam(exemplar, levels=1)
    with pytest.raises(ValueError, match="^exemplar: expected uint8"):
        linework.slam(np.zeros((32, 128), np.float32))
    with pytest.raises(ValueError, match="no such SLAM file"):
        linework.read_slam(tmp_path / "missing.exr")
    with pytest.raises(ValueError, match=r"^path: .*a SLAM file is OpenEXR \(\.exr\)$"):
        linework.write_slam(tmp_path / "a.png", np.zeros((2, 4, 16), np.float32))
    with pytest.raises(ValueError, match=r"^path: .*/nodir/w\.exr: the folder .*/nodir does not exist$"):
        linework.write_slam(tmp_path / "nodir" / "w.exr", np.zeros((2, 4, 16), np.float32))
    with pytest.raises(ValueError, match=r"^path: .*/nodir/w\.png: the folder .*/nodir does not exist$"):
        linework.write_png(tmp_path / "nodir" / "w.png", np.zeros((4, 4, 4), np.uint8))
    with pytest.raises(ValueError, match=r"^ink: values must lie in \[0, 1\]$"):
        linework.write_slam(tmp_path / "a.exr", np.full((2, 4, 16), 2.0, np.float32))
    # Seeds are whole numbers from 0 (a ValueError, not pybind11's TypeError listing signatures).
    with pytest.raises(ValueError, match=r"^seed: must be a whole number from 0 to 4294967295, got -1$"):
        linework.slam_pattern("dots", seed=-1)
    with pytest.raises(ValueError, match=r"^seed: must be a whole number from 0 to 4294967295, got 4294967296$"):
        linework.slam(exemplar, seed=2**32)
    with pytest.raises(ValueError, match=r"^seed: must be a whole number from 0 to 18446744073709551615, got -5$"):
        linework.ribbon_exemplar("chain", seed=-5)
    with pytest.raises(ValueError, match=r"^seed: must be a whole number from 0 to 18446744073709551615, got 18446744073709551616$"):
        linework.ribbon_exemplar("chain", seed=2**64)
    assert np.array_equal(linework.ribbon_exemplar("chain", seed=2**64 - 1),
                          linework.ribbon_exemplar("chain", seed=2**64 - 1))
    # NumPy integers are whole numbers too; a float or a bool is not a seed.
    assert np.array_equal(linework.ribbon_exemplar("chain", seed=np.int64(3)), linework.ribbon_exemplar("chain", seed=3))
    assert np.array_equal(linework.slam_pattern("dots", seed=np.uint32(3)), linework.slam_pattern("dots", seed=3))
    with pytest.raises(TypeError, match=r"^seed: expected a whole number, got float$"):
        linework.ribbon_exemplar("chain", seed=1.5)


# ---- Ribbons ----------------------------------------------------------------------------

@pytest.fixture(scope="module")
def ribbon_inputs(tmp_path_factory):
    """A small chain exemplar written by `linework ribbon-exemplar` and the curve as a file."""
    folder = tmp_path_factory.mktemp("ribbon")
    cli("ribbon-exemplar", "chain", "--size", "64x20", "-o", folder / "chain.png")
    (folder / "curve.json").write_text(json.dumps({"points": RIBBON_CURVE}))
    # A loop for the closed options (RIBBON_CURVE closed doubles back on itself: no ink).
    loop = [[60.0 + 40.0 * math.cos(2 * math.pi * k / 24), 30.0 + 18.0 * math.sin(2 * math.pi * k / 24)]
            for k in range(24)]
    (folder / "loop.json").write_text(json.dumps({"points": loop}))
    return folder


def test_ribbon_exemplar_equals_the_command_line(ribbon_inputs):
    image = linework.ribbon_exemplar("chain", width=64, height=20)
    assert image.shape == (20, 64, 4) and image.dtype == np.uint8
    np.testing.assert_array_equal(image, read_png(ribbon_inputs / "chain.png"))


def test_ribbon_equals_the_command_lines_png(ribbon_inputs):
    exemplar = read_png(ribbon_inputs / "chain.png")
    cli("ribbon", ribbon_inputs / "chain.png", "--curve", ribbon_inputs / "curve.json", "-o",
        ribbon_inputs / "gpu.png", "--device", "cpu", "--seed", 2, "--dump-dp", ribbon_inputs / "dp.json")
    image, info = linework.ribbon(exemplar, np.array(RIBBON_CURVE), seed=2, device="cpu", return_info=True)
    expected = read_png(ribbon_inputs / "gpu.png")
    assert image.shape == expected.shape == (46, 104, 4) and image.dtype == np.uint8
    np.testing.assert_array_equal(image, expected)
    assert (image[..., 3] == 255).all() and (image[..., :3] < 128).any()  # over white, with a pattern
    # The DP result the command line dumps.
    dump = json.loads((ribbon_inputs / "dp.json").read_text())
    np.testing.assert_array_equal(info["positions"], np.array(dump["positions"]))
    assert info["pieces"] == dump["pieces"]
    assert info["total_cost"] == pytest.approx(dump["total_cost"], rel=1e-6)
    assert info["greedy_cost"] == pytest.approx(dump["greedy_cost"], rel=1e-6)
    assert info["total_cost"] < info["greedy_cost"] < info["random_cost"]
    assert (info["width"], info["piece"], info["scale"], info["size"]) == (18.0, 9.0, 18.0, (104, 46))


def test_ribbon_options_equal_the_command_line(ribbon_inputs):
    # The C++ reference DP, stitching, a transparent background, a given size, the curve
    # and exemplar as files, closed.
    cli("ribbon", ribbon_inputs / "chain.png", "--curve", ribbon_inputs / "loop.json", "-o",
        ribbon_inputs / "ref.png", "--reference", "--stitch", "--transparent", "--closed", "--size", "120x60",
        "--piece", 8, "--width", 16)
    image, info = linework.ribbon(str(ribbon_inputs / "chain.png"), ribbon_inputs / "loop.json", reference=True,
                                  stitch=True, transparent=True, closed=True, size=(120, 60), piece=8, width=16,
                                  return_info=True)
    np.testing.assert_array_equal(image, read_png(ribbon_inputs / "ref.png"))
    assert image.shape == (60, 120, 4) and (image[..., 3] == 0).any() and (image[..., 3] > 0).any()
    assert info["closed"] and info["stitch_after"] <= info["stitch_before"]


def test_ribbon_that_draws_nothing_is_an_error(ribbon_inputs):
    # RIBBON_CURVE closed doubles back within the ribbon's width: every piece is empty, and a
    # blank image is no result (the command refuses it too).
    with pytest.raises(ValueError, match="^curve: the ribbon drew nothing"):
        linework.ribbon(read_png(ribbon_inputs / "chain.png"), RIBBON_CURVE, closed=True, size=(120, 60), piece=8,
                        width=16, reference=True)


def test_ribbon_scale_under_the_pattern_is_named_as_the_cause(ribbon_inputs):
    # As the command line warns: a scale under the pattern's rows cuts every piece, bends or not.
    exemplar = read_png(ribbon_inputs / "chain.png")
    with pytest.warns(RuntimeWarning, match=r"scale 4 is too small for the pattern's 12 rows and one above and below "
                                             r"\(scale 14 holds them\); leave scale out for the default, 18"):
        linework.ribbon(exemplar, RIBBON_CURVE, scale=4, reference=True)


def test_ribbon_is_deterministic_per_seed(ribbon_inputs):
    exemplar = read_png(ribbon_inputs / "chain.png")
    a = linework.ribbon(exemplar, RIBBON_CURVE, seed=3, reference=True)
    np.testing.assert_array_equal(a, linework.ribbon(exemplar, RIBBON_CURVE, seed=3, reference=True))
    # The seed picks among equally good DP ends; a one-colour exemplar would tie everywhere,
    # the chain does not: the seeds' images may agree, but never their random baselines.
    _, i3 = linework.ribbon(exemplar, RIBBON_CURVE, seed=3, reference=True, return_info=True)
    _, i4 = linework.ribbon(exemplar, RIBBON_CURVE, seed=4, reference=True, return_info=True)
    assert i3["random_cost"] != i4["random_cost"]


def test_ribbon_bad_input_gives_the_command_lines_message(ribbon_inputs):
    exemplar = read_png(ribbon_inputs / "chain.png")
    message = cli_error("ribbon", ribbon_inputs / "chain.png", "--curve", ribbon_inputs / "curve.json", "-o",
                        ribbon_inputs / "x.png", "--piece", 0.0001)
    assert message.startswith("--piece: ")
    with pytest.raises(ValueError) as e:
        linework.ribbon(exemplar, RIBBON_CURVE, piece=0.0001)
    assert str(e.value) == message[2:]
    with pytest.raises(ValueError, match="^piece: must be a positive number, got -1$"):
        linework.ribbon(exemplar, RIBBON_CURVE, piece=-1)
    with pytest.raises(ValueError, match="^curve: the curve needs at least two distinct points$"):
        linework.ribbon(exemplar, [[1.0, 1.0], [1.0, 1.0]])
    with pytest.raises(ValueError, match=r"^curve: expected an N×2 array"):
        linework.ribbon(exemplar, np.zeros((4, 3)))
    with pytest.raises(ValueError, match="^exemplar: no opaque pixel"):
        linework.ribbon(np.zeros((20, 64, 4), np.uint8), RIBBON_CURVE)
    with pytest.raises(ValueError, match="^device: "):
        linework.ribbon(exemplar, RIBBON_CURVE, device="quantum")
    with pytest.raises(ValueError, match="^avoid: the avoidance map is 8x8 but the output is 104x46$"):
        linework.ribbon(exemplar, RIBBON_CURVE, avoid=np.zeros((8, 8, 4), np.uint8))
    # A size the ribbon misses would give a blank image: refused, as on the command line.
    message = cli_error("ribbon", ribbon_inputs / "chain.png", "--curve", ribbon_inputs / "curve.json", "-o",
                        ribbon_inputs / "x.png", "--size", "5x5")
    assert message.startswith("--size 5x5: nothing of the ribbon")
    with pytest.raises(ValueError) as e:
        linework.ribbon(exemplar, RIBBON_CURVE, size=(5, 5))
    assert str(e.value) == message[2:]
    # A size no image has: worded as the command line's --size.
    with pytest.raises(ValueError, match=r"^size: must be between 1x1 and 16384x16384, got \(0, 5\)$"):
        linework.ribbon(exemplar, RIBBON_CURVE, size=(0, 5))
    # An avoidance map that forbids everything empties every piece: refused (a blank image);
    # one that forbids half of the image empties some: said, not only in info.
    with pytest.raises(ValueError, match="^curve: the ribbon drew nothing: .* or where `avoid` forbids ink$"):
        linework.ribbon(exemplar, RIBBON_CURVE, avoid=np.full((46, 104, 4), 255, np.uint8), reference=True)
    half = np.zeros((46, 104, 4), np.uint8)
    half[:, :52] = 255
    with pytest.warns(RuntimeWarning, match="pieces lie where no ink can avoid the overlap"):
        linework.ribbon(exemplar, RIBBON_CURVE, avoid=half, reference=True)


# ---- Stroke patterns --------------------------------------------------------------------

def crosses(seed):
    """A jittered grid of small red crosses as stroke dicts."""
    rng = np.random.default_rng(seed)
    strokes = []
    for gx in range(6):
        for gy in range(4):
            c = np.array([20.0 + 18 * gx, 20.0 + 18 * gy]) + rng.uniform(-2, 2, 2)
            r = rng.uniform(4, 6)
            strokes.append({"points": [c - [r, 0], c + [r, 0]], "width": 1.5, "color": (0.8, 0.1, 0.1)})
            strokes.append({"points": np.array([c - [0, r], c + [0, r]]), "widths": [1.0, 2.0], "color": "#202060"})
    return strokes


def test_pattern_equals_the_command_lines_strokes(tmp_path):
    region = CURVES / "circle.json"
    cli("pattern", PATTERNS / "flowers.svg", "--region", region, "-o", tmp_path / "p.svg", "--seed", 4)
    cli("pattern", PATTERNS / "flowers.svg", "--region", region, "-o", tmp_path / "p.json", "--seed", 4)
    strokes, info = linework.pattern(str(PATTERNS / "flowers.svg"), region=curve_points(region), seed=4,
                                     return_info=True)
    assert len(strokes) > 50
    assert all(s["points"].dtype == np.float32 and s["points"].shape[1] == 2 for s in strokes)
    assert_strokes_match_svg(strokes, tmp_path / "p.svg")
    assert_strokes_equal_json(strokes, tmp_path / "p.json")
    # Every element but the centre seed is matched or takes the closest neighbourhood.
    assert info["matched"] + info["fallback"] == len(info["source"]) - 1
    assert info["first_stroke"][-1] == len(strokes)


def test_pattern_from_python_strokes_along_a_path(tmp_path):
    # The reference as Python data; the command line reads the same strokes from JSON.
    reference = crosses(1)
    (tmp_path / "ref.json").write_text(json.dumps({"strokes": [
        {"points": np.asarray(s["points"]).tolist(), **{k: v for k, v in s.items() if k != "points"}}
        for s in reference]}))
    cli("pattern", tmp_path / "ref.json", "--path", CURVES / "wave.json", "-o", tmp_path / "p.json", "--scale", 8,
        "--rings", 2, "--variation", 0.5, "--fit", "skeleton", "--lloyd", 10)
    strokes = linework.pattern(reference, path=CURVES / "wave.json", scale=8, rings=2, variation=0.5,
                               fit="skeleton", lloyd=10)
    assert_strokes_equal_json(strokes, tmp_path / "p.json")
    # Strokes out are strokes in: the output feeds the synthesizer again (at a scale that keeps
    # its crosses apart: at 8, the crosses placed along the path touch, and all are one element).
    again, info = linework.pattern(strokes, region=[[0, 0], [120, 0], [120, 90], [0, 90]], scale=2, return_info=True)
    assert info["reference_elements"] > 100 and len(again) > 0


def test_pattern_is_deterministic_per_seed():
    region = curve_points(CURVES / "circle.json")
    a = linework.pattern(PATTERNS / "stipples.svg", region=region, seed=7)
    b = linework.pattern(PATTERNS / "stipples.svg", region=region, seed=7)
    c = linework.pattern(PATTERNS / "stipples.svg", region=region, seed=8)
    assert len(a) == len(b) and all(np.array_equal(x["points"], y["points"]) for x, y in zip(a, b))
    assert len(a) != len(c) or any(not np.array_equal(x["points"], y["points"]) for x, y in zip(a, c))


def test_pattern_of_one_element_warns_as_the_command_line_does():
    region = curve_points(CURVES / "circle.json")
    with pytest.warns(UserWarning, match=r"flowers\.svg: its 276 strokes are one element at scale ε = 1e\+30"):
        one = linework.pattern(PATTERNS / "flowers.svg", region=region, scale=1e30)
    assert len(one) == 276
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        linework.pattern(PATTERNS / "flowers.svg", region=region)


def test_pattern_bad_input_gives_the_command_lines_message(tmp_path):
    two = tmp_path / "two.json"
    two.write_text(json.dumps({"points": [[0, 0], [10, 0]]}))
    message = cli_error("pattern", PATTERNS / "crosses.svg", "--region", two, "-o", tmp_path / "x.svg")
    with pytest.raises(ValueError) as e:
        linework.pattern(PATTERNS / "crosses.svg", region=two)
    assert str(e.value) == message
    with pytest.raises(ValueError) as e:
        linework.pattern(PATTERNS / "crosses.svg", region=[[0, 0], [10, 0]])
    assert str(e.value) == message.replace(str(two), "region")
    with pytest.raises(ValueError, match="^give exactly one of path and region$"):
        linework.pattern(crosses(1))
    with pytest.raises(ValueError, match=r"^reference\[0\]\.colour: unknown key$"):
        linework.pattern([{"points": [[0, 0], [1, 1]], "colour": (1, 0, 0)}], region=[[0, 0], [9, 0], [9, 9]])
    with pytest.raises(ValueError, match=r"^reference\[1\]: colour components must lie in \[0, 1\]$"):
        linework.pattern([[[0, 0], [1, 1]], {"points": [[0, 0]], "color": (2, 0, 0)}], region=[[0, 0], [9, 0], [9, 9]])
    with pytest.raises(ValueError, match=r"^reference: the reference has no strokes$"):
        linework.pattern([], region=[[0, 0], [9, 0], [9, 9]])
    with pytest.raises(ValueError, match="^rings: 13 is not in the range 1 to 12$"):
        linework.pattern(crosses(1), region=[[0, 0], [9, 0], [9, 9]], rings=13)


# ---- Hatching ---------------------------------------------------------------------------

def test_hatch_equals_the_command_lines_strokes(tmp_path):
    training = PATTERNS / "hatch_training.svg"
    out = cli("hatch", training, "-o", tmp_path / "h.svg", "--count", 120, "--seed", 5, "--kl2")
    cli("hatch", training, "-o", tmp_path / "h.json", "--count", 120, "--seed", 5)
    strokes, info = linework.hatch(training, count=120, seed=5, return_info=True)
    assert len(strokes) == 120
    assert_strokes_match_svg(strokes, tmp_path / "h.svg")
    assert_strokes_equal_json(strokes, tmp_path / "h.json")
    # The blocks --kl2 prints.
    printed = [line for line in out.splitlines() if line.startswith("block ")]
    assert printed == [f"block {b['index']} strokes {b['first']}-{b['last']} KL2 {b['kl2']:.4f}"
                       for b in info["blocks"]]
    # 50 + 50 + 20: the last block is held to a threshold of its own size.
    assert info["blocks"][0]["threshold"] == info["threshold"]
    assert info["blocks"][2]["threshold"] > info["threshold"]


def hatch_training(seed):
    """A hand-drawn-like sequence of 30 slanted strokes as N×2 arrays and dicts."""
    rng = np.random.default_rng(seed)
    strokes, x = [], 0.0
    for i in range(30):
        x += rng.uniform(3, 6)
        top = np.array([x + rng.uniform(-1, 1), rng.uniform(0, 4)])
        bottom = top + [rng.uniform(4, 8), rng.uniform(25, 35)]
        middle = 0.5 * (top + bottom) + rng.uniform(-1, 1, 2)
        points = np.array([top, middle, bottom])
        strokes.append(points if i % 2 else {"points": points, "width": float(rng.uniform(0.8, 1.6))})
    return strokes


def test_hatch_along_paths_from_python_data(tmp_path):
    # The training as Python data; the command line reads the same strokes from JSON.
    training = hatch_training(3)
    as_json = [{"points": s.tolist()} if isinstance(s, np.ndarray) else
               {"points": s["points"].tolist(), "width": s["width"]} for s in training]
    (tmp_path / "train.json").write_text(json.dumps({"strokes": as_json}))
    paths = PATTERNS / "hatch_paths.svg"
    cli("hatch", tmp_path / "train.json", "-o", tmp_path / "h.json", "--count", 40, "--along", paths, "--window", 4,
        "--block", 20, "--threshold", 0, "--plausible", 0.8, "--seed", 9)
    strokes = linework.hatch(training, count=40, along=paths, window=4, block=20, threshold=0, plausible=0.8, seed=9)
    assert len(strokes) > 0
    assert_strokes_equal_json(strokes, tmp_path / "h.json")


def test_hatch_is_deterministic_per_seed():
    training = PATTERNS / "hatch_training.svg"
    a = linework.hatch(training, count=80, seed=1)
    b = linework.hatch(training, count=80, seed=1)
    c = linework.hatch(training, count=80, seed=2)
    assert all(np.array_equal(x["points"], y["points"]) for x, y in zip(a, b))
    assert any(not np.array_equal(x["points"], y["points"]) for x, y in zip(a, c))


def test_hatch_bad_input_gives_the_command_lines_message(tmp_path):
    training = PATTERNS / "hatch_training.svg"
    message = cli_error("hatch", training, "-o", tmp_path / "x.svg", "--count", 10, "--window", 41)
    assert message.startswith("--window: ")
    with pytest.raises(ValueError) as e:
        linework.hatch(str(training), count=10, window=41)
    assert str(e.value) == message[2:].replace("give --window ", "give window=")
    with pytest.raises(ValueError, match="^training: hatching needs a training sequence of at least 3 strokes$"):
        linework.hatch([[[0, 0], [0, 10]], [[5, 0], [5, 10]]], count=10)
    with pytest.raises(ValueError, match="^count: 0 is not in the range 1 to 1000000$"):
        linework.hatch(training, count=0)
    with pytest.raises(ValueError, match=r"^training: expected a list of strokes, got one N×2 array"):
        linework.hatch(np.zeros((5, 2)), count=10)
    # An empty list of paths is refused, as an --along file without strokes (not ignored).
    with pytest.raises(ValueError, match="^along: no strokes$"):
        linework.hatch(training, count=10, along=[])
