"""Headless test of the Blender add-on, run by CTest:

  blender -b --factory-startup --python-exit-code 1 --python test_addon.py -- \
      --addon ZIP_OR_FOLDER --source SOURCE_DIR

Installs the add-on (a zip through Blender's add-on installer, or a folder
linked into BLENDER_USER_SCRIPTS/addons), voxel-remeshes exact shapes inside
Blender, runs "Sharpen Chamfered Edges" as the UI does (with an undo step) in
Object and Edit mode, checks that the distance to the exact shape drops and
that undo restores the remeshed input, and that a bad mesh is refused with a
report. Any failed check raises: Blender exits with code 1.
"""
import argparse
import math
import os
import pathlib
import sys

import bpy
import numpy as np

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
parser = argparse.ArgumentParser()
parser.add_argument("--addon", required=True)
parser.add_argument("--source", required=True)
args = parser.parse_args(argv)
sys.path.insert(0, str(pathlib.Path(args.source) / "python" / "tests"))
from ply import read_ply  # noqa: E402
from spots import spot_faces  # noqa: E402

addon_path = pathlib.Path(args.addon)
if addon_path.suffix == ".zip":
    bpy.ops.preferences.addon_install(filepath=str(addon_path))
else:
    addons = pathlib.Path(bpy.utils.user_resource("SCRIPTS", path="addons", create=True))
    link = addons / "edge_sharpener_addon"
    if not link.exists():
        link.symlink_to(addon_path.resolve(), target_is_directory=True)
    bpy.utils.refresh_script_paths()  # the addons folder may be new: put it on sys.path
bpy.ops.preferences.addon_enable(module="edge_sharpener_addon")
import edge_sharpener_addon as addon  # noqa: E402

es = addon.es
assert es is not None, "the add-on could not import edge_sharpener"
print(f"edge_sharpener from {es.__file__}")

# The operator, its menus and its redo panel (the table's ordinary options, and
# each method's tuning under "Advanced", collapsed).
assert hasattr(bpy.types, "MESH_OT_sharpen_chamfered_edges")
for menu in ("VIEW3D_MT_edit_mesh_clean", "VIEW3D_MT_object_cleanup"):
    assert addon._menu_entry in getattr(bpy.types, menu).draw._draw_funcs, menu
rna = bpy.ops.mesh.sharpen_chamfered_edges.get_rna_type().properties
panel = {p.identifier for p in rna if p.identifier != "rna_type"}
ordinary = {o["key"] for o in es.ordinary_options()}
tuning = {o["key"] for o in es.tuning_options()}
assert ordinary and tuning and not ordinary & tuning
assert panel == ordinary | tuning | {"mark_sharp", "selected_only", "show_advanced"}, panel
assert not rna["show_advanced"].default
for option in es.OPTIONS:  # labels and tooltips are the table's
    assert rna[option["key"]].name == option["label"], option["key"]
    assert rna[option["key"]].description.startswith(option["help"]), option["key"]
    if option["type"] in ("real", "integer", "flag"):
        assert addon._value(option, rna[option["key"]].default) == option["default"], option["key"]


class FakeLayout:
    """What the redo panel's draw() puts in a layout: properties, labels, boxes."""
    def __init__(self):
        self.items = []

    def prop(self, data, name, **_):
        self.items.append(("prop", name))

    def label(self, text):
        self.items.append(("label", text))

    def box(self):
        box = FakeLayout()
        self.items.append(("box", box))
        return box


def drawn(show_advanced):
    panel = type("Panel", (), {"layout": FakeLayout(), "show_advanced": show_advanced})()
    addon.MESH_OT_sharpen_chamfered_edges.draw(panel, bpy.context)
    return panel.layout.items


# Collapsed: the ordinary options, Mark Sharp and the Advanced toggle; open: a box
# per tuning group, titled after it, holding its options in table order.
closed = drawn(False)
assert closed == [("prop", o["key"]) for o in es.ordinary_options()] + \
    [("prop", "mark_sharp"), ("prop", "show_advanced")], closed
