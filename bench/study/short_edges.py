#!/usr/bin/env python3
"""The default on the benchmark's cached inputs with their short edges collapsed first, beside as they come.

A study, not a stage of the sharpener: marching cubes (the project's, MeshLab's Uniform Mesh
Resampling) leave clusters of vertices a few hundredths of a cell apart where the surface passes
near a grid node; on a sharp edge the sharpener's new vertices then land on the edge line in an
order the cluster's tiny faces cannot follow, faces turn over, and the intersection guard sends
vertices back to rest, each a notch about half a cell deep (docs/auto-method-decisions.md,
2026-12-05 and 2026-12-06). This collapses every input edge shorter than EPS x the input's median
edge length, shortest first, each into the end that turns the faces around it least, where the
link condition holds and no face turns over (the input's own positions: no vertex moves), then
sharpens both meshes with the build's default and prints each one's max and RMS (% of the
diagonal; mesh-distance --sampling meshlab, 100,000 samples a side) with the input's.

Run: /usr/bin/python3 bench/study/short_edges.py [--eps 0.1,0.2] [--match REGEX] [--build build]
         [--features-only [--rings N]]
(the cache is made by scripts/bench-quality.sh). Needs Debian's python3-numpy and python3-open3d.
"""
import argparse
import json
import os
import pathlib
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import open3d as o3d

from evidence_study import cached_inputs, model_of, references
from notch_census import median_edge_length, sent_back_points

ROOT = pathlib.Path(__file__).resolve().parents[2]


def collapse_short_edges(vertices, faces, eps, allowed=None):
    """Collapses the edges shorter than eps x the median edge length, shortest first: each into
    the end whose removal turns the faces around it least, where the edge has two faces, the
    link condition holds and no face around turns over; with `allowed` (a vertex mask), only
    edges both of whose ends it holds. Returns (vertices, faces, collapses)."""
    faces = [list(f) for f in faces]
    limit = eps * median_edge_length(vertices, np.asarray(faces))
    faces_of = [set() for _ in range(len(vertices))]
    for i, f in enumerate(faces):
        for v in f:
            faces_of[v].add(i)
    alive = [True] * len(faces)
    lengths = {}
    for f in faces:
        for k in range(3):
            a, b = sorted((f[k], f[(k + 1) % 3]))
            lengths[(a, b)] = float(np.linalg.norm(vertices[a] - vertices[b]))
    short = sorted((length, edge) for edge, length in lengths.items() if length < limit
                   and (allowed is None or (allowed[edge[0]] and allowed[edge[1]])))

    def neighbours(v):
        out = set()
        for fi in faces_of[v]:
            out.update(faces[fi])
        out.discard(v)
        return out

    def normal(points):
        return np.cross(points[1] - points[0], points[2] - points[0])

    collapses = 0
    for _, (a, b) in short:
        shared = faces_of[a] & faces_of[b]
        if len(shared) != 2:
            continue
        opposite = set()
        for fi in shared:
            opposite.update(set(faces[fi]) - {a, b})
        if neighbours(a) & neighbours(b) != opposite:
            continue
        best = None
        for gone, kept in ((b, a), (a, b)):
            least_cos = 1.0
            for fi in faces_of[gone] - shared:
                before = normal(vertices[faces[fi]])
                after = normal(np.array([vertices[kept if v == gone else v] for v in faces[fi]]))
                cos = before @ after / max(np.linalg.norm(before) * np.linalg.norm(after), 1e-300)
                if not (np.linalg.norm(after) > 0 and before @ after > 0):
                    least_cos = None
                    break
                least_cos = min(least_cos, cos)
            if least_cos is not None and (best is None or least_cos > best[0]):
                best = (least_cos, gone, kept)
        if best is None:
            continue
        _, gone, kept = best
        for fi in shared:
            alive[fi] = False
            for v in faces[fi]:
                faces_of[v].discard(fi)
        for fi in faces_of[gone]:
            faces[fi] = [kept if v == gone else v for v in faces[fi]]
            faces_of[kept].add(fi)
        faces_of[gone] = set()
        collapses += 1
    kept_faces = np.array([f for f, keep in zip(faces, alive) if keep])
    used = np.unique(kept_faces)
    remap = np.full(len(vertices), -1)
    remap[used] = np.arange(len(used))
    return vertices[used], remap[kept_faces], collapses


