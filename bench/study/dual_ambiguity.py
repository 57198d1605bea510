#!/usr/bin/env python3
"""How alike a voxel remesher makes a sharp edge and a designed fillet (issue 61, point 4).

The companion of bevel_ambiguity.py (marching cubes; `--finish fillet` there for fillets) for the
sampler of OpenVDB's volumeToMesh and Blender's voxel remesh: one vertex per cell the surface
crosses, at the mean of the surface's crossings of the cell's edges, joined across every crossed
grid edge (a dual contour; OpenVDB at adaptivity 0). With Preserve Volume, Blender then casts each
vertex onto the input: here, onto its nearest point of the true cross-section (the benchmark's
*vdbproj* family). A sharp, axis-aligned 90-degree edge and the same edge rounded by a fillet are
sampled over their exact signed distance, in cross-section (along an axis-aligned edge the field
does not change), for each phase of the grid against the edge, and it prints the widest fillet
(radius and width across, in cells) whose mesh lies within 0.05 cells of the sharp edge's:
- both by the voxel remesher (one sampler, as bevel_ambiguity.py asks of marching cubes);
- the fillet by the voxel remesher with its vertices cast onto it, the sharp edge without (two
  samplers a user may have run: the mesh alone does not say which).

Run: /usr/bin/python3 bench/study/dual_ambiguity.py (about a minute). Needs Debian's
python3-numpy and python3-skimage.
"""
import argparse

import numpy as np

import bevel_ambiguity as bevel

TOLERANCE = 0.05  # cells, as bevel_ambiguity.py's wider tolerance


def dual_segments(edge_x, edge_z, radius, cast=False, half=6):
    """The dual contour of the cross-section (a fillet of `radius`; 0: the sharp edge) on the
    unit grid, as segments; with `cast`, every vertex moved to its nearest point of the shape."""
    xs = np.arange(-half, half + 1, dtype=float)
    x, z = np.meshgrid(xs, xs, indexing="ij")
    f = bevel.signed_distance(x, z, edge_x, edge_z, radius, "fillet")
    n = len(xs)
    vertex = {}
    for i in range(n - 1):
        for j in range(n - 1):
            ring = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            crossings = []
            for (a0, a1), (b0, b1) in zip(ring, ring[1:] + ring[:1]):
                fa, fb = f[a0, a1], f[b0, b1]
                if (fa < 0) != (fb < 0):
                    t = fa / (fa - fb)
                    crossings.append(np.array([xs[a0] + t * (xs[b0] - xs[a0]),
                                               xs[a1] + t * (xs[b1] - xs[a1])]))
            if crossings:
                vertex[(i, j)] = np.mean(crossings, axis=0)
    if cast:
        shape = bevel.densify(bevel.region_corners(edge_x, edge_z, radius, "fillet"), 0.002)
        for k, v in vertex.items():
            vertex[k] = shape[np.argmin(np.linalg.norm(shape - v, axis=1))]
    # Each crossed grid edge joins the two cells it bounds: an edge along x from node (i, j)
    # bounds cells (i, j - 1) and (i, j); one along z, cells (i - 1, j) and (i, j).
    segments = []
    for i in range(n):
        for j in range(n):
            crossed = []
            if i + 1 < n and (f[i, j] < 0) != (f[i + 1, j] < 0):
                crossed.append(((i, j - 1), (i, j)))
            if j + 1 < n and (f[i, j] < 0) != (f[i, j + 1] < 0):
                crossed.append(((i - 1, j), (i, j)))
            for a, b in crossed:
                if a in vertex and b in vertex:
                    segments.append((vertex[a], vertex[b]))
    return segments


def segments_distance(points, segments):
    return np.min([bevel.point_segment_distance(points, a, b) for a, b in segments], axis=0)


def near_points(segments, edge_x, edge_z, radius=3.0):
    points = np.concatenate([bevel.densify(np.array([a, b])) for a, b in segments])
    return bevel.near_edge(points, edge_x, edge_z, radius)


def hausdorff(a, b, edge_x, edge_z):
    """Two-sided Hausdorff distance between two segment sets, over their parts near the edge."""
    return max(segments_distance(near_points(a, edge_x, edge_z), b).max(),
               segments_distance(near_points(b, edge_x, edge_z), a).max())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--phases", default="0.1,0.3,0.5,0.7,0.9",
                    help="where the edge falls in its cell, in x and in z (fractions of a cell)")
    args = ap.parse_args()
    phases = [float(p) for p in args.phases.split(",")]
    radii = np.round(np.arange(0.1, 4.0001, 0.1), 2)
    print("| edge phase x, z | widest fillet alike, one sampler: radius / width, cells "
          "| the fillet cast onto its surface: radius / width, cells |")
    print("|---|---|---|")
    widest = {"one": [], "cast": []}
    for px in phases:
        for pz in phases:
            sharp = dual_segments(px, pz, 0.0)
            cells = []
            for kind, cast in (("one", False), ("cast", True)):
                alike = [r for r in radii
                         if hausdorff(sharp, dual_segments(px, pz, r, cast), px, pz) <= TOLERANCE]
                r = max(alike) if alike else 0.0
                widest[kind].append(r * np.sqrt(2))
                cells.append(f"{r:.1f} / {r * np.sqrt(2):.2f}" if alike else "none")
            print(f"| {px:g}, {pz:g} | {cells[0]} | {cells[1]} |")
    for kind, label in (("one", "by the voxel remesher alone"),
                        ("cast", "cast onto the fillet, against the sharp edge uncast")):
        w = sorted(widest[kind])
        print(f"\nWithin {TOLERANCE:g} cells, {label}: over {len(w)} places of the edge, the "
              f"widest fillet is {w[0]:.2f}-{w[-1]:.2f} cells wide (median {w[len(w) // 2]:.2f}).")


if __name__ == "__main__":
    main()
