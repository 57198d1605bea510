#!/usr/bin/env python3
"""The narrow planar facets of a reference (designed faces between two creases, as fandisk's
0.05-wide face or octa-flower17k's petal-tip facets), with their width across, and where a
sharpened mesh's harmful moves lie beside them: the numbers behind an entry of
bench/quality/designed.json.

A facet is a connected set of reference faces whose normals lie within --angle degrees of
the first face's (grown across shared edges); its width across is measured in bins along its
longest axis. With MESH, `evidence-study --vertices` is run on it and, for every moved vertex
that lands more than --harm sample spacings farther from the reference than it was, the
nearest narrow facet and that facet's width where the vertex lies are printed, in MESH's
sample spacings (its median edge length).

Run: /usr/bin/python3 bench/study/narrow_facets.py REF [--mesh MESH] [--max-width W]
         [--within=X,Y,Z,R ...] [--build build]
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys
from collections import defaultdict

import numpy as np

import within

ROOT = pathlib.Path(__file__).resolve().parents[2]


def read(path):
    try:
        import open3d as o3d
    except ImportError as e:
        sys.exit(f"narrow_facets: {e} (Debian python3-open3d)")
    m = o3d.io.read_triangle_mesh(path)
    m.merge_close_vertices(1e-9)
    m.compute_triangle_normals()
    return np.asarray(m.vertices), np.asarray(m.triangles), np.asarray(m.triangle_normals)


def facets(t, n, max_turn_deg):
    """Connected groups of faces whose normals lie within max_turn_deg of their seed's."""
    by_edge = defaultdict(list)
    for f, tri in enumerate(t):
        for i in range(3):
            by_edge[tuple(sorted((tri[i], tri[(i + 1) % 3])))].append(f)
    neighbours = defaultdict(list)
    for fs in by_edge.values():
        for a in fs:
            neighbours[a].extend(b for b in fs if b != a)
    cos = np.cos(np.radians(max_turn_deg))
    group = np.full(len(t), -1)
    groups = []
    for seed in range(len(t)):
        if group[seed] >= 0:
            continue
        group[seed] = len(groups)
        members, stack = [seed], [seed]
        while stack:
            for g in neighbours[stack.pop()]:
                if group[g] < 0 and n[g] @ n[seed] >= cos:
                    group[g] = len(groups)
                    members.append(g)
                    stack.append(g)
        groups.append(members)
    return groups


def profile(v, t, n, members, bins=8):
    """(normal, centre, long axis, across axis, points, widths along the long axis)."""
    normal = n[members].mean(axis=0)
    normal /= np.linalg.norm(normal)
    points = v[np.unique(t[members])]
    centre = points.mean(axis=0)
    q = points - centre
    q -= np.outer(q @ normal, normal)
    _, axes = np.linalg.eigh(q.T @ q)
    along, across = q @ axes[:, 2], q @ axes[:, 1]
    edges = np.linspace(along.min(), along.max(), bins + 1)
    widths = [np.ptp(across[(along >= lo) & (along <= hi)])
              for lo, hi in zip(edges[:-1], edges[1:])
              if ((along >= lo) & (along <= hi)).sum() > 1]
    return normal, centre, axes[:, 2], axes[:, 1], points, widths


def width_at(facet, x, reach):
    """The facet's width across at the position of x along its long axis (within reach), or
    None where x lies past the facet's ends."""
    _, centre, long_axis, across_axis, points, _ = facet
    along = (points - centre) @ long_axis
    near = np.abs(along - (x - centre) @ long_axis) <= reach
    return np.ptp((points[near] - centre) @ across_axis) if near.sum() > 1 else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("reference")
    ap.add_argument("--mesh", help="an input whose default output's harmful moves to place")
    ap.add_argument("--max-width", type=float, default=np.inf,
                    help="list facets whose widest bin is at most this (reference units)")
    ap.add_argument("--min-faces", type=int, default=3)
    ap.add_argument("--angle", type=float, default=4.0, help="degrees a facet's normals turn")
    within.add_option(ap, "only facets with a face centroid within R of this point")
    ap.add_argument("--harm", type=float, default=0.3,
                    help="a move is harmful when it lands this many spacings farther")
    ap.add_argument("--build", default=str(ROOT / "build"))
    args = ap.parse_args()
    v, t, n = read(args.reference)
    centroids = v[t].mean(axis=1)
    spheres = within.spheres(args, "narrow_facets")
    found = []
    for members in facets(t, n, args.angle):
        if len(members) < args.min_faces:
            continue
        if spheres and not within.inside(centroids[members], spheres).any():
            continue
        facet = profile(v, t, n, members)
        if facet[5] and max(facet[5]) <= args.max_width:
            found.append(facet)
    print(f"{len(found)} facets ({args.reference}); width across in bins along each:")
    for normal, centre, _, _, _, widths in found:
        print(f"  normal {np.round(normal, 3)} at {np.round(centre, 2)}: "
              + " ".join(f"{w:.3g}" for w in widths))
    if not args.mesh or not found:
        return
    out = subprocess.run([os.path.join(args.build, "bench", "study", "evidence-study"),
                          args.mesh, args.reference, "case", "--vertices"],
                         capture_output=True, text=True, check=True).stdout
    moves = [json.loads(line) for line in out.splitlines() if line.startswith("{")]
    mv, mt, _ = read(args.mesh)
    spacing = np.median(np.linalg.norm(mv[mt] - mv[mt[:, [1, 2, 0]]], axis=2))
    harmful = sorted((m for m in moves if m["after"] - m["before"] > args.harm),
                     key=lambda m: -m["after"])
    print(f"{len(harmful)} moves land more than {args.harm:g} spacings farther "
          f"(spacing {spacing:.4g}); before -> after (spacings), the nearest facet:")
    widths = []
    for m in harmful:
        x = np.array(m["x"])
        facet = min(found, key=lambda f: np.linalg.norm(f[4] - x, axis=1).min())
        w = width_at(facet, x, spacing)
        there = "past its end" if w is None else f"{w / spacing:.2f} spacings wide there"
        if w is not None:
            widths.append(w / spacing)
        print(f"  {m['before']:.2f} -> {m['after']:.2f} at {np.round(x, 2)}: facet "
              f"{np.round(facet[0], 2)}, {np.linalg.norm(facet[4] - x, axis=1).min() / spacing:.2f}"
              f" spacings away, {there}")
    if widths:
        print(f"facet width beside the {len(widths)} harmful moves not past a facet's end: "
              f"{min(widths):.2f}-{max(widths):.2f} spacings (median {np.median(widths):.2f})")


if __name__ == "__main__":
    main()