opened = drawn(True)
assert opened[:len(closed)] == closed
boxes = [item[1].items for item in opened[len(closed):]]
groups = list(dict.fromkeys(o["group"] for o in es.tuning_options()))
assert len(boxes) == len(groups) == 6, boxes
for box, group in zip(boxes, groups):
    assert box[0] == ("label", group.removeprefix("Tuning: ").capitalize()), box[0]
    assert box[1:] == [("prop", o["key"]) for o in es.tuning_options() if o["group"] == group]


def new_object(name, vertices, faces):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(np.asarray(vertices).tolist(), [], np.asarray(faces).tolist())
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    for other in bpy.context.scene.objects:
        other.select_set(other == obj)
    bpy.context.view_layer.objects.active = obj
    return obj


def distance(obj, exact):
    vertices, faces = addon.mesh_arrays(obj.data)
    return es.mesh_distance(vertices, faces, *exact, samples=100000)["symmetric"]


def sharpen(**options):
    # ('EXEC_DEFAULT', True): run with an undo step, as from the menu.
    return bpy.ops.mesh.sharpen_chamfered_edges("EXEC_DEFAULT", True, **options)


def check_shape(name, exact, voxel_size):
    obj = new_object(name, *exact)
    obj.data.remesh_voxel_size = voxel_size
    assert bpy.ops.object.voxel_remesh() == {"FINISHED"}
    remeshed = [a.copy() for a in addon.mesh_arrays(obj.data)]
    before = distance(obj, exact)
    bpy.ops.ed.undo_push(message="remeshed")

    for mode in ("OBJECT", "EDIT"):
        obj = bpy.data.objects[name]  # undo replaces the data blocks
        bpy.context.view_layer.objects.active = obj
        bpy.ops.object.mode_set(mode=mode)
        if mode == "EDIT":  # Edit Mode acts on the selected faces: all of them here
            bpy.ops.mesh.select_all(action="SELECT")
        assert sharpen(method="extended") == {"FINISHED"}
        bpy.ops.object.mode_set(mode="OBJECT")
        obj = bpy.data.objects[name]
        after = distance(obj, exact)
        print(f"{name} ({len(remeshed[1])} triangles, voxel {voxel_size}), {mode} mode: "
              f"max {before['max_percent']:.4f}% -> {after['max_percent']:.4f}%, "
              f"RMS {before['rms_percent']:.5f}% -> {after['rms_percent']:.5f}% of the diagonal")
        assert after["rms"] < before["rms"] / 3, (before, after)
        assert after["max"] < before["max"], (before, after)
        # Undo (in the mode the operator ran in) restores the remeshed input.
        bpy.ops.object.mode_set(mode=mode)
        assert bpy.ops.ed.undo() == {"FINISHED"}
        bpy.ops.object.mode_set(mode="OBJECT")
        restored = addon.mesh_arrays(bpy.data.objects[name].data)
        assert np.array_equal(restored[0], remeshed[0]) and np.array_equal(restored[1], remeshed[1]), \
            f"undo did not restore {name} ({mode} mode)"
    bpy.data.objects.remove(bpy.data.objects[name])


for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj)

# A cube turned off the voxel grid's axes (aligned, the remesher is exact).
corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)
quads = np.array([[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]])
a, b = 0.5, 0.3
turn = np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]]) @ \
    np.array([[1, 0, 0], [0, math.cos(b), -math.sin(b)], [0, math.sin(b), math.cos(b)]])
cube_vertices = corners @ turn.T
cube_triangles = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
check_shape("cube", (cube_vertices, cube_triangles), 0.1)

lblock = read_ply(pathlib.Path(args.source) / "test_meshes" / "generated" / "lblock_reference.ply")
check_shape("lblock", (lblock["vertices"].astype(float) @ turn.T, lblock["faces"]), 0.04)

