#!/usr/bin/env python3
"""A convex corner three ways: the input, the default's result, and the information limit.

Draws one corner of a generated shape three times, from the same view, cropped to the faces
with all three vertices within --radius cells of it: the project's marching-cubes mesh at 1%
of the diagonal, that mesh sharpened by the default method (edge-sharpener -q), and dual
contouring with exact Hermite data on the same grid (dual-contour SHAPE 1), the information
limit. Faces are coloured by the largest distance of 15 points on them to the exact reference
surface, in cells (one colour bar, 0 to 1 cell). Each title gives the maximum error inside the
ball both ways (the mesh's points to the reference, the reference's points, its sharp corner
and edges too, to the mesh), in % of the diagonal and in cells; the three are also printed.

Default corner: the reference vertex where the most distinct face planes meet (ties: the
largest z, then y, then x), the apex of the pyramid. The view looks down the corner's outward
direction (the mean of its planes' normals), turned 20 degrees around z, from at most 35
degrees above the horizon (--elev, --azim to choose).

Run: /usr/bin/python3 bench/study/corner_figure.py [--build build] [--shape pyramid|cube]
     [--corner X,Y,Z] [--radius 4] [--elev E --azim A] [--out docs/images/corner-limit.png]
Needs Debian's python3-numpy and python3-matplotlib.
"""
import argparse
import pathlib
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "python" / "tests"))
from ply import read_ply  # noqa: E402
from figure_axes import frame  # noqa: E402


def unit(x):
    return x / np.maximum(np.linalg.norm(x, axis=-1, keepdims=True), 1e-30)


def normals(tris):
    return unit(np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0]))


def distance(points, tris):
    """Each point's distance to the nearest of the triangles (m, 3, 3), brute force."""
    a, b, c = (tris[:, i].astype(float) for i in range(3))
    n = np.cross(b - a, c - a)
    ok = np.linalg.norm(n, axis=1) > 1e-20  # degenerate triangles: by their edges only
    n = unit(n)
    out = np.empty(len(points))
    for s in range(0, len(points), 256):
        q = points[s:s + 256, None, :]
        plane = ((q - a) * n).sum(-1)
        foot, inside, seg = q - plane[..., None] * n, ok[None, :], np.inf
        for e0, e1 in ((a, b), (b, c), (c, a)):
            inside = inside & ((np.cross(e1 - e0, foot - e0) * n).sum(-1) >= 0)
            t = np.clip(((q - e0) * (e1 - e0)).sum(-1) / np.maximum(
                ((e1 - e0) ** 2).sum(-1), 1e-30), 0, 1)
            seg = np.minimum(seg, np.linalg.norm(q - e0 - t[..., None] * (e1 - e0), axis=-1))
        out[s:s + 256] = np.where(inside, np.abs(plane), seg).min(axis=1)
    return out


def face_points(tris, k=4):
    """A barycentric grid of (k+1)(k+2)/2 points on each triangle: (m, points, 3)."""
    w = np.array([(i, j, k - i - j) for i in range(k + 1) for j in range(k + 1 - i)]) / k
    return np.einsum("pi,mid->mpd", w, tris.astype(float))


def plane_points(tris, corner, r, h):
    """Points every h on the reference triangles and their edges within r of the corner."""
    out = []
    for a, b, c in tris.astype(float):
        n, u = unit(np.cross(b - a, c - a)), unit(b - a)
        s = np.arange(-r, r + h, h)
        foot = corner - np.dot(corner - a, n) * n
        grid = (foot + s[:, None, None] * u + s[None, :, None] * np.cross(n, u)).reshape(-1, 3)
        inside = np.ones(len(grid), bool)
        for e0, e1 in ((a, b), (b, c), (c, a)):
            inside &= np.cross(e1 - e0, grid - e0) @ n >= -1e-12
            t = np.linspace(0, 1, int(np.linalg.norm(e1 - e0) / h) + 2)
            out.append(e0 + t[:, None] * (e1 - e0))
        out.append(grid[inside])
    p = np.concatenate(out)
    return p[np.linalg.norm(p - corner, axis=1) <= r]


def planes_at(ref, i):
    """How many distinct face planes meet at reference vertex i."""
    v, f = ref["vertices"].astype(float), ref["faces"]
    return len(np.unique(np.round(normals(v[f[(f == i).any(axis=1)]]), 6), axis=0))


def default_corner(ref):
    """The index of the reference vertex in the most distinct face planes (ties: largest z,
    y, x)."""
    v = ref["vertices"].astype(float)
    return max(range(len(v)), key=lambda i: (planes_at(ref, i), *v[i][::-1]))


def triangles_near(ref, corner, reach):
    """The reference's triangles (m, 3, 3) within `reach` of the point `corner`."""
    tris = ref["vertices"].astype(float)[ref["faces"]]
    return np.array([t for t in tris if distance(corner[None], t[None])[0] <= reach])


