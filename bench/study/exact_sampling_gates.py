#!/usr/bin/env python3
"""Gates for "sampled exactly" (feature_evidence.h: sampledExactly) studied on one half's features.

  bench/study/exact_sampling_gates.py FEATURES.jsonl [--inputs DIR]

FEATURES.jsonl is evidence_study.py's output (one line per feature of every input of a half).
For each gate (a quantile of the edge features' "nine in ten within" distances, weighted by
their new vertices or not, against a bound in sample spacings) it lists the inputs the gate
would take for exact that the default's gate (the vertex-weighted median at 0.001) does not,
and what that would change: the features not already weak with half their samples farther
than 0.05 spacings from their planes (opt.onPlaneSpacings) would go back, giving up their
harm_sum (negative: they brought the vertices nearer the reference). With --inputs (the
quality cache's inputs; needs Debian's python3-open3d), it also prints, for each of those
inputs, the share of vertices with two coordinates shared by at least three other vertices
(a marching-cubes lattice puts every vertex on a grid edge).
"""
import argparse
import collections
import functools
import json
import os

DEFAULT = ("vertex-weighted median <= 0.001", 0.5, 0.001, True)
GATES = (
    ("vertex-weighted median <= 0.01", 0.5, 0.01, True),
    ("vertex-weighted lower quartile <= 0.001", 0.25, 0.001, True),
    ("vertex-weighted lower quartile <= 0.01", 0.25, 0.01, True),
    ("vertex-weighted third <= 0.01", 0.33, 0.01, True),
    ("median over features <= 0.01", 0.5, 0.01, False),
)
ON_PLANE_SPACINGS = 0.05


def quantile(features, q, weighted):
    pairs = sorted((f["off_plane_q90"], f["vertices"] if weighted else 1)
                   for f in features if not f["corner"] and f["moved"] > 0)
    if not pairs:
        return None
    total, acc = sum(w for _, w in pairs), 0
    for value, w in pairs:
        acc += w
        if acc >= q * total:
            return value
    return pairs[-1][0]


def exact(features, gate):
    _, q, bound, weighted = gate
    value = quantile(features, q, weighted)
    return value is not None and value <= bound


@functools.lru_cache(maxsize=None)  # an input flips under several gates
def lattice_share(path):
    import numpy as np
    import open3d as o3d
    v = np.asarray(o3d.io.read_triangle_mesh(path).vertices).astype(np.float32)
    shared = np.zeros(v.shape, bool)
    for axis in range(3):
        _, inverse, counts = np.unique(v[:, axis], return_inverse=True, return_counts=True)
        shared[:, axis] = counts[inverse] >= 4
    return float((shared.sum(axis=1) >= 2).mean())


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("features")
    ap.add_argument("--inputs", help="the quality cache's inputs directory")
    args = ap.parse_args()
    cases = collections.defaultdict(list)
    with open(args.features) as lines:
        for line in lines:
            f = json.loads(line)
            cases[f["case"]].append(f)
    for gate in GATES:
        gained = lost = 0.0
        flips = []
        for case, features in sorted(cases.items()):
            if "scan" in case or not exact(features, gate) or exact(features, DEFAULT):
                continue
            back = [f for f in features
                    if not f["weak"] and f["off_plane_q50"] > ON_PLANE_SPACINGS]
            harm = sum(f["harm_sum"] for f in back)
            gained, lost = gained + max(harm, 0), lost + max(-harm, 0)
            flips.append((case, harm))
        print(f"{gate[0]}: {len(flips)} inputs more taken for exact; their features going "
              f"back would gain {gained:.1f} and give up {lost:.1f} sample spacings "
              f"(net {gained - lost:+.1f})")
        for case, harm in flips:
            extra = ""
            if args.inputs:
                path = os.path.join(args.inputs, case + ".ply")
                if os.path.exists(path):
                    extra = f", lattice share {lattice_share(path):.2f}"
            print(f"    {case}: {harm:+.1f}{extra}")


if __name__ == "__main__":
    main()