# Refusal: a tetrahedron with one face flipped. The operator reports why and leaves the mesh alone.
tet = new_object("flipped", [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
                 [[0, 1, 2], [0, 1, 3], [1, 2, 3], [0, 3, 2]])
bpy.ops.ed.undo_push(message="flipped")
try:
    sharpen()
except RuntimeError as error:  # bpy.ops raises the operator's ERROR report
    message = str(error)
else:
    raise AssertionError("an inconsistently oriented mesh was not refused")
print(f"refusal report: {message.strip()}")
assert "Edge-Sharpener refused the mesh" in message and "oriented" in message, message
assert len(bpy.data.objects["flipped"].data.polygons) == 4

# Non-manifold spots: the L-block with a non-manifold vertex and edge is sharpened, the
# faces at the spots as they came (the same vertex indices, the same positions).
spotted = read_ply(pathlib.Path(args.source) / "test_meshes" / "generated" / "lblock_mc2_spots.ply")
new_object("spots", spotted["vertices"], spotted["faces"])
bpy.ops.ed.undo_push(message="spots")
assert sharpen() == {"FINISHED"}
spots_mesh = bpy.data.objects["spots"].data
spots_v = np.array([v.co[:] for v in spots_mesh.vertices], dtype=np.float32)
spots_f = np.array([p.vertices[:] for p in spots_mesh.polygons])
held = spot_faces(spotted["vertices"], spotted["faces"])
assert held and spot_faces(spots_v, spots_f) == held, "a face at a non-manifold spot changed"
assert (spots_v[:len(spotted["vertices"])] == spotted["vertices"]).all()
assert len(spots_f) > len(spotted["faces"]), "nothing was sharpened"
print(f"non-manifold spots: {len(held)} faces as they came, {len(spotted['faces'])} -> {len(spots_f)} faces")

# A point colour attribute (the voxel remesher keeps one with Preserve Color
# Attributes) survives: the original vertices keep their colours, each new
# vertex gets the mean of the vertices it was made between (blue is 7/255
# everywhere, so on every new vertex too: never white).
obj = new_object("painted", cube_vertices, cube_triangles)
obj.data.remesh_voxel_size = 0.1
obj.data.use_remesh_preserve_vertex_colors = True
bpy.ops.object.voxel_remesh()
mesh = bpy.data.objects["painted"].data
if "paint" not in mesh.color_attributes:
    mesh.color_attributes.new("paint", "BYTE_COLOR", "POINT")
mesh.color_attributes.active_color = mesh.color_attributes["paint"]
co = np.empty(3 * len(mesh.vertices), dtype=np.float32)
mesh.vertices.foreach_get("co", co)
x = co.reshape(-1, 3)[:, 0]
paint = np.stack([np.round(250 * (x - x.min()) / np.ptp(x)) / 255, np.full_like(x, 100 / 255),
                  np.full_like(x, 7 / 255), np.ones_like(x)], axis=1).astype(np.float32)
mesh.color_attributes["paint"].data.foreach_set("color_srgb", paint.ravel())
n = len(mesh.vertices)
assert sharpen() == {"FINISHED"}
mesh = bpy.data.objects["painted"].data
assert len(mesh.vertices) > n, "nothing was sharpened"
attribute = mesh.color_attributes["paint"]
assert attribute.domain == "POINT" and attribute.data_type == "BYTE_COLOR"
after = np.empty(4 * len(mesh.vertices), dtype=np.float32)
attribute.data.foreach_get("color_srgb", after)
after = np.round(after.reshape(-1, 4) * 255).astype(int)
assert np.array_equal(after[:n], np.round(paint * 255).astype(int)), "original vertices recoloured"
assert (after[n:, 1] == 100).all() and (after[n:, 2] == 7).all(), "a new vertex is not blended"
assert after[n:, 0].min() < 60 and after[n:, 0].max() > 190, "the gradient did not come through"
print(f"point colours: {n} -> {len(mesh.vertices)} vertices, all coloured")

# A tuning option set in the Advanced panel reaches the core: with every feature
# shorter than the minimum size, each is left as it was, and so is the mesh. It
# holds for that run only (SKIP_SAVE): the next run has the default again, while
# an ordinary option (method) is remembered, as Blender does.
obj = new_object("tuned", cube_vertices, cube_triangles)
obj.data.remesh_voxel_size = 0.1
bpy.ops.object.voxel_remesh()
remeshed = addon.mesh_arrays(bpy.data.objects["tuned"].data)
assert sharpen(method="auto", min_feature_vertices=1000) == {"FINISHED"}
tuned = addon.mesh_arrays(bpy.data.objects["tuned"].data)
assert np.array_equal(tuned[0], remeshed[0]) and len(tuned[1]) == len(remeshed[1]), "a feature was sharpened"
assert sharpen() == {"FINISHED"}
assert len(addon.mesh_arrays(bpy.data.objects["tuned"].data)[1]) > len(remeshed[1]), "nothing sharpened"
print("tuning: min_feature_vertices=1000 left the remeshed cube as it was; the next run sharpened it")
# Only the tuning that differs from the table's default goes to the package.
class Probe:
    pass
probe = Probe()
for option in es.OPTIONS:
    setattr(probe, option["key"], option["default"])
assert "tuning" not in addon._options(probe)
probe.max_label_hops, probe.max_bend_fraction = 7, np.float32(0.3)
assert addon._options(probe)["tuning"] == {"max_label_hops": 7, "max_bend_fraction": 0.3}

# colorize paints the labels into a colour attribute.
obj = new_object("cube2", cube_vertices, cube_triangles)
obj.data.remesh_voxel_size = 0.1
bpy.ops.object.voxel_remesh()
assert sharpen(colorize=True) == {"FINISHED"}
assert "Edge-Sharpener labels" in bpy.data.objects["cube2"].data.color_attributes

# The restored edges are marked sharp (Mark Sharp, on by default), and a
# smooth-shaded mesh gets Auto Smooth at 180 degrees: they are the turned
# cube's twelve edges (side 2), and only they.
def cube_edge_distance(points):
    """Each point's distance to the nearest of the turned cube's 12 edges."""
    best = np.full(len(points), np.inf)
    for i in range(8):
        for j in range(i + 1, 8):
            if np.count_nonzero(corners[i] != corners[j]) != 1:
                continue
            p, q = cube_vertices[i], cube_vertices[j]
            t = np.clip((points - p) @ (q - p) / ((q - p) @ (q - p)), 0, 1)
            best = np.minimum(best, np.linalg.norm(points - (p + t[:, None] * (q - p)), axis=1))
    return best


for mark in (True, False):
    obj = new_object("smooth", cube_vertices, cube_triangles)
    obj.data.remesh_voxel_size = 0.1
    bpy.ops.object.voxel_remesh()
    bpy.ops.object.shade_smooth()
    assert sharpen(mark_sharp=mark) == {"FINISHED"}
    mesh = bpy.data.objects["smooth"].data
    flags = np.zeros(len(mesh.edges), dtype=bool)
    mesh.edges.foreach_get("use_edge_sharp", flags)
    ends = np.empty(2 * len(mesh.edges), dtype=np.int64)
    mesh.edges.foreach_get("vertices", ends)
    co = np.empty(3 * len(mesh.vertices), dtype=np.float32)
    mesh.vertices.foreach_get("co", co)
    co, ends = co.reshape(-1, 3).astype(float), ends.reshape(-1, 2)[flags]
    if not mark:
        assert not flags.any() and not mesh.use_auto_smooth
        break
    length = np.linalg.norm(co[ends[:, 0]] - co[ends[:, 1]], axis=1).sum()
    off = cube_edge_distance(co[ends.ravel()]).max()
    print(f"marked sharp: {len(ends)} edges, {length:.3f} long (the cube's edges: 24), "
          f"at most {off:.4f} off them")
    assert 0.9 * 24 < length < 24.01 and off < 0.02, (length, off)
    assert mesh.use_auto_smooth and abs(mesh.auto_smooth_angle - math.pi) < 1e-6
    bpy.data.objects.remove(bpy.data.objects["smooth"])

# A user's edge marks (seams, creases here) stay on the edges sharpening keeps
# (between the same two original vertices), and only there.
mc = read_ply(pathlib.Path(args.source) / "test_meshes" / "generated" / "lblock_mc2.ply")
obj = new_object("marked_lblock", mc["vertices"], mc["faces"])
mesh = obj.data
before = np.sort(np.array([e.vertices[:] for e in mesh.edges]), axis=1)
mesh.edges.foreach_set("use_seam", np.ones(len(mesh.edges), bool))
if "crease" in bpy.types.MeshEdge.bl_rna.properties:
    mesh.edges.foreach_set("crease", np.full(len(mesh.edges), 0.5, np.float32))
n = len(mesh.vertices)
assert sharpen(mark_sharp=False) == {"FINISHED"}
mesh = bpy.data.objects["marked_lblock"].data
after = np.sort(np.array([e.vertices[:] for e in mesh.edges]), axis=1)
key = len(mesh.vertices) + 1  # above every vertex index, before and after
kept = np.isin(after[:, 0] * key + after[:, 1], before[:, 0] * key + before[:, 1])
seams = np.zeros(len(mesh.edges), bool)
mesh.edges.foreach_get("use_seam", seams)
assert len(mesh.vertices) > n and 0.5 * len(before) < kept.sum() < len(before), kept.sum()
assert np.array_equal(seams, kept), "a seam was lost or added"
if "crease" in bpy.types.MeshEdge.bl_rna.properties:
    crease = np.zeros(len(mesh.edges), np.float32)
    mesh.edges.foreach_get("crease", crease)
    assert np.allclose(crease[kept], 0.5) and not crease[~kept].any(), "a crease was lost or added"
print(f"edge marks: {kept.sum()} of {len(before)} input edges kept with their seams and creases")


# Edit Mode acts on the selected faces (issue 61): the bevelled block with every face but
# its wide designed bevel's selected. The bevel's vertices come out as they came, and the
# mesh is what the package gives with that face_mask; Object Mode sharpens the whole mesh.
generated = pathlib.Path(args.source) / "test_meshes" / "generated"
block = read_ply(generated / "bevelled_block_mc2.ply")
on_bevel = np.zeros(len(block["faces"]), dtype=bool)
on_bevel[np.loadtxt(generated / "bevelled_block_mc2_bevel.txt", dtype=np.int64)] = True
obj = new_object("bevelled", block["vertices"], block["faces"])
bpy.context.tool_settings.mesh_select_mode = (False, False, True)
obj.data.vertices.foreach_set("select", np.zeros(len(obj.data.vertices), dtype=bool))
obj.data.edges.foreach_set("select", np.zeros(len(obj.data.edges), dtype=bool))
obj.data.polygons.foreach_set("select", ~on_bevel)
bpy.ops.ed.undo_push(message="bevelled")
bpy.ops.object.mode_set(mode="EDIT")
assert sharpen() == {"FINISHED"}
bpy.ops.object.mode_set(mode="OBJECT")
got_v, got_f = addon.mesh_arrays(bpy.data.objects["bevelled"].data)
want_v, want_f, want = es.sharpen(block["vertices"], block["faces"], face_mask=~on_bevel)
assert want["evidence"]["verdicts"]["outside_selection"] >= 1
assert np.array_equal(got_v, want_v) and np.array_equal(got_f, want_f), "Edit Mode != face_mask"
bevel_vertices = np.unique(block["faces"][on_bevel])
assert (got_v[bevel_vertices] == block["vertices"][bevel_vertices]).all(), "the bevel moved"
assert len(got_f) > len(block["faces"]), "nothing was sharpened"
whole_v, whole_f, _ = es.sharpen(block["vertices"], block["faces"])
obj = new_object("bevelled_whole", block["vertices"], block["faces"])
assert sharpen() == {"FINISHED"}  # Object Mode: the whole mesh, whatever is selected
got_v, got_f = addon.mesh_arrays(bpy.data.objects["bevelled_whole"].data)
assert np.array_equal(got_v, whole_v) and np.array_equal(got_f, whole_f), "Object Mode != whole"
print(f"Edit Mode selection: {len(bevel_vertices)} bevel vertices as they came, "
      f"{len(block['faces'])} -> {len(want_f)} triangles; {want['input_notes']}")

print("blender add-on test: all checks passed")
