"""linework.Session against the command line: the same lines as its SVG, the same pixels as its
PNG, meshes as arrays like the same mesh from a file, and the command line's error messages."""
import json
import re

import numpy as np
import pytest

import linework
from conftest import SOURCE, assert_lines_match_svg, cli_error, run_cli, svg_groups

SPOT = SOURCE / "scenes/models/spot/spot.glb"
SIZE = (240, 180)


def cli_render(tmp_path, scene, *flags):
    """`linework render` of one frame with --svg: (image, svg groups)."""
    out = tmp_path / "cli"
    run_cli("render", scene, "-o", out, "--device", "cpu", "--svg", out / "lines.svg", *flags)
    return linework.read_image(out / "frame_0000.png"), svg_groups(out / "lines.svg")


def test_lines_and_render_equal_the_cli(tmp_path):
    image, svg = cli_render(tmp_path, "scenes/spot.json", "--size", "240x180")
    s = linework.Session(SOURCE / "scenes/spot.json", device="cpu", size=SIZE)
    lines = s.lines()
    assert list(lines) == ["silhouette", "suggestive", "crease", "border"]
    assert assert_lines_match_svg(lines, svg) > 100
    render = s.render()
    assert render.shape == (180, 240, 4) and render.dtype == np.uint8
    assert np.array_equal(render, image)


def test_a_transparent_render_equals_the_clis_png(tmp_path):
    # Over a transparent background both give straight alpha, as PNG stores it (Python gave
    # the premultiplied frame: [243, 0, 0, 243] where the PNG has [255, 0, 0, 243]).
    scene = tmp_path / "transparent.json"
    scene.write_text(json.dumps({"model": str(SPOT), "size": [240, 180], "shading": "none",
                                 "background": "transparent", "lines": {"silhouette": {"color": [1, 0, 0]}},
                                 "camera": {"eye": [2.6, 0.9, -2.4], "target": [0, 0.05, 0], "fov": 35}}))
    image, _ = cli_render(tmp_path, scene)
    partial = (image[..., 3] > 0) & (image[..., 3] < 255)
    assert (image[partial][:, 0] == 255).sum() > 100  # red silhouette edges, straight
    s = linework.Session(scene, device="cpu")
    assert np.array_equal(s.render(), image)
    assert np.array_equal(s.frame().image, image)


def test_line_sets_scene_equals_the_cli(tmp_path):
    # Four line sets (hidden dashes, a SLAM with a width modifier, noise, an along ramp).
    image, svg = cli_render(tmp_path, "scenes/spot_line_sets.json", "--size", "320x240")
    s = linework.Session(str(SOURCE / "scenes/spot_line_sets.json"), device="cpu", size=(320, 240))
    # One frame, its image and lines from the same drawing (the SLAM set is parameterized:
    # every call is the next frame of a sequence).
    frame = s.frame()
    assert list(frame.lines) == ["hidden", "outline", "suggestive", "creases"]
    assert assert_lines_match_svg(frame.lines, svg) > 100
    assert np.array_equal(frame.image, image)
    # hidden=True adds the runs the "hidden" set selects; they are not visible.
    hidden = s.lines(hidden=True)["hidden"]
    assert hidden and all(not p.visible.any() for p in hidden)


def test_polyline_data(tmp_path):
    s = linework.Session(SPOT, device="cpu", size=SIZE)
    paths = s.lines()["silhouette"]
    assert paths
    view, proj = s.view_matrix, s.projection_matrix
    for p in paths:
        n = len(p)
        assert p.points.shape == (n, 2) and p.position.shape == (n, 3) and p.visible.all()
        assert p.type == "silhouette" and p.line_set == "silhouette"
        assert np.all(np.diff(p.s) > 0)
        # The surface point projects onto the screen point (the pixel centre convention).
        h = np.c_[p.position, np.ones(n)] @ (proj @ view).T
        ndc = h[:, :2] / h[:, 3:]
        pixels = np.c_[(ndc[:, 0] + 1) * SIZE[0] / 2, (ndc[:, 1] + 1) * SIZE[1] / 2]
        assert np.abs(pixels - p.points).max() < 0.05
        # Eye depth is the distance along the view axis.
        eye_space = np.c_[p.position, np.ones(n)] @ view.T
        assert np.allclose(-eye_space[:, 2], p.depth, rtol=1e-4)


