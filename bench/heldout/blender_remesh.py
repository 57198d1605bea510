#!/usr/bin/python3
"""A second held-out check of the default method, on the remeshers Blender users run: Blender
3.4's voxel remesh (OpenVDB inside Blender: Mesh.remesh_voxel_size and object.voxel_remesh,
adaptivity 0, Preserve Volume on as Blender sets it) at 1% and 0.5% of the reference's
diagonal, and its Remesh modifier in Smooth mode (dual contouring on an octree, scale 0.9,
Remove Disconnected on) at a cell of about 1%. No threshold is chosen on it; it says whether a
rule chosen on the tuning half harms meshes made by another tool.

  /usr/bin/python3 bench/heldout/blender_remesh.py [--build BUILD] [--shared DIR]
      [--method auto] [--out FILE.md] [-- extra CLI options]

References as in open3d_poisson.py: the generated shapes the quality benchmark wrote
(BUILD/quality-cache/generated, after scripts/bench-quality.sh), test_meshes/real and
../shared/meshes. Open3D reads each reference (Blender 3.4 has no OFF importer, and its OBJ
importer turns the axes) and hands Blender its vertices and triangles as arrays, multiplied by
a power of two (exact in floating point) that puts the diagonal in [1, 2): Blender takes no
voxel size under 0.0001. Blender triangulates the remeshed faces (bmesh); they are divided by
the same power of two and reduced to their largest connected component. The Smooth mode's
octree spans the largest side / 0.9 in 2^depth cells; the depth is the one whose cell is
nearest 1% of the diagonal on a log scale (within a factor of sqrt 2). A sampler whose mesh
would have more than MAX_FACES faces (twice the area over the cell squared) is skipped for
that reference. Distances: mesh-distance --sampling meshlab, "worse" by the benchmark's rule
(bench/quality/families.py). Needs Debian's blender and python3-open3d; the meshes are
written to BUILD/heldout-blender.
"""
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import heldout  # noqa: E402

