#!/usr/bin/python3
"""Where a mesh's error lies against its reference, by distance to the reference's sharp edges.

  /usr/bin/python3 bench/study/scan_error_bands.py REFERENCE MESH [--angle 30] [--samples 100000]

Samples both surfaces evenly (Open3D), measures each sample's distance to the other surface and
to the reference's sharp edges (dihedral angle above --angle degrees), and prints, per band of
that edge distance (in % of the reference's diagonal): the band's share of the reference's area,
its share of the two-sided squared error and its largest distance. Written for the depth scans
of the quality benchmark (docs/auto-method-decisions.md: "A rough input's planar faces are flattened"), whose
fusion bulges the faces for a few voxels beside every edge. Needs Debian's python3-open3d.
"""
import argparse
from collections import defaultdict

import numpy as np
import open3d as o3d

BANDS = ((0, 1), (1, 2), (2, 4), (4, float("inf")))


def sharp_edges(mesh, angle_deg):
    """The reference's edges whose faces' normals turn by more than angle_deg: (starts, ends)."""
    mesh.compute_triangle_normals()
    verts, tris = np.asarray(mesh.vertices), np.asarray(mesh.triangles)
    normals = np.asarray(mesh.triangle_normals)
    faces_of = defaultdict(list)
    for f, t in enumerate(tris):
        for k in range(3):
            faces_of[tuple(sorted((t[k], t[(k + 1) % 3])))].append(f)
    cos_limit = np.cos(np.radians(angle_deg))
    edges = [e for e, fs in faces_of.items()
             if len(fs) == 2 and normals[fs[0]] @ normals[fs[1]] < cos_limit]
    return verts[[a for a, _ in edges]], verts[[b for _, b in edges]]


def distance_to_segments(points, starts, ends):
    best = np.full(len(points), np.inf)
    for a, b in zip(starts, ends):
        ab = b - a
        t = np.clip(((points - a) @ ab) / max(ab @ ab, 1e-30), 0, 1)
        best = np.minimum(best, np.linalg.norm(points - (a + t[:, None] * ab), axis=1))
    return best


def distance_to_mesh(mesh, points):
    scene = o3d.t.geometry.RaycastingScene()
    scene.add_triangles(o3d.t.geometry.TriangleMesh.from_legacy(mesh))
    return scene.compute_distance(o3d.core.Tensor(points.astype(np.float32))).numpy()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("reference")
    ap.add_argument("mesh")
    ap.add_argument("--angle", type=float, default=30.0, help="sharp edge: dihedral above, deg")
    ap.add_argument("--samples", type=int, default=100000)
    args = ap.parse_args()
    ref = o3d.io.read_triangle_mesh(args.reference)
    ref.remove_duplicated_vertices()
    mesh = o3d.io.read_triangle_mesh(args.mesh)
    verts = np.asarray(ref.vertices)
    diag = np.linalg.norm(verts.max(0) - verts.min(0))
    starts, ends = sharp_edges(ref, args.angle)
    on_ref = np.asarray(ref.sample_points_uniformly(args.samples).points)
    on_mesh = np.asarray(mesh.sample_points_uniformly(args.samples).points)
    err_ref = distance_to_mesh(mesh, on_ref) / diag * 100
    err_mesh = distance_to_mesh(ref, on_mesh) / diag * 100
    edge_ref = distance_to_segments(on_ref, starts, ends) / diag * 100
    edge_mesh = distance_to_segments(on_mesh, starts, ends) / diag * 100
    total = (err_ref ** 2).sum() + (err_mesh ** 2).sum()
    print(f"{len(starts)} sharp edges; distances in % of the diagonal")
    for lo, hi in BANDS:
        in_ref = (edge_ref >= lo) & (edge_ref < hi)
        in_mesh = (edge_mesh >= lo) & (edge_mesh < hi)
        share = ((err_ref[in_ref] ** 2).sum() + (err_mesh[in_mesh] ** 2).sum()) / total
        largest = max(err_ref[in_ref].max(initial=0), err_mesh[in_mesh].max(initial=0))
        print(f"edge distance {lo:g}-{hi:g}%: area {in_ref.mean():.2f}, squared error "
              f"{share:.2f}, max {largest:.3f}%")


if __name__ == "__main__":
    main()
