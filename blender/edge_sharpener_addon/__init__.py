"""Blender add-on: Mesh > Clean Up > Sharpen Chamfered Edges.

Restores the sharp edges and corners that the voxel remesher (or marching
cubes, or a uniform resampling) cut into chamfers, with the edge_sharpener
Python package. The operator's redo panel shows the package's ordinary
options, built from its option table (edge_sharpener.ordinary_options()), and
under a collapsed "Advanced" each method's tuning (tuning_options()), by group.
"""

bl_info = {
    "name": "Edge-Sharpener",
    "author": "Edge-Sharpener contributors",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Mesh > Clean Up (Edit Mode), Object > Clean Up (Object Mode)",
    "description": "Restores sharp edges and corners cut into chamfers by voxel remeshing",
    "category": "Mesh",
}

import math

import bpy
import numpy as np

# The zip built by CMake bundles the package inside the add-on; otherwise the
# package installed for Blender's Python (pip, cmake --install, PYTHONPATH).
try:
    from . import edge_sharpener as es
except ImportError:
    try:
        import edge_sharpener as es
    except ImportError as error:
        es = None
        _import_error = str(error)


def _property(option):
    """A Blender property for one row of the option table (its label, its help
    as the tooltip, with the unit). Blender remembers an operator's last values
    for its next run: the ordinary options' only; a tuning value, out of sight
    under Advanced, holds for the run it was set in (its redo panel)."""
    unit = f" [{option['unit']}]" if option["unit"] and option["type"] != "choice" else ""
    common = {"name": option["label"], "description": option["help"] + unit}
    if not option["ordinary"]:
        common["options"] = {"SKIP_SAVE"}
    kind = option["type"]
    if kind == "choice":
        items = [(c, c.capitalize(), "") for c in option["choices"]]
        return bpy.props.EnumProperty(items=items, default=option["default"], **common)
    if kind == "flag":
        return bpy.props.BoolProperty(default=option["default"], **common)
    low = option["min"]
    if option["min_exclusive"]:
        low += 1e-3  # the range excludes its minimum
    if kind == "integer":
        return bpy.props.IntProperty(default=option["default"], min=int(low), max=int(option["max"]), **common)
    # Enough decimals to show the default (0.001, 0.018).
    decimals = len(repr(float(option["default"])).partition(".")[2].rstrip("0"))
    return bpy.props.FloatProperty(default=option["default"], min=low, max=option["max"],
                                   precision=min(6, max(2, decimals)), **common)


def _ordinary_options():
    return es.ordinary_options() if es is not None else ()


def _tuning_options():
    return es.tuning_options() if es is not None else ()


def _value(option, value):
    """A property's value as the package takes it: a float property holds a
    float32, given as the decimal it reads as (0.3, not 0.30000001192)."""
    if option["type"] == "real":
        return float(str(np.float32(value)))
    return value


def _options(operator):
    """sharpen()'s keywords from the operator's properties: the ordinary
    options, and the tuning that differs from its default in the tuning dict."""
    options = {o["key"]: _value(o, getattr(operator, o["key"])) for o in _ordinary_options()}
    tuning = {}
    for option in _tuning_options():
        value = _value(option, getattr(operator, option["key"]))
        if value != option["default"]:
            tuning[option["key"]] = value
    if tuning:
        options["tuning"] = tuning
    return options


def mesh_arrays(mesh):
    """The mesh's vertices (float32) and triangles (its polygons triangulated)."""
    mesh.calc_loop_triangles()
    vertices = np.empty(3 * len(mesh.vertices), dtype=np.float32)
    mesh.vertices.foreach_get("co", vertices)
    triangles = np.empty(3 * len(mesh.loop_triangles), dtype=np.int32)
    mesh.loop_triangles.foreach_get("vertices", triangles)
    return vertices.reshape(-1, 3), triangles.reshape(-1, 3)