def test_mesh_as_arrays_gives_the_glb_lines():
    vertices, faces, normals = linework.load_mesh(SPOT)
    assert vertices.shape[1] == 3 and faces.shape[1] == 3 and faces.max() < len(vertices)
    from_file = linework.Session(SPOT, device="cpu", size=SIZE).lines()
    scene = {"size": list(SIZE)}
    with_normals = linework.Session(scene, vertices=vertices, faces=faces, normals=normals, device="cpu").lines()
    assert list(with_normals) == list(from_file)
    for name in from_file:
        assert len(with_normals[name]) == len(from_file[name]), name
        for a, b in zip(with_normals[name], from_file[name]):
            assert np.array_equal(a.points, b.points) and np.array_equal(a.position, b.position)
    # Without normals too: the line stages weld the mesh and compute their own.
    without = linework.Session(scene, vertices=vertices, faces=faces, device="cpu").lines()
    for name in from_file:
        assert [p.points.tolist() for p in without[name]] == [p.points.tolist() for p in from_file[name]], name
    # Lists and other dtypes convert; the renders agree too.
    listed = linework.Session(scene, vertices=vertices.astype(np.float64).tolist(), faces=faces.astype(np.int64),
                              normals=normals, device="cpu")
    assert np.array_equal(listed.render(), linework.Session(SPOT, device="cpu", size=SIZE).render())


def test_camera_overrides_and_view_matrix(tmp_path):
    image, svg = cli_render(tmp_path, SPOT, "--size", "240x180", "--eye", "2,0.5,2", "--fov", "30")
    s = linework.Session(SPOT, device="cpu", size=SIZE, eye=(2, 0.5, 2), fov=30)
    assert np.array_equal(s.render(), image)
    assert_lines_match_svg(s.lines(), svg)
    # A camera set from its own view matrix draws the same frame, to the rounding of taking
    # the matrix apart into eye, target and up (float inverse; on spot 2 values of 172 800 off by 1).
    s.set_camera(view=s.view_matrix)
    diff = np.abs(s.render().astype(int) - image.astype(int))
    assert diff.max() <= 2 and np.count_nonzero(diff) <= 0.0005 * diff.size
    # The camera set by parts equals the command line's flags for the same camera: the target
    # is the reset camera's (not the one taken apart from the matrix above, 1e-7 off, which
    # multisampled edges show).
    s.reset_camera()
    c = s.camera
    s.set_camera(eye=(1.5, 1.0, -2.0))
    moved, _ = cli_render(tmp_path / "moved", SPOT, "--size", "240x180", "--fov", "30",
                          "--eye", "1.5,1,-2", "--target", ",".join(f"{v:.9g}" for v in c["target"]))
    assert np.array_equal(s.render(), moved)


def test_configure_is_a_scene_edit(tmp_path):
    s = linework.Session(SOURCE / "scenes/spot.json", device="cpu", size=SIZE)
    before = s.render()
    edit = {"lines": {"silhouette": {"width": 4, "color": [0.8, 0.1, 0.1]}, "crease": {"angle": 60}},
            "background": [0.9, 0.9, 1]}
    s.configure(edit)
    scene = json.loads((SOURCE / "scenes/spot.json").read_text())
    scene.update(edit)
    scene["model"] = str(SOURCE / "scenes" / scene["model"])
    scene["size"] = list(SIZE)
    path = tmp_path / "edited.json"
    path.write_text(json.dumps(scene))
    image, svg = cli_render(tmp_path, path)
    after = s.render()
    assert not np.array_equal(after, before)
    assert np.array_equal(after, image)
    assert_lines_match_svg(s.lines(), svg)
    # A bad key raises the scene parser's error and changes nothing.
    with pytest.raises(ValueError, match=r"lines\.silhouette\.width"):
        s.configure({"lines": {"silhouette": {"width": "wide"}}})
    # JSON has no NaN: the key that holds one is named (the json module names none).
    with pytest.raises(ValueError, match=r"^configure: camera\.eye\[1\]: not a finite number \(nan\)$"):
        s.configure({"camera": {"eye": [0.0, float("nan"), 3.0]}})
    assert np.array_equal(s.render(), image)
    assert s.scene["lines"]["silhouette"]["width"] == 4
    # Size and camera change live; an orbit reopens the session (a camera path is its own).
    s.configure({"size": [120, 90], "camera": {"eye": [2, 0.5, 2], "target": [0, 0, 0]}})
    assert s.size == (120, 90) and s.render().shape == (90, 120, 4)
    assert np.allclose(s.camera["eye"], [2, 0.5, 2])
    s.configure({"camera": {"orbit": 90}, "animation": {"frames": [0, 3]}})  # about that camera
    assert s.frame_range == (0, 3)
    s.render(frame=3)  # the orbit's end: a quarter turn about the up axis through the target
    assert np.allclose(s.camera["eye"], [2, 0.5, -2], atol=1e-4) or np.allclose(s.camera["eye"], [-2, 0.5, 2], atol=1e-4)