BLENDER = "/usr/bin/blender"
SCALE = 0.9  # the Remesh modifier's default
MAX_FACES = 1500000
# (key, mode, cell as a fraction of the diagonal, title; {cells}: the Smooth mode's cells)
SAMPLERS = (
    ("voxel1", "voxel", 0.01, "Blender 3.4 voxel remesh (OpenVDB), voxel 1% of the diagonal, "
                              "adaptivity 0, Preserve Volume"),
    ("voxel05", "voxel", 0.005, "Blender 3.4 voxel remesh (OpenVDB), voxel 0.5% of the "
                                "diagonal, adaptivity 0, Preserve Volume"),
    ("smooth1", "smooth", 0.01, f"Blender 3.4 Remesh modifier, Smooth, scale {SCALE}, cell "
                                "nearest 1% of the diagonal ({cells}), Remove Disconnected"),
    ("quadriflow1", "quadriflow", 0.01, "Blender 3.4 QuadriFlow remesh, as many quads as cells "
                                        "of 1% of the diagonal cover the surface, Preserve "
                                        "Sharp off, seed 0"),
)
# How the inputs were made (the markdown file's second paragraph).
MADE = """Each reference, read by Open3D, is remeshed by Blender 3.4 run headless (its
coordinates multiplied by a power of two that puts the diagonal in [1, 2), since Blender takes
no voxel size under 0.0001, and divided by it after: exact). The voxel remesh (OpenVDB;
Mesh.remesh_voxel_size, adaptivity 0) runs at 1% and 0.5% of the diagonal with Preserve Volume
on, as Blender sets it for every mesh: the new vertices are projected onto the input's surface
afterwards, so edges parallel to the grid axes come back almost sharp (the cube to 3e-6% of its
diagonal). The Remesh modifier in Smooth mode (scale 0.9, Remove Disconnected on) runs at the
octree depth whose cell (the largest side / 0.9 / 2^depth) is nearest 1% of the diagonal.
QuadriFlow (added 2026-11-28; Preserve Sharp, Preserve Boundary and Symmetry off, seed 0) aims
at as many quads as squares of 1% of the diagonal cover the surface; it lays its quads along a
cross field and puts their corners on the input's surface, so it cuts sharp edges into chamfers
as a remesher does, with no grid. A mesh it returns as it was is listed as not made. The
quads are triangulated in Blender (bmesh, Beauty) and the largest connected component is
kept; a mesh the sharpener refuses is listed with its message. The geometric means leave out
the references without sharp features (sphere, rocker-arm); chamfer-cube is left out, as its
reference is another shape."""
# What was learnt from it, by hand (written under the tables in --out).
NOTES = """What it found (diagnosed by hand):

- Every voxel case marked worse comes with Preserve Volume. With it off, none of abc6,
  bevelled_block, finished_hexprism, plate_holes and cube is worse at either size: the
  sharpened meshes are about as far from the reference either way (bevelled_block at 1%:
  0.57% / 0.037% from the projected input, 0.57% / 0.040% from the other), but the projected
  input is nearer (0.404% / 0.0357% against 0.704% / 0.0929%).
- abc6, bevelled_block, finished_hexprism: their designed bevels and fillets, as in the
  benchmark. plate_holes at 1%: its bottom outline is a fillet of radius 6.35 (1.7 voxels),
  which the projection leaves round and the sharpener turns into a sharp edge along the whole
  outline (vertices up to 0.86% of the diagonal from the fillet); at 0.5% (3.5 voxels) it is
  not worse.
- Planar regions' own planes (2026-11-27, `--local-planes-only` turns them off). First run
  with every shift allowed, it read lblock at voxel 1% 0.138% -> 0.322% (exact planes made
  faces along a concave edge coincide; the tuning half showed the same at cross_prism UMR
  0.5%); the rule now leaves a shift under a tenth of a spacing to the fitted planes, chosen on
  the tuning half but after seeing lblock here, so for that bound this check is not blind.
  With it: the same verdicts; validation means at voxel 1% max x2.18 -> x2.12, RMS x8.25 ->
  x8.06 (fandisk 0.302% -> 0.367%, finished_hexprism 0.559% -> 0.594%, already worse; block
  0.280% -> 0.253%).
- Edges stopped at corners (2026-11-27, chosen on the benchmark's tuning half): run once with
  it, the same verdicts and the same figures but one, finished_hexprism at voxel 1% (already
  worse), RMS 0.0502% -> 0.0505%.
- ADIS16480: the connector's pins (0.4 mm across: 0.6 and 1.2 voxels) are lost by the voxel
  remesh at both sizes and by the Smooth mode; the max, 6.3% and 3.3%, is the distance from
  them to the mesh, which no sharpener changes.
- The Smooth mode's non-manifold edges are Blender's own (present before triangulation;
  six refusals). Neither remesher left a floating part at 1%.
- tube, Smooth: the inner wall's two facets that face the x axis get a ridge along the tube's
  whole length, their middle vertices moved 0.07 units (0.6% of the diagonal) into the wall,
  which is under two cells thick (the benchmark's thin wall); not diagnosed further.
- First run with the build before the 2026-11-27 evidence rules (mostly-on-plane exemption,
  "most refused" feature bound), then with them: the same verdicts; twirl at 0.5% max 0.548%
  -> 0.603% (its input 0.598%: a max on its curved blades, not worse by the rule), block at
  0.5% RMS 0.00547% -> 0.00543%, nothing else changed.
- The bend rule of 2026-11-27 (a vertex whose flank bends away moves within one sample spacing
  with a feature that is sharpened; `--bent-move`, chosen on the benchmark's tuning half):
  the same verdicts; finished_hexprism at 1% RMS 0.0428% -> 0.0473% (its designed fillets;
  already worse, max unchanged), twirl at 0.5% max 0.603% -> 0.532%, block in Smooth mode
  0.75% -> 0.542%, a few RMS figures in the third digit.
- Samples off their planes on a mesh sampled exactly (2026-11-28, `--exact-sampling`): this
  check's Preserve Volume failures made the benchmark emulate it (the *vdbproj* family, its
  vertices within 5e-7 of the diagonal of Blender's), and the rule was chosen on that family's
  tuning half, so this check is not blind to it. Here: bevelled_block and finished_hexprism no
  longer worse at either size (1%: 0.570% -> 0.359% and 0.594% -> 0.389%; 0.5%: 0.473% ->
  0.179% and 0.270% -> 0.236%), the tube at 1% RMS 0.0144% -> 0.0165% (its input 0.0367%),
  nothing else changed; worse 4 -> 2 of 20 at 1% (abc6, plate_holes), 3 -> 1 at 0.5% (abc6).
  Own planes only where the fit is the same surface (the same day): bevelled_block at 1% RMS
  0.0375% -> 0.0374%, nothing else.
  'Already sharp' judged feature by feature on a mesh sampled exactly (2026-11-28, chosen on
  the benchmark's vdbproj family, tuning half): the projection leaves 7_8ths_cube's and
  cross_prism's convex edges sharp and their concave ones chamfered, and the whole mesh was
  left as already sharp; now only the sliding features are, and the corners they run into
  are judged by their own evidence. 7_8ths_cube 0.442% -> 0.361% at 1% and 0.218% -> 0.0748%
  at 0.5% (RMS x4.3 and x19), cross_prism RMS x1.32 and x1.94 (max as it was); nothing else
  changed, in this check or the four others.
- QuadriFlow (2026-11-28, first run; a tool no rule was chosen on): 4 of 20 worse, the
  validation half's max x1.39 / RMS x1.87 against the tuning half's x0.98 / x1.16 (over the 7
  tuning meshes it made).
  - plate_holes (tuning): its bottom fillet (radius 6.35, 1.7 of QuadriFlow's edges) along
    the rounded corners of its outline is sharpened to the box's edge: 215 output vertices lie
    more than 0.5 units farther from the reference than the input there (up to 3.7 units
    after moves of up to 3.9), 7 that much nearer. The same designed fillet as the voxel
    remesh's at 1%: with every vertex on the surface, a fillet under two edges wide looks
    like a chamfer.
  - abc6 and finished_hexprism: their designed chamfers and fillets, as in the benchmark.
  - rocker-arm (no sharp edge; validation half, not diagnosed further): QuadriFlow's mesh
    is rough by the smooth bound (noise 0.021 spacings) and 35% of the moves are refused,
    under the 40% bound, so 83 of 120 features are sharpened: blends made edges (max 0.602%
    -> 0.8%, RMS +50%). The benchmark's samplers give its moves more refusals (Open3D's
    Screened Poisson 49%).
  - ADIS16480 and twirl: QuadriFlow returns them as they were (not made); the sphere comes
    back with 1,217 vertices, 2.75% of its diagonal off.
  - The planes grown face by face on a rough input (the same day) run only on a mesh left
    whole: nothing here changed with them.
- Since 2026-12-04 an output near the worse line is judged on a million samples a side (as
  the benchmark's), and counted apart where a designed feature lies within the ambiguous
  width: abc6 by the voxel remesher at 1% reads 0.312% -> 0.316% (+1.3%), not worse; the
  worse outputs left with no designed feature that narrow are plate_holes' fillet (voxel 1%,
  QuadriFlow), tube's facets (Smooth mode) and rocker-arm (QuadriFlow).
- The designed-fillet rule (2026-12-05, chosen on the benchmark's tuning half;
  `--fillet-margin`), first run here on 2026-12-06: plate_holes at voxel 1% is no longer
  worse (RMS 0.103% -> 0.0446%, its input 0.0485%), and QuadriFlow's plate_holes RMS 0.0499%
  -> 0.0334% (max still worse). But cylinder_block (tuning half, no designed feature) in
  Smooth mode lost its gain: max 0.146% -> 1.13% (its input's), RMS 0.0072% -> 0.0889% (its
  input 0.104%). The octree's phase leaves five of its axis-parallel edges sharp and rounds
  eight others into clean arcs 2.0-2.2 spacings across; the rule takes those for designed
  fillets beside sharp edges a grid meets alike, as it does plate_holes' fillet beside its
  top edges under the projected voxel remesh. Widths alone cannot tell a 2.4-spacing fillet
  from a sampler's 2.2-spacing rounding. Not worse than its input (the report lists the eight
  edges as on the surface); `--fillet-margin 0` sharpens them (0.146%).
"""
# Run by Blender: blender -b --python-expr IN_BLENDER -- IN.npz OUT.npz voxel SIZE
#                                                      -- IN.npz OUT.npz smooth DEPTH
IN_BLENDER = f"""
import sys
import bmesh
import bpy
import numpy as np
src, dst, mode, value = sys.argv[sys.argv.index("--") + 1:]
bpy.ops.wm.read_factory_settings(use_empty=True)
data = np.load(src)
mesh = bpy.data.meshes.new("reference")
mesh.from_pydata(data["vertices"].tolist(), [], data["triangles"].tolist())
obj = bpy.data.objects.new("reference", mesh)
bpy.context.collection.objects.link(obj)
bpy.context.view_layer.objects.active = obj
if mode == "voxel":
    mesh.remesh_voxel_size = float(value)
    mesh.remesh_voxel_adaptivity = 0.0
    mesh.use_remesh_preserve_volume = True
    bpy.ops.object.voxel_remesh()
elif mode == "quadriflow":
    obj.select_set(True)
    counts = len(mesh.vertices), len(mesh.polygons)
    done = bpy.ops.object.quadriflow_remesh(
        target_faces=int(value), use_preserve_sharp=False, use_preserve_boundary=False,
        use_mesh_symmetry=False, seed=0)
    if done != {{"FINISHED"}}:
        sys.exit(f"QuadriFlow did not finish: {{done}}")
    if (len(obj.data.vertices), len(obj.data.polygons)) == counts:
        sys.exit("QuadriFlow left the mesh as it was")
else:
    remesh = obj.modifiers.new("remesh", "REMESH")
    remesh.mode = "SMOOTH"
    remesh.octree_depth = int(value)
    remesh.scale = {SCALE}
    remesh.use_remove_disconnected = True
    bpy.ops.object.modifier_apply(modifier=remesh.name)
bm = bmesh.new()
bm.from_mesh(obj.data)
bmesh.ops.triangulate(bm, faces=bm.faces[:])
bm.to_mesh(obj.data)
vertices = np.empty(3 * len(obj.data.vertices), np.float32)
obj.data.vertices.foreach_get("co", vertices)
triangles = np.empty(3 * len(obj.data.polygons), np.int32)
obj.data.polygons.foreach_get("vertices", triangles)
np.savez(dst, vertices=vertices.reshape(-1, 3), triangles=triangles.reshape(-1, 3))
"""


