#!/usr/bin/env python3
"""How deep each restored edge's chamfer cuts: per feature the default keeps, the median distance
of its samples from its other flank's plane, in sample spacings (`evidence-study --sources`:
other_signed), beside what its moves did against the true shape (`evidence-study`: harm_sum,
per moved vertex; negative: nearer the reference). Prints one line per feature, shallowest
first: a designed fillet or bevel whose band is as deep as sampled sharp edges' chamfers is one
the mesh alone cannot tell from them.

Run: /usr/bin/python3 bench/study/chamfer_depth.py MESH... [--build build]
     [--shared ../shared/meshes]
A mesh is named REFERENCE__anything.ply (the quality benchmark's and the held-out checks'
naming); its reference is looked up by evidence_study.references.
"""
import argparse
import json
import os
import pathlib
import statistics
import subprocess
from collections import defaultdict

from evidence_study import references

ROOT = pathlib.Path(__file__).resolve().parents[2]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("meshes", nargs="+")
    ap.add_argument("--build", default=str(ROOT / "build"))
    ap.add_argument("--shared", default=str(ROOT.parent / "shared" / "meshes"))
    ap.add_argument("--min-samples", type=int, default=10,
                    help="leave out features with fewer source samples")
    args = ap.parse_args()
    study = os.path.join(args.build, "bench", "study", "evidence-study")

    refs = references(os.path.join(args.build, "quality-cache"), args.shared)

    def lines(*cmd):
        out = subprocess.run(cmd, capture_output=True, text=True).stdout
        return [json.loads(line) for line in out.splitlines() if line.startswith("{")]

    rows = []
    for mesh in args.meshes:
        name = os.path.basename(mesh)
        ref = refs.get(name.split("__")[0])
        if ref is None:
            print(f"# {name}: no reference found")
            continue
        features = {d["feature"]: d for d in lines(study, mesh, ref, name)
                    if "harm_sum" in d and not d["corner"] and not d["weak"]}
        depth = defaultdict(list)
        for d in lines(study, mesh, ref, name, "--sources"):
            depth[d["feature"]].append(abs(d["other_signed"]))
        for f, d in features.items():
            if len(depth[f]) < args.min_samples:
                continue
            rows.append((statistics.median(depth[f]), d["harm_sum"] / max(1, d["moved"]), name,
                         f, d["flank_angle_deg"], d["vertices"]))
    print("depth (spacings) | harm per moved vertex (spacings) | mesh | feature | flanks' angle "
          "(deg) | new vertices")
    for r in sorted(rows):
        print("%.2f | %+.3f | %s | %d | %.0f | %d" % r)


if __name__ == "__main__":
    main()
