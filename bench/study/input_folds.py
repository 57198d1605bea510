#!/usr/bin/env python3
"""Faces the samplers leave folded over their neighbours, counted per cached input and family.

Two faces sharing an edge are folded over each other when their normals turn 120 degrees or more
apart (the pipeline's own test, `VertexRules::kFoldMaxCos`). The pipeline's planar-fold stage
re-tiles or relaxes only folds that sharpening made; a fold the input has stays, and a restored
face beside one can cross it, which the intersection guard answers by sending the restored vertex
back (a notch). This counts, for every cached input of the benchmark (no sharpening), the faces
of such pairs, per input and per sampler family, to say which samplers leave them.

Run: /usr/bin/python3 bench/study/input_folds.py [--match REGEX] [--build build] [--each]
(the cache is made by scripts/bench-quality.sh). Needs Debian's python3-numpy and python3-open3d.
"""
import argparse
import collections
import os
import pathlib

import numpy as np
import open3d as o3d

from evidence_study import cached_inputs, family_of

ROOT = pathlib.Path(__file__).resolve().parents[2]
FOLD_MAX_COS = -0.5  # VertexRules::kFoldMaxCos


def folded_faces(path):
    """How many faces of the mesh at `path` are folded over an edge neighbour, and its face count."""
    mesh = o3d.io.read_triangle_mesh(path)
    v, t = np.asarray(mesh.vertices), np.asarray(mesh.triangles)
    normals = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    normals /= np.maximum(np.linalg.norm(normals, axis=1), 1e-300)[:, None]
    edges = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    faces = np.tile(np.arange(len(t)), 3)
    key = np.sort(edges, axis=1)
    order = np.lexsort((key[:, 1], key[:, 0]))
    key, faces = key[order], faces[order]
    same = np.all(key[1:] == key[:-1], axis=1)  # manifold: an edge's two faces sit side by side
    a, b = faces[:-1][same], faces[1:][same]
    folded = np.einsum("ij,ij->i", normals[a], normals[b]) <= FOLD_MAX_COS
    return len(np.unique(np.concatenate([a[folded], b[folded]]))), len(t)


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--build", default=str(ROOT / "build"))
    ap.add_argument("--match", default="", help="only cached inputs whose file name this finds")
    ap.add_argument("--each", action="store_true", help="also one line per input with folds")
    args = ap.parse_args()
    totals = collections.defaultdict(lambda: [0, 0, 0])  # inputs, with folds, folded faces
    for path in cached_inputs(os.path.join(args.build, "quality-cache"), args.match):
        folded, faces = folded_faces(path)
        row = totals[family_of(path)]
        row[0] += 1
        row[1] += folded > 0
        row[2] += folded
        if args.each and folded:
            print(f"{os.path.basename(path)}: {folded} of {faces} faces folded")
    print("| family | inputs | with folded faces | folded faces |")
    print("|---|---|---|---|")
    for family, (inputs, with_folds, folded) in sorted(totals.items()):
        print(f"| {family} | {inputs} | {with_folds} | {folded} |")


if __name__ == "__main__":
    main()