def test_keys_that_change_nothing_are_python_warnings():
    """A per-type style beside line sets changes nothing: the engine's warning reaches Python's
    `warnings` (catchable, filterable) instead of stderr."""
    s = linework.Session(SOURCE / "scenes/spot.json", device="cpu", size=SIZE)
    with pytest.warns(UserWarning, match=r'lines\.silhouette: width: beside "line_sets" a type\'s switch and style'):
        s.configure({"lines": {"silhouette": {"width": 4}}, "line_sets": [{"name": "all"}]})
    with pytest.warns(UserWarning, match="a ribbon set draws its exemplar"):
        s.configure({"line_sets": [{"name": "r", "style": {"ribbon": str(SOURCE / "scenes/exemplars/chain.png"),
                                                           "alpha": 0.5}}]})


def test_frames_snapshot_and_restore(tmp_path):
    scene = {"model": str(SPOT), "size": [160, 120], "camera": {"orbit": 40},
             "animation": {"frames": [0, 5]},
             "lines": {"silhouette": {"width": 4, "slam": str(SOURCE / "scenes/slams/dots.exr"), "taper": 8}}}
    path = tmp_path / "orbit.json"
    path.write_text(json.dumps(scene))
    out = tmp_path / "seq"
    run_cli("render", path, "-o", out, "--device", "cpu", "--frames", "0:5", "--warmup", "2")
    s = linework.Session(scene, device="cpu")
    frames = list(s.frames(range(0, 6), warmup=2, lines=True))
    assert [f.index for f in frames] == list(range(6))
    for f in frames:
        assert np.array_equal(f.image, linework.read_image(out / f"frame_{f.index:04d}.png")), f.index
        assert f.lines["silhouette"] and f.timings["total_ms"] > 0
        # One key style: total_ms, …, gpu_surface_ms (it was "gpu surface ms").
        assert "gpu_surface_ms" in f.timings and all(re.fullmatch(r"[a-z0-9_]+_ms", k) for k in f.timings), f.timings
    # render(frame=f) draws frame f of the scene's range, in order a coherent sequence too.
    single = linework.Session(scene, device="cpu")
    images = [single.render(frame=f) for f in range(6)]
    out = tmp_path / "plain"
    run_cli("render", path, "-o", out, "--device", "cpu")
    for f, image in enumerate(images):
        assert np.array_equal(image, linework.read_image(out / f"frame_{f:04d}.png")), f
    # A session restored from a snapshot after frame 2 (another session's, as a farm task or a
    # resumed render would) draws frames 3..5 exactly as the uninterrupted one did.
    first = linework.Session(scene, device="cpu")
    for f in range(3):
        first.render(frame=f)
    snap = first.snapshot()
    resumed = linework.Session(scene, device="cpu")
    resumed.restore(snap)
    for f in range(3, 6):
        assert np.array_equal(resumed.render(frame=f), images[f]), f
    # Without the snapshot the parameterization starts afresh and the strokes differ.
    cold = linework.Session(scene, device="cpu")
    assert not np.array_equal(cold.render(frame=3), images[3])


def test_errors_carry_the_cli_messages(tmp_path):
    with pytest.raises(ValueError) as e:
        linework.Session(tmp_path / "missing.json", device="cpu")
    assert str(e.value) == cli_error("render", tmp_path / "missing.json", "-o", tmp_path / "o")
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"model": str(SPOT), "lines": {"silhouette": {"widht": 2}}}))
    with pytest.raises(ValueError) as e:
        linework.Session(bad, device="cpu")
    assert str(e.value) == cli_error("render", bad, "-o", tmp_path / "o")
    broken = tmp_path / "broken.glb"
    broken.write_bytes(b"glTF not really")
    with pytest.raises(ValueError) as e:
        linework.Session(broken, device="cpu")
    assert str(e.value) == cli_error("render", broken, "-o", tmp_path / "o")
    with pytest.raises(ValueError) as e:
        linework.Session(SPOT, device="tpu")
    assert str(e.value) == cli_error("render", SPOT, "-o", tmp_path / "o", "--device", "tpu").replace("--device", "device")
    with pytest.raises(ValueError, match=r"faces: index 9 of triangle 0 is past the 3 vertices"):
        linework.Session(vertices=np.eye(3), faces=[[0, 1, 9]], device="cpu")
    with pytest.raises(ValueError, match=r"vertices: expected an N×3 array"):
        linework.Session(vertices=np.zeros((4, 2)), faces=[[0, 1, 2]], device="cpu")
    with pytest.raises(ValueError, match=r"model: not allowed beside a mesh given as arrays"):
        linework.Session({"model": str(SPOT)}, vertices=np.eye(3), faces=[[0, 1, 2]], device="cpu")
    s = linework.Session(SPOT, device="cpu", size=(64, 48))
    with pytest.raises(ValueError, match="frame and t"):
        s.render(frame=0, t=0.0)
    with pytest.raises(ValueError, match="eye and the target coincide"):
        s.set_camera(eye=s.camera["target"])


