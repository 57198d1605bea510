"""Renders docs/images/blender-sharpen.png: an L-block voxel-remeshed in
Blender (left) and the same after "Sharpen Chamfered Edges" (right), Cycles on
the CPU, flat shading. Prints the distances to the exact shape.

  blender -b --factory-startup --python-use-system-env \
      --python blender/tools/render_figure.py -- SOURCE_DIR OUTPUT.png [--smooth]
(with the package on PYTHONPATH, e.g. PYTHONPATH=build/python)

With --smooth (docs/images/blender-sharpen-smooth.png), three smooth-shaded
copies: voxel-remeshed, sharpened with Mark Sharp off, sharpened as by default
(the restored edges marked sharp).
"""
import math
import pathlib
import sys

import bpy
import numpy as np

arguments = sys.argv[sys.argv.index("--") + 1:]
source, output = arguments[:2]
smooth = "--smooth" in arguments[2:]
sys.path.insert(0, str(pathlib.Path(source) / "blender"))
sys.path.insert(0, str(pathlib.Path(source) / "python" / "tests"))
import edge_sharpener_addon as addon  # noqa: E402
from ply import read_ply  # noqa: E402

addon.register()
es = addon.es
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj)

a, b = 0.5, 0.3
turn = np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]]) @ \
    np.array([[1, 0, 0], [0, math.cos(b), -math.sin(b)], [0, math.sin(b), math.cos(b)]])
lblock = read_ply(pathlib.Path(source) / "test_meshes" / "generated" / "lblock_reference.ply")
exact = (lblock["vertices"].astype(float) @ turn.T, lblock["faces"])


def remeshed(name, x):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(exact[0].tolist(), [], exact[1].tolist())
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    obj.data.remesh_voxel_size = 0.04
    bpy.ops.object.voxel_remesh()
    obj.location.x = x
    return obj


def distance(obj):
    return es.mesh_distance(*addon.mesh_arrays(obj.data), *exact, samples=200000)["symmetric"]


if smooth:
    shown = [remeshed("voxel_remesh", -2.6), remeshed("unmarked", 0), remeshed("marked", 2.6)]
    for obj in shown:
        obj.data.polygons.foreach_set("use_smooth", np.ones(len(obj.data.polygons), bool))
    for obj, mark in ((shown[1], False), (shown[2], True)):
        bpy.context.view_layer.objects.active = obj
        bpy.ops.mesh.sharpen_chamfered_edges(mark_sharp=mark)
else:
    shown = [remeshed("voxel_remesh", -1.3), remeshed("sharpened", 1.3)]
    bpy.context.view_layer.objects.active = shown[1]
    bpy.ops.mesh.sharpen_chamfered_edges()
for obj in shown:
    d = distance(obj)
    print(f"{obj.name}: max {d['max_percent']:.3f}%  RMS {d['rms_percent']:.4f}% of the diagonal")
    if not smooth:
        obj.data.polygons.foreach_set("use_smooth", np.zeros(len(obj.data.polygons), bool))
    material = bpy.data.materials.new(obj.name)
    material.diffuse_color = (0.8, 0.55, 0.3, 1)
    material.use_nodes = True
    material.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.8, 0.45, 0.2, 1)
    obj.data.materials.append(material)

scene = bpy.context.scene
camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
scene.collection.objects.link(camera)
camera.location = (0, -9.6, 4.8) if smooth else (0, -6.4, 3.2)
camera.rotation_euler = (math.radians(63), 0, 0)
camera.data.lens = 40
scene.camera = camera
sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", "SUN"))
sun.data.energy = 5
sun.rotation_euler = (math.radians(50), math.radians(-25), math.radians(-35))
scene.collection.objects.link(sun)
scene.world = bpy.data.worlds.new("world")
scene.world.color = (0.3, 0.3, 0.33)
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 24
scene.cycles.use_denoising = False
scene.render.resolution_x, scene.render.resolution_y = (1200, 420) if smooth else (900, 420)
scene.render.filepath = output
bpy.ops.render.render(write_still=True)
