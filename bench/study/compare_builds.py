#!/usr/bin/env python3
"""Two builds' default outputs on the quality benchmark's cached inputs, compared.

Runs `edge-sharpener` of the build BEFORE and of the build AFTER on every input the benchmark
cached (BUILD/quality-cache/inputs, and its own marching cubes, generated/*_mc1.ply), byte-
compares the two outputs, and measures those that differ against their reference as the
benchmark does (mesh-distance --sampling meshlab, 100,000 samples a side; a million when an
output is within 2% of its input's figures, or its max 2% above the before's; the largest of
three seeds' figures when it is then worse than its input or still 2% above). Prints one line
per changed output: half, input, the input's / before's / after's max and RMS (% of the
diagonal), and whether the after is worse than its input (max up or RMS up) when the before was
not (NEWLY-WORSE).

Run: /usr/bin/python3 bench/study/compare_builds.py BEFORE/apps/edge-sharpener \\
         [--after AFTER] [--build build] [--shared ../shared/meshes] [--match REGEX]
(AFTER is --after, or --build's edge-sharpener; the cache is made by scripts/bench-quality.sh.)
"""
import argparse
import filecmp
import json
import os
import pathlib
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor

from evidence_study import cached_inputs, model_of, references

ROOT = pathlib.Path(__file__).resolve().parents[2]
SEEDS = (None, 1, 2)  # None: mesh-distance's default, MeshLab's own


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before", help="the other build's edge-sharpener")
    parser.add_argument("--build", default=str(ROOT / "build"))
    parser.add_argument("--after", help="the edge-sharpener to compare (default: --build's)")
    parser.add_argument("--shared", default=str(ROOT.parent / "shared" / "meshes"))
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--match", default="",
                        help="only the inputs whose file name this regular expression finds")
    args = parser.parse_args()
    build = pathlib.Path(args.build)
    cache = build / "quality-cache"
    after = pathlib.Path(args.after) if args.after else build / "apps" / "edge-sharpener"
    distance = build / "apps" / "mesh-distance"
    tuning = set(json.load(open(ROOT / "bench" / "quality" / "split.json"))["tuning"])
    inputs = cached_inputs(str(cache), args.match)
    refs = references(str(cache), args.shared)

    def measure(mesh, ref, samples=100000, seeds=(None,)):
        """Max and RMS (% of the diagonal); with several seeds, the largest of each."""
        figures = []
        for seed in seeds:
            out = subprocess.run([distance, "--json", "--sampling", "meshlab", "--samples",
                                  str(samples), mesh, ref] +
                                 ([] if seed is None else ["--seed", str(seed)]),
                                 capture_output=True, text=True, check=True)
            d = json.loads(out.stdout)["symmetric"]
            figures.append((d["max_percent"], d["rms_percent"]))
        return max(f[0] for f in figures), max(f[1] for f in figures)

    def compare(path, tmp):
        ref = refs.get(model_of(path))
        stem = os.path.join(tmp, os.path.basename(path))
        a, b = stem + ".before.ply", stem + ".after.ply"
        ra = subprocess.run([args.before, "-q", path, a], capture_output=True).returncode
        rb = subprocess.run([after, "-q", path, b], capture_output=True).returncode
        try:
            if ra or rb:
                return None if ra == rb else (path, f"exit {ra} before, {rb} after")
            if ref is None or filecmp.cmp(a, b, shallow=False):
                return None
            i, x, y = measure(path, ref), measure(a, ref), measure(b, ref)
            if y[0] > 0.98 * i[0] or y[1] > 0.98 * i[1] or y[0] > 1.02 * x[0]:
                i, x, y = measure(path, ref, 10**6), measure(a, ref, 10**6), measure(b, ref, 10**6)
            if y[0] > i[0] or y[1] > i[1] or y[0] > 1.02 * x[0]:
                # A Montecarlo sampling finds a narrow peak of the distance by chance, and
                # another output's face areas move every sample: the largest over three seeds.
                i, x, y = (measure(m, ref, 10**6, SEEDS) for m in (path, a, b))
            return path, i, x, y
        finally:
            for f in (a, b):
                if os.path.exists(f):
                    os.remove(f)

    with tempfile.TemporaryDirectory() as tmp, ThreadPoolExecutor(args.jobs) as pool:
        rows = [r for r in pool.map(lambda p: compare(p, tmp), inputs) if r]
    for row in rows:
        if isinstance(row[1], str):
            print(f"{os.path.basename(row[0])}: {row[1]}")
            continue
        path, i, x, y = row
        worse = lambda o: o[0] > i[0] or o[1] > i[1]  # noqa: E731
        flag = "NEWLY-WORSE" if worse(y) and not worse(x) else ("worse" if worse(y) else "")
        half = "tuning" if model_of(path) in tuning else "validation"
        print(f"{half:10} {os.path.basename(path)[:-4]:40} input {i[0]:.3f}/{i[1]:.4f} "
              f"before {x[0]:.3f}/{x[1]:.4f} after {y[0]:.3f}/{y[1]:.4f} {flag}")
    print(f"{len(rows)} of {len(inputs)} outputs changed")


if __name__ == "__main__":
    main()
