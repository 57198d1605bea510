#!/usr/bin/env python3
"""The figure of docs/plugin.md's colour legend: Detect and Sharpen --colorize, by verdict.

Runs the CLI twice on one input, with --detect-only and with --colorize, and draws both
meshes' face colours side by side, flat shaded, from the same view. The default input is the
generated finished_hexprism (designed bevels and fillets) by marching cubes at 1% of its
diagonal, where the default leaves features for several reasons.

Run: /usr/bin/python3 bench/study/verdict_figure.py [--build build] [--input MESH]
     [--out docs/images/verdict-colors.png]
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


def shaded(mesh, light):
    """Face colours darkened by the angle to the light, as a flat-shaded view shows them."""
    v, f = mesh["vertices"], mesh["faces"]
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-30)
    lit = 0.45 + 0.55 * np.clip(n @ light, 0, 1)
    rgb = np.stack([mesh["face_red"], mesh["face_green"], mesh["face_blue"]], axis=1) / 255.0
    return np.clip(rgb * lit[:, None], 0, 1)


def draw(ax, mesh, title, elev, azim):
    v, f = mesh["vertices"], mesh["faces"]
    el, az = np.radians(elev), np.radians(azim)
    towards_eye = np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])
    light = towards_eye + np.array([0.0, 0.0, 0.4])
    light /= np.linalg.norm(light)
    colours = shaded(mesh, light)
    ax.add_collection3d(Poly3DCollection(v[f], facecolors=colours, edgecolors=colours,
                                         linewidths=0.3))
    lo, hi = v.min(axis=0), v.max(axis=0)
    centre, half = (lo + hi) / 2, (hi - lo).max() / 2
    frame(ax, centre, half, 1.5, elev, azim, title, 11)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--input", help="a mesh (default: finished_hexprism at 1%% cells)")
    parser.add_argument("--out", default=str(ROOT / "docs" / "images" / "verdict-colors.png"))
    parser.add_argument("--elev", type=float, default=24)
    parser.add_argument("--azim", type=float, default=-100)
    args = parser.parse_args()
    build = pathlib.Path(args.build)
    with tempfile.TemporaryDirectory() as tmp:
        detected, sharpened = pathlib.Path(tmp) / "detect.ply", pathlib.Path(tmp) / "sharp.ply"
        source = args.input
        if source is None:
            subprocess.run([str(build / "test_meshes" / "generate-test-meshes"), tmp, "--cells",
                            "0.01", "--shapes", "finished_hexprism"], check=True,
                           capture_output=True)
            source = str(pathlib.Path(tmp) / "finished_hexprism_mc1.ply")
        for out, flags in ((detected, ["--detect-only"]), (sharpened, ["--colorize"])):
            run = subprocess.run([str(build / "apps" / "edge-sharpener"), source, str(out),
                                  *flags], check=True, capture_output=True, text=True)
            print(run.stdout.splitlines()[1])
        fig = plt.figure(figsize=(11, 5.4), dpi=110)
        for i, (path, title) in enumerate(((detected, "Detect: the input, by verdict"),
                                           (sharpened, "Sharpen --colorize"))):
            draw(fig.add_subplot(1, 2, i + 1, projection="3d"), read_ply(path), title,
                 args.elev, args.azim)
        fig.subplots_adjust(left=0, right=1, bottom=0, top=0.95, wspace=0)
        fig.savefig(args.out)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
