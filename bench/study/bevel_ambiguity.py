#!/usr/bin/env python3
"""How alike marching cubes makes a sharp edge and a designed bevel (issue 20's information limit).

A sharp, axis-aligned 90-degree edge and the same edge cut by a designed 45-degree bevel are
sampled by marching cubes over an exact signed distance field, the way MeshLab's Uniform Mesh
Resampling and the project's own marching cubes sample a shape. Along an axis-aligned edge the
field does not change, so each mesh is its marching-squares contour extruded along the edge: the
study works on the cross-section, exactly.

For each phase of the grid against the edge (where the edge falls inside its cell, in x and in z),
it finds the widest bevel, among legs of 0.05 to 3 cells, whose marching-cubes contour lies within
a tolerance of the sharp edge's (the same contour to rounding, 1e-6 cells; and 0.05 cells, the
distance within which the default method takes a sample to lie on its plane), and prints:
- the bevel's leg (cut along each face) and width (across), in cells;
- the Hausdorff distance between the two marching-cubes contours (what a sharpener can see);
- the Hausdorff distance between the two true shapes (the bevel's depth, leg / sqrt 2);
- the input's own max error against each true shape: a sharpener that restores the edge lowers
  the first to about zero and raises the second to the bevel's depth; one that leaves the mesh
  keeps both. Where the two inputs are the same mesh, no rule does both;
- the largest reduction of the sharp shape's max error that leaves the bevelled shape's max error
  no more than 2% up (the benchmark's "worse"): the output may lie at most 1.02 times the input's
  error from the bevel, so at least the bevel's depth less that from the sharp edge.

All distances in cells (the grid's spacing; a marching-cubes mesh's median edge length on a flat
face is about one cell). Run: /usr/bin/python3 bench/study/bevel_ambiguity.py
Needs Debian's python3-numpy and python3-skimage (scikit-image's find_contours is marching
squares with linear interpolation along the grid's edges).
"""
import argparse
import math

import numpy as np
from skimage import measure

# The benchmark's "worse" by the max error (bench/quality/families.py: WORSE_MAX).
WORSE_MAX = 0.02
# How far apart two marching-cubes meshes may lie and still be taken for one, in cells: to
# rounding, and the 0.05 sample spacings within which the default takes a sample to lie on its
# plane.
TOLERANCES = (1e-6, 0.05)
# Errors are floored here (cells) where a ratio divides by them: a bevel sampled exactly.
ERROR_FLOOR = 1e-3


def region_corners(edge_x, edge_z, leg, finish="bevel"):
    """The cross-section's boundary near the edge: {x <= edge_x, z <= edge_z}, cut by
    x + z <= edge_x + edge_z - leg (a bevel) or rounded by a quarter circle of radius `leg`
    tangent to both faces (a fillet) when leg > 0, as a polyline from far down the x face,
    over the edge, to far along the z face."""
    far = 50.0
    if leg <= 0:
        return np.array([[edge_x, edge_z - far], [edge_x, edge_z], [edge_x - far, edge_z]])
    if finish == "fillet":
        t = np.linspace(0.0, math.pi / 2, 91)
        arc = np.stack([edge_x - leg + leg * np.cos(t), edge_z - leg + leg * np.sin(t)], axis=1)
        return np.concatenate([[[edge_x, edge_z - far]], arc, [[edge_x - far, edge_z]]])
    return np.array([[edge_x, edge_z - far], [edge_x, edge_z - leg], [edge_x - leg, edge_z],
                     [edge_x - far, edge_z]])


def point_segment_distance(p, a, b):
    """Distances from points p (n x 2) to the segment a-b."""
    ab = b - a
    t = np.clip(((p - a) @ ab) / (ab @ ab), 0.0, 1.0)
    return np.linalg.norm(p - (a + t[:, None] * ab), axis=1)


def polyline_distance(p, poly):
    """Distances from points p (n x 2) to a polyline."""
    return np.min([point_segment_distance(p, poly[i], poly[i + 1]) for i in range(len(poly) - 1)],
                  axis=0)


def signed_distance(x, z, edge_x, edge_z, leg, finish="bevel"):
    """Exact signed distance to the convex cross-section (negative inside)."""
    if finish == "fillet" and leg > 0:
        qx, qz = x - (edge_x - leg), z - (edge_z - leg)
        rounded = np.hypot(np.maximum(qx, 0.0), np.maximum(qz, 0.0))
        return rounded + np.minimum(np.maximum(qx, qz), 0.0) - leg
    planes = [(np.array([1.0, 0.0]), edge_x), (np.array([0.0, 1.0]), edge_z)]
    if leg > 0:
        s = 1.0 / math.sqrt(2.0)
        planes.append((np.array([s, s]), (edge_x + edge_z - leg) * s))
    p = np.stack([x.ravel(), z.ravel()], axis=1)
    inside = np.max([p @ n - d for n, d in planes], axis=0)
    outside = polyline_distance(p, region_corners(edge_x, edge_z, leg))
    return np.where(inside <= 0, inside, outside).reshape(x.shape)


