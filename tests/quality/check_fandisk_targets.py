#!/usr/bin/env python3
"""Assertions on fandisk resampled by MeshLab's Uniform Mesh Resampling (results JSON of
run.py --models fandisk --inputs umr), at the default multiplier.

- No method comes out farther from the reference than its input (max and RMS, 1%).
- At 1% cells, the extended method reaches max x1.6 / RMS x3.2 (measured 0.493,
  x1.80 / x3.52), and the default (auto) the issue's target: max below 0.43% of the
  diagonal, the paper's own figure (measured 0.403, x2.20 / x3.57). Every step is
  deterministic (MeshLab's resampling, the sharpener, the fixed-seed distance), so the
  margin is not noise.
"""
import checks

TOL = 0.01
MULT = 2.0
# (variant, resolution): (max below this % of the diagonal, min max factor, min RMS factor)
TARGETS = {("extended", "1%"): (0.6, 1.6, 3.2), ("auto", "1%"): (0.43, 2.0, 3.2)}


def main():
    results = checks.load_results()
    failures, seen = [], set()
    for c in results["cases"]:
        if c["input"] != "umr" or "before" not in c:
            if c["input"] == "umr":  # MeshLab now and then writes no output: only 1% is needed
                print(f"  fandisk UMR {c['resolution']}: input not made: {c['make'].get('why')}")
            continue
        b = c["before"]
        for r in c["runs"]:
            if abs(r["multiplier"] - MULT) > 1e-9:
                continue
            tag = f"fandisk UMR {c['resolution']} {r['method']}"
            if r["status"] != "ok":
                failures.append(f"{tag}: {r['status']}: {r.get('why')}")
                continue
            a = r["after"]
            fmax, frms = b["max"] / a["max"], b["rms"] / a["rms"]
            print(f"  {tag:34s} max {b['max']:.4f} -> {a['max']:.4f} (x{fmax:.2f})  "
                  f"RMS {b['rms']:.5f} -> {a['rms']:.5f} (x{frms:.2f})")
            if a["max"] > b["max"] * (1 + TOL) or a["rms"] > b["rms"] * (1 + TOL):
                failures.append(f"{tag}: farther from the reference than its input")
            target = TARGETS.get((r["method"], c["resolution"]))
            if target:
                seen.add((r["method"], c["resolution"]))
                below, need_max, need_rms = target
                if not (a["max"] < below and fmax >= need_max and frms >= need_rms):
                    failures.append(f"{tag}: max {a['max']:.4f}% (x{fmax:.2f}), RMS x{frms:.2f}; "
                                    f"expected max < {below}% and at least x{need_max} / "
                                    f"x{need_rms}")
    for key in TARGETS:
        if key not in seen:
            failures.append(f"no run of {key[0]} at UMR {key[1]}")
    checks.finish(failures, "fandisk targets: all assertions hold")


if __name__ == "__main__":
    main()