def selected_triangles(mesh):
    """Per triangle of mesh_arrays(mesh), whether its polygon is selected (the
    selection Edit Mode last wrote to the mesh)."""
    polygon = np.empty(len(mesh.loop_triangles), dtype=np.int32)
    mesh.loop_triangles.foreach_get("polygon_index", polygon)
    selected = np.empty(len(mesh.polygons), dtype=bool)
    mesh.polygons.foreach_get("select", selected)
    return selected[polygon]


def point_colors(mesh):
    """The mesh's colour attribute on points (the active one, else the first),
    as (name, data type, RGBA floats as stored: sRGB for bytes), or None. The
    voxel remesher keeps such an attribute with Preserve Color Attributes."""
    attributes = [a for a in mesh.color_attributes if a.domain == "POINT"]
    if not attributes:
        return None
    active = mesh.color_attributes.active_color
    attribute = active if active is not None and active.domain == "POINT" else attributes[0]
    values = np.empty(4 * len(mesh.vertices), dtype=np.float32)
    key = "color_srgb" if attribute.data_type == "BYTE_COLOR" else "color"
    attribute.data.foreach_get(key, values)
    return attribute.name, attribute.data_type, values.reshape(-1, 4)


def set_point_colors(mesh, name, data_type, values):
    """Writes RGBA floats (sRGB for bytes) into a new point colour attribute."""
    attribute = mesh.color_attributes.new(name, data_type, "POINT")
    key = "color_srgb" if data_type == "BYTE_COLOR" else "color"
    attribute.data.foreach_set(key, np.ascontiguousarray(values, dtype=np.float32).ravel())
    mesh.color_attributes.active_color = attribute


def sharpened_colors(colors, report):
    """The output's point colours: the input's values on the original vertices
    (they keep their index), each new vertex with the mean of the vertices it
    was made between, as the package blends them (8 bits a channel)."""
    blended = report["vertex_colors"].astype(np.float32) / 255.0
    blended[: len(colors)] = colors
    return blended


def replace_geometry(mesh, vertices, faces, face_colors=None):
    """Replaces the mesh's geometry with this triangle mesh (UV maps and other
    attributes do not survive: the triangles are new; the caller writes a point
    colour attribute and the edge marks back). Keeps smooth or flat shading as the
    majority of the old faces had it."""
    smooth = np.zeros(len(mesh.polygons), dtype=bool)
    mesh.polygons.foreach_get("use_smooth", smooth)
    use_smooth = bool(smooth.mean() > 0.5) if len(smooth) else False
    mesh.clear_geometry()
    mesh.vertices.add(len(vertices))
    mesh.vertices.foreach_set("co", np.ascontiguousarray(vertices, dtype=np.float32).ravel())
    mesh.loops.add(3 * len(faces))
    mesh.loops.foreach_set("vertex_index", np.ascontiguousarray(faces, dtype=np.int32).ravel())
    mesh.polygons.add(len(faces))
    mesh.polygons.foreach_set("loop_start", np.arange(0, 3 * len(faces), 3, dtype=np.int32))
    mesh.polygons.foreach_set("loop_total", np.full(len(faces), 3, dtype=np.int32))
    mesh.polygons.foreach_set("use_smooth", np.full(len(faces), use_smooth))
    mesh.update(calc_edges=True)
    if face_colors is not None:
        # Face colours on the face corners (Blender's colour attributes hold
        # points or corners).
        layer = mesh.color_attributes.new("Edge-Sharpener labels", "BYTE_COLOR", "CORNER")
        corner_colors = np.repeat(face_colors.astype(np.float32) / 255.0, 3, axis=0)
        layer.data.foreach_set("color", corner_colors.ravel())


# Per-edge marks a user sets (sharp, seam, crease): an edge property on Blender
# 3.x, a named edge attribute on Blender 4 where the property went away.
_EDGE_MARKS = (("use_edge_sharp", "sharp_edge", bool), ("use_seam", None, bool),
               ("crease", "crease_edge", np.float32))


def _edge_ends(mesh):
    """Each edge's two vertex indices, lower first, as an (edges, 2) int64 array."""
    ends = np.empty(2 * len(mesh.edges), dtype=np.int64)
    mesh.edges.foreach_get("vertices", ends)
    return np.sort(ends.reshape(-1, 2), axis=1)