def measure(mesh, ref_tris, ref_points, corner, r, margin):
    """The cropped faces, their colours' distances, and the two-sided max within r."""
    tris = mesh["vertices"].astype(float)[mesh["faces"]]
    crop = np.linalg.norm(tris - corner, axis=2).max(axis=1) <= r
    pts = face_points(tris[crop])
    d = distance(pts.reshape(-1, 3), ref_tris).reshape(pts.shape[:2])
    near = np.linalg.norm(tris - corner, axis=2).min(axis=1) <= r + margin
    back = distance(ref_points, tris[near])  # the reference's points, the corner's too
    return tris[crop], d.max(axis=1), max(d.max(), back.max())


def draw(ax, tris, values, cell, cmap, centre, half, elev, azim, title):
    el, az = np.radians(elev + 25), np.radians(azim - 50)  # above and left of the eye
    light = np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])
    lit = 0.6 + 0.4 * np.abs(normals(tris) @ light)
    colours = cmap(np.clip(values / cell, 0, 1))[:, :3] * lit[:, None]
    ax.add_collection3d(Poly3DCollection(tris, facecolors=colours, edgecolors=(0, 0, 0, 0.25),
                                         linewidths=0.25))
    frame(ax, centre, half, 1.1, elev, azim, title, 12)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--shape", default="pyramid", help="a generated shape (pyramid, cube)")
    parser.add_argument("--corner", help="X,Y,Z (default: the vertex in the most planes)")
    parser.add_argument("--radius", type=float, default=4, help="crop radius in cells")
    parser.add_argument("--elev", type=float, help="view elevation (default: the corner's, <= 35)")
    parser.add_argument("--azim", type=float, help="view azimuth (default: the corner's + 20)")
    parser.add_argument("--out", default=str(ROOT / "docs" / "images" / "corner-limit.png"))
    args = parser.parse_args()
    build = pathlib.Path(args.build)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        subprocess.run([str(build / "test_meshes" / "generate-test-meshes"), str(tmp), "--cells",
                        "0.01", "--shapes", args.shape], check=True, capture_output=True)
        mc, sharp, dc = tmp / f"{args.shape}_mc1.ply", tmp / "sharp.ply", tmp / "dc.ply"
        subprocess.run([str(build / "apps" / "edge-sharpener"), str(mc), str(sharp), "-q"],
                       check=True, capture_output=True)
        subprocess.run([str(build / "test_meshes" / "dual-contour"), args.shape, "1", str(dc)],
                       check=True, capture_output=True)
        ref = read_ply(tmp / f"{args.shape}_reference.ply")
        meshes = [read_ply(p) for p in (mc, sharp, dc)]
    rv = ref["vertices"].astype(float)
    diagonal = np.linalg.norm(rv.max(axis=0) - rv.min(axis=0))
    cell, corner = 0.01 * diagonal, rv[default_corner(ref)]
    corner = np.array([float(x) for x in args.corner.split(",")]) if args.corner else corner
    r, margin = args.radius * cell, 2 * cell
    ref_tris = triangles_near(ref, corner, r + margin)
    if len(ref_tris) == 0:
        sys.exit(f"no reference face within {args.radius + 2} cells of {corner}")
    out = unit(np.unique(np.round(normals(ref_tris), 6), axis=0).mean(axis=0))
    elev = min(np.degrees(np.arcsin(out[2])), 35) if args.elev is None else args.elev
    azim = np.degrees(np.arctan2(out[1], out[0])) if np.hypot(*out[:2]) > 1e-6 else 0
    azim = azim + 20 if args.azim is None else args.azim
    ref_points = plane_points(ref_tris, corner, r, 0.1 * cell)
    lo, hi = ref_points.min(axis=0), ref_points.max(axis=0)  # the crop's box, the same view
    cmap, centre, half = plt.get_cmap("YlOrRd"), (lo + hi) / 2, 0.52 * (hi - lo).max()
    fig = plt.figure(figsize=(15, 5.5), dpi=100)
    names = ("Input: marching cubes, 1% cells", "Sharpened: edge-sharpener (default)",
             "Limit: dual contouring, exact Hermite data")
    for i, (mesh, name) in enumerate(zip(meshes, names)):
        tris, values, worst = measure(mesh, ref_tris, ref_points, corner, r, margin)
        pct, cells = 100 * worst / diagonal, worst / cell
        print(f"{name}: max error within {args.radius:g} cells of the corner "
              f"{pct:.4f}% of the diagonal, {cells:.4f} cells")
        draw(fig.add_subplot(1, 3, i + 1, projection="3d"), tris, values, cell, cmap, centre, half,
             elev, azim, f"{name}\nmax error {pct:.2f}% ({cells:.2f} cells)")
    fig.subplots_adjust(left=0, right=0.93, bottom=0, top=0.86, wspace=0)
    bar = fig.colorbar(plt.cm.ScalarMappable(norm=plt.Normalize(0, 1), cmap=cmap),
                       cax=fig.add_axes((0.94, 0.15, 0.012, 0.65)))
    bar.set_label("distance to the exact surface [cells]", fontsize=11)
    fig.suptitle(f"{args.shape}: the corner at ({', '.join(f'{x:g}' for x in corner)}), "
                 f"{args.radius:g} cells around it", fontsize=13)
    fig.savefig(args.out)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
