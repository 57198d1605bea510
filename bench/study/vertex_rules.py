#!/usr/bin/env python3
"""Compares per-vertex rules on the output of `evidence_study.py --vertices` (one line per
moved vertex of a kept feature): a rule sends the vertices it flags back to rest. Per rule, the
summed change of the kept vertices' distance to the reference per sampler family (sample
spacings; negative: nearer), and the inputs whose max error a rule would leave above the
input's by more than 2% (an estimate from the vertices and the benchmark's results JSON, the
input's own max or a kept vertex's distance, without the cleanup and the intersection guard
that follow: plate_holes at CSG 1% is listed by every rule but is not worse in the benchmark).

  bench/study/vertex_rules.py VERTICES.jsonl [--results RESULTS.json] [--cases]

Python 3 standard library only. How the long-move rule (feature_evidence.h:
vertexEvidenceIsWeak) was chosen on the tuning half.
"""
import argparse
import collections
import json
import os

SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def case_info(results):
    """Per case name (model__input_resolution): the input's max error (% of the diagonal),
    the default method's sample spacing and the reference's diagonal."""
    info = {}
    for c in results["cases"]:
        runs = [r for r in c["runs"] if r["method"] == "auto" and r.get("status") == "ok"]
        if not runs or "before" not in c or "sample_spacing" not in runs[0]:
            continue
        res = (c.get("resolution") or "").replace("%", "pct").replace(" ", "")
        for key in (f"{c['model']}__{c['input']}_{res}", f"{c['model']}__{c['input']}"):
            info[key] = (c["before"]["max"], runs[0]["sample_spacing"], c["before"]["diag"])
    return info


def rules():
    out = {"none": lambda r: False}
    for t in (0.2, 0.3, 0.4, 0.5):
        out[f"off-plane > {t}"] = lambda r, t=t: r["source_off_plane"] > t
    for t in (0.15, 0.2, 0.3):
        out[f"off-plane / reach > {t}"] = (
            lambda r, t=t: r["source_off_plane"] / max(r["reach"], 1e-9) > t)
    for t in (0.6, 0.8, 1.0):
        out[f"off-plane x move > {t}"] = lambda r, t=t: r["source_off_plane"] * r["length"] > t
    for t in (1.5, 2.0):
        out[f"move > {t} and off-plane > 0.3"] = (
            lambda r, t=t: r["length"] > t and r["source_off_plane"] > 0.3)
    out["move > 2 and off-plane > 0.3, edges only (the rule)"] = (
        lambda r: not r["corner"] and r["length"] > 2 and r["source_off_plane"] > 0.3)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("vertices")
    ap.add_argument("--results",
                    default=os.path.join(SOURCE, "build", "quality-cache", "results.json"))
    ap.add_argument("--cases", action="store_true", help="list the inputs left worse")
    args = ap.parse_args()
    rows = [json.loads(line) for line in open(args.vertices)]
    info = case_info(json.load(open(args.results)))
    cases = collections.defaultdict(list)
    for r in rows:
        cases[r["case"]].append(r)
    family = lambda name: name.split("__")[1].split("_")[0] if "__" in name else name
    for name, rule in rules().items():
        change = collections.defaultdict(float)
        worse = []
        for case, rs in cases.items():
            for r in rs:
                if not rule(r):
                    change[family(case)] += r["after"] - r["before"]
            if case not in info:
                continue
            before, spacing, diag = info[case]
            kept = [100 * spacing / diag * (r["before"] if rule(r) else r["after"]) for r in rs]
            if max([before] + kept) > 1.02 * before:
                worse.append(case)
        flagged = sum(rule(r) for r in rows)
        print(f"{name:52s} flags {flagged:6d}  "
              + " ".join(f"{f} {v:.0f}" for f, v in sorted(change.items()))
              + f"  worse {len(worse)}")
        if args.cases and worse:
            print("    " + ", ".join(sorted(worse)))


if __name__ == "__main__":
    main()