def _pair_keys(pairs, mesh):
    """One int64 per vertex pair (lower index first) of the mesh as it is now."""
    return pairs[:, 0] * (len(mesh.vertices) + 1) + pairs[:, 1]


def _edge_values(mesh, prop, attribute, dtype, values=None):
    """Reads (values None) or writes one mark on every edge; None where the mesh has no
    such mark."""
    if prop in bpy.types.MeshEdge.bl_rna.properties:
        target, key = mesh.edges, prop
    elif attribute is not None and (attribute in mesh.attributes or values is not None):
        layer = mesh.attributes.get(attribute)
        if layer is None:
            layer = mesh.attributes.new(attribute, "BOOLEAN" if dtype is bool else "FLOAT", "EDGE")
        target, key = layer.data, "value"
    else:
        return None
    if values is None:
        values = np.zeros(len(mesh.edges), dtype=dtype)
        target.foreach_get(key, values)
        return values
    target.foreach_set(key, values)
    return values


def edge_marks(mesh):
    """The marked edges (sharp, seam, crease) as (vertex pairs, {mark: values}), for
    keep_edge_marks: the original vertices keep their index through sharpening."""
    ends = _edge_ends(mesh)
    marks = {}
    for prop, attribute, dtype in _EDGE_MARKS:
        values = _edge_values(mesh, prop, attribute, dtype)
        if values is not None and values.any():
            marks[(prop, attribute, dtype)] = values
    return ends, marks


def keep_edge_marks(mesh, kept):
    """Writes the marks `kept` (edge_marks of the input) back on the edges that are
    still there, between the same two vertices; an edge sharpening split is gone."""
    ends, marks = kept
    if not marks:
        return
    keys, old_keys = _pair_keys(_edge_ends(mesh), mesh), _pair_keys(ends, mesh)
    order = np.argsort(old_keys)
    where = np.searchsorted(old_keys[order], keys)
    found = where < len(old_keys)
    found[found] = old_keys[order][where[found]] == keys[found]
    for (prop, attribute, dtype), old in marks.items():
        values = np.zeros(len(keys), dtype=dtype)
        values[found] = old[order][where[found]]
        _edge_values(mesh, prop, attribute, dtype, values)


def mark_sharp_edges(mesh, pairs):
    """Marks the mesh's edges joining each vertex pair of `pairs` (the report's
    sharp_edges: the restored feature lines) sharp, so that smooth shading
    keeps them crisp. On Blender 3.x, where that takes Auto Smooth, a smooth
    mesh without it gets it at 180 degrees (only the marked edges split).
    Returns the number of edges marked."""
    if len(pairs) == 0 or len(mesh.edges) == 0:
        return 0
    sharp = np.isin(_pair_keys(_edge_ends(mesh), mesh), _pair_keys(pairs, mesh))
    marked = _edge_values(mesh, "use_edge_sharp", "sharp_edge", bool)
    _edge_values(mesh, "use_edge_sharp", "sharp_edge", bool, sharp if marked is None else marked | sharp)
    if hasattr(mesh, "use_auto_smooth") and not mesh.use_auto_smooth and len(mesh.polygons) and \
            mesh.polygons[0].use_smooth:
        mesh.use_auto_smooth = True
        mesh.auto_smooth_angle = math.pi
    return int(sharp.sum())