def diagonal(mesh):
    return float((mesh.get_axis_aligned_bounding_box().get_extent() ** 2).sum() ** 0.5)


def parameter(mesh, mode, fraction):
    """Blender's parameter (the voxel size, or the octree depth) for a cell of about fraction
    of the diagonal, and the cell it makes as a fraction of the diagonal."""
    if mode == "voxel":
        return fraction * diagonal(mesh), fraction
    if mode == "quadriflow":  # the number of quads
        return round(mesh.get_surface_area() / (fraction * diagonal(mesh)) ** 2), fraction
    side = max(mesh.get_axis_aligned_bounding_box().get_extent())
    depth = round(math.log2(side / (SCALE * fraction * diagonal(mesh))))
    return depth, side / (SCALE * 2 ** depth) / diagonal(mesh)


def remesh(mesh, out, mode, value):
    """Blender's remesh of mesh (voxel size, octree depth or number of quads: value),
    triangulated, its largest connected component written to out; "" or why not."""
    import numpy as np
    import open3d as o3d
    factor = 2.0 ** -math.floor(math.log2(diagonal(mesh)))
    with tempfile.TemporaryDirectory() as tmp:
        src, dst = os.path.join(tmp, "in.npz"), os.path.join(tmp, "out.npz")
        np.savez(src, vertices=np.asarray(mesh.vertices) * factor,
                 triangles=np.asarray(mesh.triangles))
        arg = str(value * factor) if mode == "voxel" else str(value)
        p = subprocess.run([BLENDER, "-b", "--factory-startup", "--python-exit-code", "1",
                            "--python-expr", IN_BLENDER, "--", src, dst, mode, arg],
                           capture_output=True, text=True)
        if p.returncode != 0:
            lines = (p.stderr or p.stdout).strip().splitlines()
            return f"Blender failed ({lines[-1] if lines else p.returncode})"
        data = np.load(dst)
        made = o3d.geometry.TriangleMesh(
            o3d.utility.Vector3dVector(data["vertices"].astype(np.float64) / factor),
            o3d.utility.Vector3iVector(data["triangles"]))
    clusters, counts, _ = made.cluster_connected_triangles()
    made.remove_triangles_by_mask(np.asarray(clusters) != int(np.argmax(np.asarray(counts))))
    made.remove_unreferenced_vertices()
    o3d.io.write_triangle_mesh(out, made)
    return ""


