#!/usr/bin/env python3
"""Corners where four or more faces meet, against the information limit (issue 60, point 2).

For every generated shape with a reference vertex in four or more distinct face planes (the
pyramid's apex), and every grid sampler at 1% and 0.5% cells: the max error within --radius
cells of that corner (both ways, as bench/study/corner_figure.py measures it) of the input, of
the input sharpened by the default method, and of dual contouring with exact Hermite data on
a grid of the same cell size (the information limit), in cells. The issue's target: the
default within 2x the limit at 0.5%.

Inputs: the project's marching cubes (generate-test-meshes, made here), and MeshLab's Uniform
Mesh Resampling, OpenVDB and OpenVDB projected from the quality benchmark's cache
(bench-quality.sh makes them; a missing one is skipped).

Run: /usr/bin/python3 bench/study/corner_table.py [--build build] [--radius 4]
Needs Debian's python3-numpy and python3-matplotlib (corner_figure.py's imports).
"""
import argparse
import pathlib
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from corner_figure import (ROOT, default_corner, measure, plane_points,  # noqa: E402
                           planes_at, triangles_near)
from ply import read_ply  # noqa: E402  (python/tests, on corner_figure's path)

# The sharp shapes; a designed bevel's or fillet's facets would count as planes.
SHAPES = ["cube", "cross_prism", "cylinder_block", "lblock", "lblock_tilted", "pyramid", "wedge"]
FAMILIES = [("mc", "own marching cubes"), ("umr", "MeshLab UMR"), ("vdb", "OpenVDB"),
            ("vdbproj", "OpenVDB projected")]


def run(cmd):
    subprocess.run([str(c) for c in cmd], check=True, capture_output=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--radius", type=float, default=4, help="cells around the corner")
    args = parser.parse_args()
    build = pathlib.Path(args.build)
    cache = build / "quality-cache" / "inputs"
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        run([build / "test_meshes" / "generate-test-meshes", tmp, "--cells", "0.01", "0.005",
             "--shapes", *SHAPES])
        for shape in SHAPES:
            ref = read_ply(tmp / f"{shape}_reference.ply")
            index = default_corner(ref)
            if planes_at(ref, index) < 4:
                continue
            rv = ref["vertices"].astype(float)
            corner = rv[index]
            diagonal = np.linalg.norm(rv.max(axis=0) - rv.min(axis=0))
            for pct in ("1", "0.5"):
                cell = float(pct) / 100 * diagonal
                r, margin = args.radius * cell, 2 * cell
                ref_tris = triangles_near(ref, corner, r + margin)
                ref_points = plane_points(ref_tris, corner, r, 0.1 * cell)
                limit = tmp / f"{shape}_dc{pct}.ply"
                run([build / "test_meshes" / "dual-contour", shape, pct, limit])

                def worst(path):
                    return measure(read_ply(path), ref_tris, ref_points, corner, r, margin)[2]

                limit_cells = worst(limit) / cell
                for family, title in FAMILIES:
                    source = (tmp / f"{shape}_mc{pct}.ply" if family == "mc"
                              else cache / f"{shape}__{family}_{pct}pct.ply")
                    if not source.exists():
                        continue
                    sharp = tmp / f"{shape}_{family}_{pct}_sharp.ply"
                    run([build / "apps" / "edge-sharpener", source, sharp, "-q"])
                    before, after = worst(source) / cell, worst(sharp) / cell
                    rows.append((shape, pct, title, before, after, limit_cells))
    print(f"Max error within {args.radius:g} cells of each corner of four or more faces, "
          "in cells of the sampler's grid")
    print()
    print("| shape | cells | sampler | input | default | limit | within 2x the limit |")
    print("|---|---|---|---|---|---|---|")
    for shape, pct, title, before, after, limit in rows:
        met = "yes" if after <= 2 * limit else "no"
        print(f"| {shape} | {pct}% | {title} | {before:.3f} | {after:.3f} | {limit:.4f} | {met} |")


if __name__ == "__main__":
    main()