class MESH_OT_sharpen_chamfered_edges(bpy.types.Operator):
    """Restore the sharp edges and corners that voxel remeshing cut into chamfers"""

    bl_idname = "mesh.sharpen_chamfered_edges"
    bl_label = "Sharpen Chamfered Edges"
    bl_options = {"REGISTER", "UNDO"}

    # One property per option of the table (set before registering): the
    # ordinary ones in the panel, each method's tuning under "Advanced".
    __annotations__ = {option["key"]: _property(option)
                       for option in _ordinary_options() + _tuning_options()}
    __annotations__["show_advanced"] = bpy.props.BoolProperty(
        name="Advanced", default=False, description="Show each method's tuning options")
    # The add-on's own: what it does with the restored edges (mark_sharp_edges).
    __annotations__["mark_sharp"] = bpy.props.BoolProperty(
        name="Mark Sharp", default=True,
        description="Mark the restored edges sharp, so that smooth shading keeps them crisp "
                    "(Blender 3.x: turns on Auto Smooth at 180 degrees on a smooth mesh without it)")
    __annotations__["selected_only"] = bpy.props.BoolProperty(
        name="Selected Only", default=True,
        description="In Edit Mode, sharpen only within the selected faces, as Blender's own "
                    "operators act: a feature outside them is left as it came, one they cut is "
                    "sharpened up to them (deselect a designed bevel). Object Mode sharpens the "
                    "whole mesh")

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        layout.use_property_decorate = False
        for option in _ordinary_options():
            layout.prop(self, option["key"])
        layout.prop(self, "mark_sharp")
        if context.mode == "EDIT_MESH":
            layout.prop(self, "selected_only")
        layout.use_property_split = False
        layout.prop(self, "show_advanced", emboss=False,
                    icon="TRIA_DOWN" if self.show_advanced else "TRIA_RIGHT")
        if not self.show_advanced:
            return
        box, group = None, None
        for option in _tuning_options():
            if option["group"] != group:
                group = option["group"]
                box = layout.box()
                box.use_property_split = True
                box.use_property_decorate = False
                box.label(text=group.removeprefix("Tuning: ").capitalize())
            box.prop(self, option["key"])

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == "MESH" and context.mode in {"OBJECT", "EDIT_MESH"}

    def execute(self, context):
        if es is None:
            self.report({"ERROR"}, "Edge-Sharpener: the edge_sharpener package is missing (" + _import_error + ")")
            return {"CANCELLED"}
        obj = context.active_object
        in_edit_mode = obj.mode == "EDIT"
        if in_edit_mode:
            bpy.ops.object.mode_set(mode="OBJECT")  # writes the edit mesh to obj.data
        try:
            vertices, faces = mesh_arrays(obj.data)
            options = _options(self)
            if in_edit_mode and self.selected_only:
                options["face_mask"] = selected_triangles(obj.data)
            kept = point_colors(obj.data)
            marks = edge_marks(obj.data)
            if kept is not None:
                options["vertex_colors"] = np.round(np.clip(kept[2], 0, 1) * 255).astype(np.uint8)
            try:
                new_vertices, new_faces, report = es.sharpen(vertices, faces, **options)
            except es.InputError as error:
                self.report({"ERROR"}, f"Edge-Sharpener refused the mesh: {error}")
                return {"CANCELLED"}
            colors = report.get("colors", {}).get("faces")
            replace_geometry(obj.data, new_vertices, new_faces, colors)
            keep_edge_marks(obj.data, marks)
            if kept is not None and not self.colorize:
                set_point_colors(obj.data, kept[0], kept[1], sharpened_colors(kept[2], report))
            marked = mark_sharp_edges(obj.data, report["sharp_edges"]) if self.mark_sharp else 0
        finally:
            if in_edit_mode:
                bpy.ops.object.mode_set(mode="EDIT")
        notes = f"; {report['input_notes']}" if report.get("input_notes") else ""
        self.report({"INFO"}, f"Edge-Sharpener: {report['summary']}{notes}; {len(faces)} -> {len(new_faces)} triangles"
                              + (f", {marked} edges marked sharp" if marked else ""))
        return {"FINISHED"}


def _menu_entry(self, context):
    self.layout.operator(MESH_OT_sharpen_chamfered_edges.bl_idname)


_menus = ("VIEW3D_MT_edit_mesh_clean", "VIEW3D_MT_object_cleanup")


def register():
    bpy.utils.register_class(MESH_OT_sharpen_chamfered_edges)
    for menu in _menus:
        getattr(bpy.types, menu).append(_menu_entry)


def unregister():
    for menu in _menus:
        getattr(bpy.types, menu).remove(_menu_entry)
    bpy.utils.unregister_class(MESH_OT_sharpen_chamfered_edges)
