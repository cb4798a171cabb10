"""examples/camera_ring.py runs as its docstring says and draws every view it was asked for."""
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

from conftest import SOURCE


def test_camera_ring_example_writes_every_view(tmp_path):
    out = tmp_path / "ring.svg"
    done = subprocess.run([sys.executable, SOURCE / "examples/camera_ring.py", "-n", "4", "--size", "160x120",
                           "--device", "cpu", "-o", out], capture_output=True, text=True, env=os.environ, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "4 views" in done.stdout
    ns = {"svg": "http://www.w3.org/2000/svg"}
    views = ET.parse(out).getroot().findall("svg:g", ns)
    assert len(views) == 4
    for g in views:  # a silhouette in every view
        assert any(p.get("stroke") == "#111111" for p in g.findall("svg:polyline", ns))
