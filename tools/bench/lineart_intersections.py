# tools/bench/lineart_intersections.py — Blender's Line Art on the scene that
# `linework-bench lines MODEL --extract-only --crossed-copy` times: the model and a copy of it
# turned 30° about the vertical through its centre and moved by a third of its size, so that
# the two cut through each other. Line Art is the peer the line-family issue names for
# intersection lines; it finds them again every frame.
#
# Run with Blender 3.4 (Debian 12's `blender` package; not a dependency of Linework):
#
#   blender -b -t 1 --debug-value 4000 --python tools/bench/lineart_intersections.py -- MODEL [ROUNDS] [--no-copy]
#
# `-t 1` gives Line Art one thread, as linework-bench's figure is per core; debug value 4000
# makes Line Art print its own stage timers ("Line art intersection time", "Line art total
# time") and "isec generated N lines". Each round evaluates the modifier with intersection
# lines off, then on; the difference of the two "intersection time"s is what intersections
# cost Line Art (the stage also bins the triangles into screen tiles, which occlusion needs
# either way). The camera looks at the model's centre from four times the model's size, so
# that every triangle of the pair is in the frame (Line Art leaves out what the camera does
# not see).
import math
import sys
import time

import bpy
import numpy
from mathutils import Matrix, Vector

numpy.bool = bool  # Debian 12's numpy 1.24 dropped the alias that Blender 3.4's glTF importer uses

args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
if not args:
    sys.exit("usage: blender -b -t 1 --debug-value 4000 --python lineart_intersections.py -- MODEL [ROUNDS] [--no-copy]")
model = args[0]
rounds = int(args[1]) if len(args) > 1 and args[1].isdigit() else 3
crossed_copy = "--no-copy" not in args

bpy.ops.wm.read_factory_settings(use_empty=True)
if model.lower().endswith(".obj"):
    bpy.ops.wm.obj_import(filepath=model)
else:
    bpy.ops.import_scene.gltf(filepath=model)
meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
if not meshes:
    sys.exit(f"{model}: no mesh imported")
for o in bpy.context.scene.objects:
    o.select_set(o.type == "MESH")
bpy.context.view_layer.objects.active = meshes[0]
if len(meshes) > 1:
    bpy.ops.object.join()  # one object, as linework-bench flattens the model into one mesh
a = bpy.context.view_layer.objects.active
# World-space vertices: an importer may parent the meshes to empties (glTF nodes).
bpy.ops.object.parent_clear(type="CLEAR_KEEP_TRANSFORM")
bpy.ops.object.transform_apply(location=True, rotation=True, scale=True)
bpy.context.view_layer.update()
corners = [Vector(c) for c in a.bound_box]
lo = Vector([min(c[i] for c in corners) for i in range(3)])
hi = Vector([max(c[i] for c in corners) for i in range(3)])
center, size = (lo + hi) / 2, (hi - lo).length
if crossed_copy:
    b = a.copy()
    b.data = a.data.copy()
    bpy.context.collection.objects.link(b)
    # Blender's vertical is z (its importers turn glTF's and OBJ's y-up into z-up).
    turn = Matrix.Rotation(math.radians(30.0), 4, "Z")
    b.matrix_world = Matrix.Translation(center + Vector((size / 3.0, 0.0, 0.0))) @ turn @ Matrix.Translation(-center)

camera_data = bpy.data.cameras.new("camera")
camera_data.clip_start, camera_data.clip_end = size * 1e-3, size * 100.0
camera = bpy.data.objects.new("camera", camera_data)
bpy.context.collection.objects.link(camera)
camera.location = center + Vector((0.0, -4.0 * size, 0.3 * size))
camera.rotation_euler = (center - camera.location).to_track_quat("-Z", "Y").to_euler()
scene = bpy.context.scene
scene.camera = camera
scene.render.resolution_x, scene.render.resolution_y = 1920, 1080

pencil = bpy.data.grease_pencils.new("lines")
pencil_object = bpy.data.objects.new("lines", pencil)
bpy.context.collection.objects.link(pencil_object)
pencil.layers.new("lines").frames.new(1)
ink = bpy.data.materials.new("ink")
bpy.data.materials.create_gpencil_data(ink)
pencil.materials.append(ink)
lineart = pencil_object.grease_pencil_modifiers.new("lineart", "GP_LINEART")
lineart.source_type = "SCENE"
lineart.target_layer, lineart.target_material = "lines", ink
lineart.use_contour = True
lineart.use_crease = lineart.use_material = lineart.use_edge_mark = lineart.use_loose = False

a.data.calc_loop_triangles()
print(f"triangles per object: {len(a.data.loop_triangles)}; objects: {2 if crossed_copy else 1}", flush=True)
for r in range(rounds):
    for intersections in (False, True):
        lineart.use_intersection = intersections
        start = time.perf_counter()
        pencil_object.update_tag()
        bpy.context.view_layer.update()  # evaluates the modifier: Line Art runs whole
        print(f"round {r} intersections {'on' if intersections else 'off'}: "
              f"{(time.perf_counter() - start) * 1e3:.1f} ms evaluation", flush=True)
