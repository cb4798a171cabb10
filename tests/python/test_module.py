"""The module's surface: its type stubs name exactly what it binds (with docstrings), and
sessions used from several threads at once draw what they draw alone."""
import ast
import inspect
import threading

import numpy as np

import linework
from conftest import SOURCE


def stub_names():
    tree = ast.parse((SOURCE / "python/linework.pyi").read_text())
    top, classes = set(), {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            top.add(node.name)
        if isinstance(node, ast.ClassDef):
            members = set()
            for item in node.body:
                if isinstance(item, ast.FunctionDef):
                    members.add(item.name)
                elif isinstance(item, ast.AnnAssign) and isinstance(item.target, ast.Name):
                    members.add(item.target.id)
            classes[node.name] = members
    return top, classes


def public(names):
    return {n for n in names if not n.startswith("_")}


def test_stubs_name_every_binding():
    top, classes = stub_names()
    bound = {n for n in public(dir(linework)) if callable(getattr(linework, n))}
    typed_dicts = {n for n in top if n not in bound and n in classes}  # TypedDicts exist in the stubs only
    assert bound == top - typed_dicts, (bound ^ (top - typed_dicts))
    for name in bound:
        obj = getattr(linework, name)
        assert (obj.__doc__ or "").strip() or name in ("FrameIterator",), f"{name} has no docstring"
        if inspect.isclass(obj):
            assert public(dir(obj)) - {"__iter__", "__next__"} <= classes[name] | {"__len__"}, \
                (name, public(dir(obj)) - classes[name])
            assert public(classes[name]) <= public(dir(obj)), (name, public(classes[name]) - public(dir(obj)))


def test_sessions_in_threads_draw_what_they_draw_alone():
    scenes = [SOURCE / "scenes/spot.json", SOURCE / "scenes/models/spot/spot.glb"]
    alone = [linework.Session(s, device="cpu", size=(160, 120)).render() for s in scenes]
    sessions = [linework.Session(s, device="cpu", size=(160, 120)) for s in scenes]
    results = [[None] * 8 for _ in scenes]

    def work(k):
        for i in range(8):
            results[k][i] = sessions[k].render()

    threads = [threading.Thread(target=work, args=(k,)) for k in range(len(scenes))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for k, images in enumerate(results):
        for image in images:
            assert np.array_equal(image, alone[k])
    assert not any(s.validation_messages for s in sessions)


def test_time_and_frame_name_the_same_frame():
    s = linework.Session(SOURCE / "scenes/spot.json", device="cpu", size=(96, 72))
    assert np.array_equal(s.render(0.0), s.render(frame=0))
