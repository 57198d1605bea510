#!/usr/bin/env python3
"""Would a per-feature gate tell a designed blend from a sampler's chamfer? Reads the
feature lines and the source lines of bench/study/evidence_study.py for one half and prints,
for each gate and bound, the harm the kept features it would send back had (summed change
of their moved vertices' distance to the reference, in sample spacings, where positive) and
the gain it would give up (where negative), with the cases that weigh most.

  bench/study/evidence_study.py --half tuning --out F.jsonl
  bench/study/evidence_study.py --half tuning --sources --out S.jsonl
  bench/study/blend_gates.py F.jsonl S.jsonl

Gates: a feature's median roundness (a moved edge vertex's farther source: its distance
from its own plane over its distance from the target; a sample on its plane reads 0, a
sample on a circular blend or a bevel up to sin 45 degrees), and its share of blend-like
sources (at least 0.15 spacings off their own plane and at least 1.5 times as far from the
other flank's plane: absorbed by one flank's region, as a fillet's samples are).
"""
import collections
import json
import sys


def weigh(rows, gate):
    harm = gain = 0.0
    harmed, gained = collections.Counter(), collections.Counter()
    for case, value, change in rows:
        if not gate(value):
            continue
        if change > 0:
            harm += change
            harmed[case] += change
        else:
            gain -= change
            gained[case] -= change
    top = lambda counter: ", ".join(f"{c} {v:.0f}" for c, v in counter.most_common(3))
    return f"sends back harm {harm:.0f}, gives up gain {gain:.0f} (gain: {top(gained)}; harm: {top(harmed)})"


def main():
    features_path, sources_path = sys.argv[1:3]
    features = {}
    for line in open(features_path):
        f = json.loads(line)
        if not f["weak"] and not f["corner"] and f["moved"] > 0:
            features[(f["case"], f["feature"])] = f
    sources = collections.defaultdict(list)
    for line in open(sources_path):
        s = json.loads(line)
        if (s["case"], s["feature"]) in features:
            sources[(s["case"], s["feature"])].append((s["off_plane"], s["off_other_plane"]))
    rows = [(k[0], f["round_q50"], f["harm_sum"]) for k, f in features.items()]
    for bound in (0.3, 0.4, 0.5, 0.6):
        print(f"median roundness > {bound}: " + weigh(rows, lambda v, b=bound: v > b))
    shares = []
    for k, f in features.items():
        own = sources.get(k, [])
        blend = sum(1 for a, b in own if a >= 0.15 and b >= 1.5 * a) / len(own) if own else 0.0
        shares.append((k[0], blend, f["harm_sum"]))
    for bound in (0.2, 0.4, 0.5, 0.6, 0.7):
        print(f"blend-like share >= {bound}: " + weigh(shares, lambda v, b=bound: v >= b))


if __name__ == "__main__":
    main()