def test_bad_edits_and_odd_arguments_leave_a_working_session(tmp_path):
    s = linework.Session(SOURCE / "scenes/spot.json", device="cpu", size=(64, 48))
    image = s.render()
    # A non-live key that fails to load keeps the old session.
    with pytest.raises(ValueError, match="nope.glb"):
        s.configure({"model": str(tmp_path / "nope.glb")})
    assert np.array_equal(s.render(), image)
    with pytest.raises(ValueError, match="configure"):
        s.configure({"lines": {"silhouette": {"width": float("nan")}}})
    # reset_camera() goes back to the configured camera, not the file's.
    s.configure({"camera": {"eye": [0, 0.5, 3], "target": [0, 0, 0]}})
    s.set_camera(eye=(3, 0, 0))
    s.reset_camera()
    assert np.allclose(s.camera["eye"], [0, 0.5, 3])
    # Only a rigid look-at names a camera.
    view = s.view_matrix
    for bad in (view.T, 2 * view, np.diag([1, 1, -1, 1]) @ view):
        with pytest.raises(ValueError, match="rigid"):
            s.set_camera(view=bad)
    with pytest.raises(ValueError, match="up is parallel"):
        linework.Session(SPOT, device="cpu", size=(64, 48), eye=(0, 5, 0), target=(0, 0, 0), up=(0, 1, 0))
    for size in ((10.5, 20), "10x20", (1, 2, 3)):
        with pytest.raises(ValueError, match="size"):
            linework.Session(SPOT, device="cpu", size=size)
    for frames in ((2**31 - 1, 2**31 - 1), (0,), range(0, 2**40)):
        with pytest.raises(ValueError, match="frames"):
            s.frames(frames)
    with pytest.raises(ValueError, match="t: expected a finite time"):
        s.render(1e30)
    with pytest.raises(TypeError, match="scene: expected a path"):
        linework.Session(5, device="cpu")
    with pytest.raises(ValueError, match="faces: index 9223372036854775813 of triangle 0 is out of range"):
        linework.Session(vertices=np.eye(3), faces=np.array([[0, 1, 2**63 + 5]], np.uint64), device="cpu")
    # OBJ and PLY are models: a quad is two triangles; a malformed one names the file.
    (tmp_path / "quad.obj").write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n")
    vertices, faces, _ = linework.load_mesh(tmp_path / "quad.obj")
    assert faces.shape == (2, 3) and vertices.shape == (4, 3)
    (tmp_path / "past.obj").write_text("v 0 0 0\nv 1 0 0\nf 1 2 9\n")
    with pytest.raises(ValueError, match="past.obj: cannot load the mesh: OBJ: vertex index out of range"):
        linework.Session(tmp_path / "past.obj", device="cpu")
    # An image given as a scene is refused by its extension.
    with pytest.raises(ValueError, match="slam-brush.png: unsupported model format '.png'"):
        linework.Session(SOURCE / "scenes/exemplars/slam-brush.png", device="cpu")
    # An error quoting a binary file's bytes still has its message.
    binary = tmp_path / "binary.json"
    binary.write_bytes((SOURCE / "scenes/exemplars/slam-brush.png").read_bytes())
    with pytest.raises(ValueError, match="binary.json: invalid JSON"):
        linework.Session(binary, device="cpu")
    # Polylines are read-only views of their frame.
    p = s.lines()["silhouette"][0]
    with pytest.raises(ValueError):
        p.points[0, 0] = 5


def test_another_scenes_snapshot_is_refused_before_anything_changes():
    spot = linework.Session(SPOT, device="cpu", size=(96, 72), coherent=True)
    spot.render()
    snap = spot.snapshot()
    one_set = {"model": str(SPOT), "line_sets": [{"name": "outline", "select": {"types": ["silhouette"]}}]}
    other = linework.Session(one_set, device="cpu", size=(96, 72))
    with pytest.raises(ValueError, match="snapshot: taken of another scene"):
        other.restore(snap)
    smaller = linework.Session(SPOT, device="cpu", size=(64, 48), coherent=True)
    with pytest.raises(ValueError, match="snapshot: taken of another scene or size"):
        smaller.restore(snap)
    fresh = linework.Session(SPOT, device="cpu", size=(64, 48), coherent=True)
    assert np.array_equal(smaller.render(), fresh.render())


def test_a_scene_of_layers_alone_has_the_svgs_empty_groups():
    s = linework.Session(SOURCE / "scenes/patterns_sheet.json", device="cpu", size=(64, 48))
    assert s.lines() == {"silhouette": [], "suggestive": [], "crease": [], "border": []}
