#!/usr/bin/env python3
"""Runs evidence-study over the quality benchmark's cached inputs of one half and writes
one JSON line per feature (bench/study/evidence_study.cpp), for choosing the evidence
guard's rule on the tuning half and checking it on the validation half.

  bench/study/evidence_study.py --build BUILD --half tuning|validation --out FILE.jsonl

With --vertices, one line per moved vertex of a kept feature instead; with --sources, one
line per (feature, source vertex) pair: how far the source lies from its own plane and from
the other sources' planes (where a feature's far samples come from).
"""
import argparse
import concurrent.futures
import glob
import json
import os
import re
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))


# Seeds for measuring again an output a change seems to make worse: mesh-distance's default
# (None, MeshLab's own) and two more. A Montecarlo sampling finds a narrow peak of the distance
# by chance, and another output's face areas move every sample.
SEEDS = (None, 1, 2)


def metro(tool, mesh, reference, samples=100000, seeds=(None,)):
    """Symmetric max and RMS (% of the reference's diagonal) by `tool` (mesh-distance
    --sampling meshlab, `samples` a side), as the benchmark reads them; with several seeds,
    the largest of each."""
    figures = []
    for seed in seeds:
        out = subprocess.run([str(tool), "--json", "--sampling", "meshlab", "--samples",
                              str(samples), str(mesh), str(reference)] +
                             ([] if seed is None else ["--seed", str(seed)]),
                             capture_output=True, text=True, check=True)
        d = json.loads(out.stdout)["symmetric"]
        figures.append((d["max_percent"], d["rms_percent"]))
    return max(f[0] for f in figures), max(f[1] for f in figures)


def references(cache, shared):
    refs = {}
    for p in glob.glob(os.path.join(cache, "generated", "*_reference.ply")):
        refs[os.path.basename(p)[:-len("_reference.ply")]] = p
    for d in (shared, os.path.join(SOURCE, "test_meshes", "real")):
        for p in glob.glob(os.path.join(d, "*")):
            stem, ext = os.path.splitext(os.path.basename(p))
            if ext.lower() in (".off", ".obj", ".stl", ".ply"):
                refs[stem] = p
    return refs


def cached_inputs(cache, match=""):
    """The benchmark's cached inputs (BUILD/quality-cache/inputs, without UnSharp Mask's outputs,
    then its own marching cubes, generated/*_mc1.ply) whose file name `match` finds."""
    inputs = sorted(p for p in glob.glob(os.path.join(cache, "inputs", "*.ply"))
                    if "unsharp" not in p)
    inputs += sorted(glob.glob(os.path.join(cache, "generated", "*_mc1.ply")))
    return [p for p in inputs if re.search(match, os.path.basename(p))]


def model_of(path):
    """The reference a cached input was made from (references()' key)."""
    name = os.path.basename(path)
    return name.split("__")[0] if "__" in name else name[:-len("_mc1.ply")]


def family_of(path):
    """The sampler family a cached input was made by (`umr`, `vdbproj`, `scan`, ...; `mc` for the
    benchmark's own marching cubes)."""
    name = os.path.basename(path)
    return name.split("__")[1].split("_")[0] if "__" in name else "mc"


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--build", default=os.path.join(SOURCE, "build"))
    ap.add_argument("--shared", default=os.path.join(SOURCE, "..", "shared", "meshes"))
    ap.add_argument("--half", choices=("tuning", "validation"), required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--jobs", type=int, default=2)
    detail = ap.add_mutually_exclusive_group()
    detail.add_argument("--vertices", action="store_true",
                        help="one line per moved vertex of a kept feature")
    detail.add_argument("--sources", action="store_true",
                        help="one line per (feature, source vertex) pair")
    args = ap.parse_args()
    cache = os.path.join(args.build, "quality-cache")
    split = json.load(open(os.path.join(SOURCE, "bench", "quality", "split.json")))
    names = set(split[args.half]) - {"chamfer-cube"}
    refs = references(cache, args.shared)
    tool = os.path.join(args.build, "bench", "study", "evidence-study")
    jobs = []
    for name in sorted(names):
        if name not in refs:
            continue
        jobs.append((refs[name], refs[name], f"{name}__asis"))
        mc = os.path.join(cache, "generated", f"{name}_mc1.ply")
        if os.path.exists(mc):
            jobs.append((mc, refs[name], f"{name}__mc_1pct"))
        for p in sorted(glob.glob(os.path.join(cache, "inputs", f"{name}__*.ply"))):
            key = os.path.basename(p)[:-4]
            if key.count("__") == 1:  # not a peer's output
                jobs.append((p, refs[name], key))

    def run(job):
        extra = ["--vertices"] if args.vertices else ["--sources"] if args.sources else []
        p = subprocess.run([tool, *job, *extra], capture_output=True, text=True)
        return p.stdout
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool, open(args.out, "w") as out:
        for text in pool.map(run, jobs):
            out.write(text)
    print(f"{len(jobs)} cases -> {args.out}")


if __name__ == "__main__":
    main()