def table(sampler, refs, half, work, args):
    """One sampler's table (heldout.Table)."""
    key, mode, fraction, title = sampler
    cells, rows = [], []
    for name, ref in sorted(refs.items()):
        mesh = heldout.load_reference(ref)
        value, size = parameter(mesh, mode, fraction)
        cells.append(size)
        rows.append((name, ref, mesh, value, size))
    table = heldout.Table(title.format(cells=f"{min(cells):.2%}-{max(cells):.2%}")
                          + ", triangulated", args)
    for name, ref, mesh, value, size in rows:
        h = half.get(name, "?")
        faces = 2 * mesh.get_surface_area() / (size * diagonal(mesh)) ** 2
        if faces > MAX_FACES:
            table.skip(name, h, f"skipped: about {faces:.3g} faces")
            continue
        made = os.path.join(work, f"{name}__{key}.ply")
        table.make_and_measure(name, h, made, ref,
                               lambda: remesh(mesh, made, mode, value))
    return table.text()


def main():
    args = heldout.parse_args(__doc__, "blender_remesh.py")
    if not os.path.exists(BLENDER):
        sys.exit(f"blender_remesh: {BLENDER} (Debian blender) is not installed")
    heldout.run_samplers(args, SAMPLERS, table, "heldout-blender",
                         "Held-out check: Blender's remeshers", 4, MADE, NOTES)


if __name__ == "__main__":
    main()
