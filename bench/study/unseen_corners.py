#!/usr/bin/env python3
"""Corners of five to eight faces on shapes neither benchmark half has, before and after a change.

Writes n-gonal pyramids and bipyramids (five to eight faces at an apex, one acute tip), turned off
the grid, remeshes each with OpenVDB (bench/samplers/vdb-remesh, plain and --project as Blender's
voxel remesh) at 0.5% and 1% of the diagonal, sharpens every input with two builds' default
method, and prints the input's and both outputs' max and RMS (% of the diagonal; mesh-distance
--sampling meshlab, 100,000 samples a side, both ways as the benchmark reads them) with whether
the outputs differ (where the after's max is 2% above the before's or the input's, all three
measured again at a million samples, the largest of three seeds). No threshold is chosen on it:
it says whether a change found on the benchmark's corners carries to corners nobody tuned on.

Run: /usr/bin/python3 bench/study/unseen_corners.py BEFORE/apps/edge-sharpener [--build build]
(AFTER is --build's edge-sharpener.) Needs Debian's python3-numpy and an OpenVDB build.
"""
import argparse
import filecmp
import math
import pathlib
import struct
import subprocess
import tempfile

import numpy as np

from evidence_study import SEEDS, metro

ROOT = pathlib.Path(__file__).resolve().parents[2]

# name -> (faces around the apex, circumradius, height, bipyramid)
SHAPES = {
    "pyramid5": (5, 0.8, 1.0, False),
    "pyramid5_tall": (5, 0.6, 1.6, False),
    "pyramid7": (7, 0.8, 1.3, False),
    "pyramid8": (8, 0.8, 0.9, False),
    "bipyramid5": (5, 0.8, 0.8, True),
    "bipyramid6": (6, 0.7, 1.0, True),
}
TURN_AXIS, TURN_ANGLE = (1.0, 3.0, 2.0), 0.7
VOXELS = (0.005, 0.01)


def turn(axis, angle):
    a = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


def pyramid(n, radius, height, bipyramid):
    """Vertices and outward triangles: n rim vertices, the apex, the base's centre (or a
    second apex below)."""
    verts = [[radius * math.cos(2 * math.pi * i / n), radius * math.sin(2 * math.pi * i / n), 0]
             for i in range(n)]
    verts += [[0, 0, height], [0, 0, -height if bipyramid else 0]]
    top, bottom = n, n + 1
    faces = []
    for i in range(n):
        j = (i + 1) % n
        faces += [(i, j, top), (j, i, bottom)]
    return np.array(verts) @ turn(TURN_AXIS, TURN_ANGLE).T, faces


def write_ply(path, verts, faces):
    with open(path, "wb") as f:
        f.write((f"ply\nformat binary_little_endian 1.0\nelement vertex {len(verts)}\n"
                 "property float x\nproperty float y\nproperty float z\n"
                 f"element face {len(faces)}\nproperty list uchar int vertex_indices\n"
                 "end_header\n").encode())
        f.write(np.asarray(verts, "<f4").tobytes())
        for t in faces:
            f.write(struct.pack("<B3i", 3, *t))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before", help="the other build's edge-sharpener")
    parser.add_argument("--build", default=str(ROOT / "build"))
    args = parser.parse_args()
    build = pathlib.Path(args.build)
    after, meter = build / "apps" / "edge-sharpener", build / "apps" / "mesh-distance"
    remesh = build / "bench" / "samplers" / "vdb-remesh"
    changed = worse = total = 0
    print("| input | input max / RMS | before | after | |\n|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        for name, params in SHAPES.items():
            reference = tmp / f"{name}_reference.ply"
            write_ply(reference, *pyramid(*params))
            for voxel in VOXELS:
                for project in (False, True):
                    tag = f"{name} {'vdbproj' if project else 'vdb'} {voxel * 100:g}%"
                    mesh = tmp / "in.ply"
                    subprocess.run([str(remesh), str(reference), str(mesh), "--voxel-fraction",
                                    str(voxel)] + (["--project"] if project else []),
                                   check=True, capture_output=True)
                    outs = []
                    for i, tool in enumerate((args.before, after)):
                        outs.append(tmp / f"out{i}.ply")
                        subprocess.run([str(tool), str(mesh), str(outs[-1]), "-q"], check=True)
                    same = filecmp.cmp(outs[0], outs[1], shallow=False)
                    base = metro(meter, mesh, reference)
                    before = metro(meter, outs[0], reference)
                    now = before if same else metro(meter, outs[1], reference)
                    if not same and (now[0] > 1.02 * before[0] or now[0] > 1.02 * base[0]):
                        base, before, now = (metro(meter, m, reference, 10**6, SEEDS)
                                             for m in (mesh, outs[0], outs[1]))
                    is_worse = now[0] > base[0] * 1.02 or now[1] > base[1] * 1.01
                    total += 1
                    changed += not same
                    worse += is_worse
                    print(f"| {tag} | {base[0]:.3f} / {base[1]:.4f} | {before[0]:.3f} / "
                          f"{before[1]:.4f} | {now[0]:.3f} / {now[1]:.4f} | "
                          f"{'' if same else 'changed'}{' worse' if is_worse else ''} |")
    print(f"\n{changed} of {total} outputs changed; {worse} worse than their input after")


if __name__ == "__main__":
    main()
