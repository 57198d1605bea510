#!/usr/bin/env python3
"""Corners where four or more faces meet, against the information limit (issue 60, point 2).

For every generated shape with reference vertices in four or more distinct face planes (the
pyramid's apex, the octahedron's six corners, the hexagonal pyramid's apex), and every grid
sampler at 1% and 0.5% cells: the max error within --radius cells of those corners (the worst
of them) (both ways, as bench/study/corner_figure.py measures it) of the input, of
the input sharpened by the default method, and of dual contouring with exact Hermite data on
a grid of the same cell size (the information limit), in cells. The issue's target: the
default within 2x the limit at 0.5%.

Inputs: the project's marching cubes (generate-test-meshes, made here), and MeshLab's Uniform
Mesh Resampling, OpenVDB and OpenVDB projected from the quality benchmark's cache
(bench-quality.sh makes them; a missing one is skipped).

Run: /usr/bin/python3 bench/study/corner_table.py [--build build] [--radius 4]
     [--sharpener PATH]   (another build's edge-sharpener, for a before/after reading)
Needs Debian's python3-numpy and python3-matplotlib (corner_figure.py's imports).
"""
import argparse
import pathlib
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from corner_figure import (ROOT, measure, plane_points,  # noqa: E402
                           planes_at, triangles_near)
from ply import read_ply  # noqa: E402  (python/tests, on corner_figure's path)

# The sharp shapes; a designed bevel's or fillet's facets would count as planes.
SHAPES = ["cube", "cross_prism", "cylinder_block", "lblock", "lblock_tilted", "pyramid", "wedge",
          "octahedron", "hexagonal_pyramid"]
FAMILIES = [("mc", "own marching cubes"), ("umr", "MeshLab UMR"), ("vdb", "OpenVDB"),
            ("vdbproj", "OpenVDB projected")]


def run(cmd):
    subprocess.run([str(c) for c in cmd], check=True, capture_output=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--radius", type=float, default=4, help="cells around the corner")
    parser.add_argument("--sharpener", help="edge-sharpener to run (default: the build's)")
    args = parser.parse_args()
    build = pathlib.Path(args.build)
    sharpener = args.sharpener or build / "apps" / "edge-sharpener"
    cache = build / "quality-cache" / "inputs"
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        run([build / "test_meshes" / "generate-test-meshes", tmp, "--cells", "0.01", "0.005",
             "--shapes", *SHAPES])
        for shape in SHAPES:
            ref = read_ply(tmp / f"{shape}_reference.ply")
            rv = ref["vertices"].astype(float)
            corners = [rv[i] for i in range(len(rv)) if planes_at(ref, i) >= 4]
            if not corners:
                continue
            diagonal = np.linalg.norm(rv.max(axis=0) - rv.min(axis=0))
            for pct in ("1", "0.5"):
                cell = float(pct) / 100 * diagonal
                r, margin = args.radius * cell, 2 * cell
                near = []
                for corner in corners:
                    ref_tris = triangles_near(ref, corner, r + margin)
                    near.append((corner, ref_tris, plane_points(ref_tris, corner, r, 0.1 * cell)))
                limit = tmp / f"{shape}_dc{pct}.ply"
                run([build / "test_meshes" / "dual-contour", shape, pct, limit])

                def worst(path):
                    mesh = read_ply(path)
                    return max(measure(mesh, tris, points, corner, r, margin)[2]
                               for corner, tris, points in near)

                limit_cells = worst(limit) / cell
                for family, title in FAMILIES:
                    source = (tmp / f"{shape}_mc{pct}.ply" if family == "mc"
                              else cache / f"{shape}__{family}_{pct}pct.ply")
                    if not source.exists():
                        continue
                    sharp = tmp / f"{shape}_{family}_{pct}_sharp.ply"
                    run([sharpener, source, sharp, "-q"])
                    before, after = worst(source) / cell, worst(sharp) / cell
                    rows.append((shape, pct, title, before, after, limit_cells))
    print(f"Max error within {args.radius:g} cells of the corners of four or more faces (the "
          "worst corner of each shape), in cells of the sampler's grid")
    print()
    print("| shape | cells | sampler | input | default | limit | within 2x the limit |")
    print("|---|---|---|---|---|---|---|")
    for shape, pct, title, before, after, limit in rows:
        met = "yes" if after <= 2 * limit else "no"
        print(f"| {shape} | {pct}% | {title} | {before:.3f} | {after:.3f} | {limit:.4f} | {met} |")


if __name__ == "__main__":
    main()