def contour(edge_x, edge_z, leg, finish="bevel", half=6):
    """The marching-squares contour of the cross-section on the unit grid, in grid units."""
    xs = np.arange(-half, half + 1, dtype=float)
    x, z = np.meshgrid(xs, xs, indexing="ij")
    lines = measure.find_contours(signed_distance(x, z, edge_x, edge_z, leg, finish), 0.0)
    line = max(lines, key=len)
    return line - half  # find_contours returns (row, column) = (x, z) indices


def densify(poly, step=0.01):
    """Points along a polyline, at most `step` apart."""
    out = []
    for a, b in zip(poly[:-1], poly[1:]):
        n = max(1, int(math.ceil(np.linalg.norm(b - a) / step)))
        out.append(a + (b - a) * (np.arange(n)[:, None] / n))
    out.append(poly[-1:])
    return np.concatenate(out)


def near_edge(points, edge_x, edge_z, radius):
    """The points within `radius` of the edge (both contours run on to the grid's border)."""
    return points[np.linalg.norm(points - [edge_x, edge_z], axis=1) <= radius]


def hausdorff(a, b, edge_x, edge_z, radius=3.0):
    """Two-sided Hausdorff distance between two polylines, over their parts near the edge."""
    pa = near_edge(densify(a), edge_x, edge_z, radius)
    pb = near_edge(densify(b), edge_x, edge_z, radius)
    return max(polyline_distance(pa, b).max(), polyline_distance(pb, a).max())


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--phases", default="0.1,0.3,0.5,0.7,0.9",
                    help="where the edge falls in its cell, in x and in z (fractions of a cell)")
    ap.add_argument("--finish", choices=("bevel", "fillet"), default="bevel",
                    help="the designed feature: a 45-degree bevel (its leg) or a fillet turning "
                         "the right angle (its radius); its width is leg x sqrt 2 either way")
    args = ap.parse_args()
    finish = args.finish
    phases = [float(p) for p in args.phases.split(",")]
    legs = np.round(np.arange(0.05, 3.0001 if finish == "bevel" else 5.0001, 0.05), 2)
    print(f"| edge phase x, z | tolerance, cells | widest {finish}: "
          f"{'leg' if finish == 'bevel' else 'radius'} / width, cells "
          "| marching cubes apart, cells | true shapes apart (bevel's depth), cells "
          "| input's max error against the sharp shape / the bevelled one, cells "
          "| best gain on the sharp shape without harm to the bevelled one |")
    print("|---|---|---|---|---|---|---|")
    alike_rows = {t: [] for t in TOLERANCES}  # (width, error against the bevel, depth, ceiling)
    for px in phases:
        for pz in phases:
            sharp_mc = contour(px, pz, 0.0)
            sharp = region_corners(px, pz, 0.0)
            against_sharp = hausdorff(sharp_mc, sharp, px, pz)
            seen = {leg: hausdorff(sharp_mc, contour(px, pz, leg, finish), px, pz)
                    for leg in legs}
            for tolerance in TOLERANCES:
                alike = [leg for leg in legs if seen[leg] <= tolerance]
                if not alike:
                    print(f"| {px:g}, {pz:g} | {tolerance:g} | none | | | | |")
                    continue
                leg = max(alike)
                bevelled = region_corners(px, pz, leg, finish)
                depth = hausdorff(sharp, bevelled, px, pz)
                against_bevel = hausdorff(sharp_mc, bevelled, px, pz)
                allowed = (1 + WORSE_MAX) * against_bevel
                ceiling = min(against_sharp / max(depth - allowed, ERROR_FLOOR * depth), 1e3)
                alike_rows[tolerance].append((leg * math.sqrt(2), against_bevel, depth, ceiling))
                print(f"| {px:g}, {pz:g} | {tolerance:g} | {leg:.2f} / {leg * math.sqrt(2):.2f} "
                      f"| {seen[leg]:.3f} | {depth:.3f} "
                      f"| {against_sharp:.3f} / {against_bevel:.3f} | x{ceiling:.2f} |")
    for tolerance, rows in alike_rows.items():
        widths = sorted(w for w, _, _, _ in rows)
        harmed = [(before, after, c) for _, before, after, c in rows
                  if after > (1 + WORSE_MAX) * before]
        worse = [after / max(before, ERROR_FLOOR) for before, after, _ in harmed]
        ceilings = sorted(c for _, _, c in harmed)
        print(f"\nMeshes within {tolerance:g} cells: over {len(rows)} places of the edge, the "
              f"widest {finish} is {widths[0]:.2f}-{widths[-1]:.2f} cells wide (median "
              f"{widths[len(widths) // 2]:.2f}); restoring the edge raises the bevelled shape's "
              f"max error at {len(worse)} of them"
              + (f" (by x{min(worse):.2f} to x{max(worse):.2f})" if worse else "") + "; "
              + (f"there, without that harm, the sharp shape's max error falls at best by "
                 f"x{ceilings[0]:.2f} to x{ceilings[-1]:.2f} (median "
                 f"x{ceilings[len(ceilings) // 2]:.2f})." if ceilings else ""))


if __name__ == "__main__":
    main()
