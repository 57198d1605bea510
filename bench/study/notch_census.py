#!/usr/bin/env python3
"""Where the default's max error lies: at a vertex the guards sent back to rest, or elsewhere.

For every cached input of the grid samplers (MeshLab's Uniform Mesh Resampling, OpenVDB plain and
cast onto the surface, the project's marching cubes), sharpens it with the build's default and
`--colorize --colors paper` (which paints each new vertex by its placement outcome: sent back by
the intersection guard pink, by the degenerate cleanup white; the geometry is the one without
colours), finds the output's farthest point from the reference both ways (its vertices and
100,000 uniform samples a side, Open3D's closest-point queries, so its max differs a little from
the benchmark's; on the reference's side, the output point nearest it), and measures how far that point lies from the nearest vertex sent back,
in the input's median edge lengths. A vertex sent back to rest leaves a notch in its restored
edge as deep as its move: the census says how many outputs' max error is such a notch.

Run: /usr/bin/python3 bench/study/notch_census.py [--match REGEX] [--build build] [--within 1]
(the cache is made by scripts/bench-quality.sh). Needs Debian's python3-numpy and python3-open3d.
"""
import argparse
import collections
import json
import os
import pathlib
import re
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import open3d as o3d

from evidence_study import cached_inputs, model_of, references

ROOT = pathlib.Path(__file__).resolve().parents[2]
SENT_BACK = {(255, 150, 200): "intersection guard", (255, 255, 255): "cleanup"}
FAMILY = re.compile(r"__(umr|vdbproj|vdb)_")


def median_edge_length(vertices, faces):
    """The mesh's median edge length (each edge once per face): its sample spacing."""
    edges = np.vstack([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    return float(np.median(np.linalg.norm(vertices[edges[:, 0]] - vertices[edges[:, 1]], axis=1)))


def sent_back_points(painted, guards=tuple(SENT_BACK.values())):
    """The vertices of a `--colorize --colors paper` output that `guards` sent back to rest."""
    colours = np.round(np.asarray(painted.vertex_colors) * 255).astype(int)
    sent = np.zeros(len(colours), bool)
    for colour, guard in SENT_BACK.items():
        if guard in guards:
            sent |= np.all(colours == colour, axis=1)
    return np.asarray(painted.vertices)[sent]


def surface_samples(mesh, count, seed=1):
    """`count` points uniform over the mesh's area (a fixed seed: reruns read the same points)."""
    v, f = np.asarray(mesh.vertices), np.asarray(mesh.triangles)
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    area = np.linalg.norm(np.cross(b - a, c - a), axis=1)
    rng = np.random.default_rng(seed)
    pick = rng.choice(len(f), size=count, p=area / area.sum())
    r1, r2 = np.sqrt(rng.random(count)), rng.random(count)
    return ((1 - r1)[:, None] * a[pick] + (r1 * (1 - r2))[:, None] * b[pick]
            + (r1 * r2)[:, None] * c[pick])


def without_zero_area_faces(mesh):
    """A copy without faces of no area (an input's exact duplicates leave some; they add no
    surface, and Debian's Open3D 0.16 aborts on them in closest-point queries)."""
    v, f = np.asarray(mesh.vertices), np.asarray(mesh.triangles)
    area = np.linalg.norm(np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]]), axis=1)
    return o3d.geometry.TriangleMesh(mesh.vertices, o3d.utility.Vector3iVector(f[area > 0]))


def farthest_point(out_path, ref_path):
    """The output point farthest from the reference, or nearest the reference point farthest from
    the output, whichever distance is larger: (distance in % of the diagonal, point)."""
    out = without_zero_area_faces(o3d.io.read_triangle_mesh(out_path))
    ref = o3d.io.read_triangle_mesh(ref_path)
    ref.remove_duplicated_vertices()
    ref = without_zero_area_faces(ref)
    diagonal = float(np.linalg.norm(ref.get_max_bound() - ref.get_min_bound()))
    best = (-1.0, None)
    for source, target, on_output in ((out, ref, True), (ref, out, False)):
        points = np.vstack([surface_samples(source, 100000), np.asarray(source.vertices)])
        scene = o3d.t.geometry.RaycastingScene()
        scene.add_triangles(o3d.t.geometry.TriangleMesh.from_legacy(target))
        closest = scene.compute_closest_points(
            o3d.core.Tensor(points.astype(np.float32)))["points"].numpy()
        d = np.linalg.norm(points - closest, axis=1)
        i = int(np.argmax(d))
        if d[i] > best[0]:
            best = (float(d[i]), points[i] if on_output else closest[i])
    return 100 * best[0] / diagonal, [float(x) for x in best[1]]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--shared", default=str(ROOT.parent / "shared" / "meshes"))
    parser.add_argument("--match", default="", help="only the inputs whose file name this finds")
    parser.add_argument("--within", type=float, default=1.0,
                        help="a max error this near a vertex sent back counts as its notch "
                             "(input's median edge lengths)")
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    build = pathlib.Path(args.build)
    cache = build / "quality-cache"
    tuning = set(json.load(open(ROOT / "bench" / "quality" / "split.json"))["tuning"])
    inputs = [p for p in cached_inputs(str(cache), args.match)
              if FAMILY.search(p) or p.endswith("_mc1.ply")]
    refs = references(str(cache), args.shared)

    def one(path):
        name, model = os.path.basename(path)[:-len(".ply")], model_of(path)
        if model not in refs:
            return None
        grid = FAMILY.search(path)
        family = grid.group(1) if grid else "mc"
        half = "tuning" if model in tuning else "validation"
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "out.ply")
            subprocess.run([build / "apps" / "edge-sharpener", "-q", "--colorize", "--colors",
                            "paper", path, out], check=True)
            max_percent, point = farthest_point(out, refs[model])
            painted = o3d.io.read_triangle_mesh(out)
        source = o3d.io.read_triangle_mesh(path)
        spacing = median_edge_length(np.asarray(source.vertices), np.asarray(source.triangles))
        nearest, sent_count = None, 0
        for guard in SENT_BACK.values():
            sent = sent_back_points(painted, (guard,))
            sent_count += len(sent)
            if len(sent):
                d = float(np.min(np.linalg.norm(sent - point, axis=1))) / spacing
                if nearest is None or d < nearest[0]:
                    nearest = (d, guard)
        return half, family, name, max_percent, nearest, sent_count

    counts = collections.defaultdict(collections.Counter)
    with ThreadPoolExecutor(args.jobs) as pool:
        for row in pool.map(one, inputs):
            if row is None:
                continue
            half, family, name, max_percent, nearest, sent = row
            key = (half, family)
            counts[key]["outputs"] += 1
            where = "-" if nearest is None else f"{nearest[0]:.2f} spacings from one sent back " \
                                                f"by the {nearest[1]}"
            print(f"{half}  {name}  max {max_percent:.3f}%  {sent} sent back  max at {where}",
                  flush=True)
            if nearest is not None and nearest[0] <= args.within:
                counts[key][nearest[1]] += 1
    print(f"\nOutputs whose max lies within {args.within:g} spacings of a vertex sent back:")
    for (half, family), c in sorted(counts.items()):
        print(f"  {half:10s} {family:8s} {c['intersection guard'] + c['cleanup']} of "
              f"{c['outputs']} (intersection guard {c['intersection guard']}, cleanup "
              f"{c['cleanup']})")


if __name__ == "__main__":
    main()
