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

from evidence_study import SEEDS, cached_inputs, metro, model_of, references

ROOT = pathlib.Path(__file__).resolve().parents[2]


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
            i, x, y = metro(distance, path, ref), metro(distance, a, ref), metro(distance, b, ref)
            if y[0] > 0.98 * i[0] or y[1] > 0.98 * i[1] or y[0] > 1.02 * x[0]:
                i, x, y = (metro(distance, m, ref, 10**6) for m in (path, a, b))
            if y[0] > i[0] or y[1] > i[1] or y[0] > 1.02 * x[0]:
                i, x, y = (metro(distance, m, ref, 10**6, SEEDS) for m in (path, a, b))
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