def bounds_list(text):
    """--eps: comma-separated positive numbers."""
    try:
        bounds = [float(e) for e in text.split(",")]
    except ValueError:
        bounds = []
    if not bounds or not all(b > 0 for b in bounds):
        raise argparse.ArgumentTypeError(f"expected positive numbers separated by commas, got {text!r}")
    return bounds


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--shared", default=str(ROOT.parent / "shared" / "meshes"))
    parser.add_argument("--eps", type=bounds_list, default=[0.1, 0.2],
                        help="comma-separated bounds, in the input's median edge lengths")
    parser.add_argument("--match", default="", help="only the inputs whose file name this finds")
    parser.add_argument("--features-only", action="store_true",
                        help="collapse only edges among the faces of the features the default "
                             "restores on the input as it comes (its --json report)")
    parser.add_argument("--rings", type=int, default=0,
                        help="with --features-only: also the faces this many vertex rings around")
    parser.add_argument("--near-sent-back", type=float, default=0, metavar="SPACINGS",
                        help="collapse only edges within this many median edge lengths of a "
                             "vertex the default's guards sent back to rest (a notch: "
                             "notch_census.py)")
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    build = pathlib.Path(args.build)
    cache = build / "quality-cache"
    sharpener, distance = build / "apps" / "edge-sharpener", build / "apps" / "mesh-distance"
    tuning = set(json.load(open(ROOT / "bench" / "quality" / "split.json"))["tuning"])
    inputs = cached_inputs(str(cache), args.match)
    refs = references(str(cache), args.shared)
    bounds = args.eps

    def measure(mesh, ref):
        out = subprocess.run([distance, "--json", "--sampling", "meshlab", "--samples", "100000",
                              mesh, ref], capture_output=True, text=True, check=True)
        d = json.loads(out.stdout)["symmetric"]
        return f"{d['max_percent']:.3f}/{d['rms_percent']:.4f}"

    def one(path):
        model = model_of(path)
        if model not in refs:
            return None
        ref = refs[model]
        half = "tuning" if model in tuning else "validation"
        cells = [half, os.path.basename(path)[:-4], "input " + measure(path, ref)]
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "out.ply")
            run = subprocess.run([sharpener, "--json", "--colorize", "--colors", "paper", path,
                                  out], capture_output=True, text=True)
            if run.returncode:
                return "  ".join(cells + ["default failed"])
            cells.append("default " + measure(out, ref))
            mesh = o3d.io.read_triangle_mesh(path)
            vertices, faces = np.asarray(mesh.vertices), np.asarray(mesh.triangles)
            allowed = None
            if args.features_only:
                allowed = np.zeros(len(vertices), bool)
                for feature in json.loads(run.stdout)["features"]:
                    if feature["verdict"] == "restored":
                        allowed[faces[feature["faces"]].ravel()] = True
                for _ in range(args.rings):
                    allowed[faces[allowed[faces].any(axis=1)].ravel()] = True
            if args.near_sent_back > 0:
                sent = sent_back_points(o3d.io.read_triangle_mesh(out))
                reach = args.near_sent_back * median_edge_length(vertices, faces)
                near = np.zeros(len(vertices), bool)
                for q in sent:
                    near |= np.linalg.norm(vertices - q, axis=1) <= reach
                allowed = near if allowed is None else allowed & near
            for eps in bounds:
                v2, f2, n = collapse_short_edges(vertices, faces, eps, allowed)
                collapsed = os.path.join(tmp, "collapsed.ply")
                o3d.io.write_triangle_mesh(collapsed, o3d.geometry.TriangleMesh(
                    o3d.utility.Vector3dVector(v2), o3d.utility.Vector3iVector(f2)))
                if subprocess.run([sharpener, "-q", collapsed, out]).returncode:
                    cells.append(f"{eps:g}: failed")
                    continue
                cells.append(f"{eps:g} ({n} collapsed) " + measure(out, ref))
        return "  ".join(cells)

    with ThreadPoolExecutor(args.jobs) as pool:
        for line in pool.map(one, inputs):
            if line:
                print(line, flush=True)


if __name__ == "__main__":
    main()
