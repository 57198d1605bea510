#!/usr/bin/env python3
"""Assertions on the quality benchmark's fast subset (results JSON of run.py --fast).

- Both methods: no sharpened mesh is farther from the reference than its input
  (max and RMS, 1% sampling tolerance).
- Exact references sharpened as they are, and the sphere's marching-cubes meshes, stay
  unchanged (the output is within 1e-3% of the diagonal of its input).
- The paper method's reduction factors (geometric means over the shapes with sharp
  edges) reach the levels measured when this test was written, with a margin:
  MeshLab UMR 1%: measured max x1.14 / RMS x1.78 over lblock, lblock_tilted, wedge,
  pyramid, cross_prism; x1.64 / x2.42 when MeshLab also resamples the cube (it comes out
  exact: factors are capped at x10); project MC 1%: measured max x1.22 / RMS x1.56.
- The extended method's reduction factors likewise: MeshLab UMR 1%: measured max x1.57 /
  RMS x6.63 over the same five shapes; project MC 1%: max x4.72 / RMS x9.69 over seven.
  (Until the self-intersection guard's grid saw faces in its last, partial cell, the UMR
  means were x1.91 / x8.45: the wedge's 35-degree edge, at the largest x, was sharpened
  into 154 crossing face pairs that went unseen; its tip now stays chamfered.)
- The auto method (the default) likewise: UMR 1% measured max x1.48 / RMS x6.12 over the five
  shapes; project MC 1%: max x4.31 / RMS x9.59 over seven (the evidence guard leaves a few of
  the pyramid's acute features chamfered). And, as for every method above, no output is worse
  than its input.
- The information limit (issue 60): every generated shape with sharp features by both grid
  samplers has its dual contouring with exact Hermite data measured, far nearer the reference
  than the input (at least x5 on max and RMS; not on the designed bevels and fillets, which a
  grid cell cuts off: dual contouring places one vertex per cell, and a bevel about a cell wide
  gives it no vertex of its own), and the limit table has a row per family.
- The shapes with designed bevels and fillets (bevelled_block, finished_hexprism): the default
  method makes none of them worse. The paper and extended methods are not held to that there
  (they cut a bevel or a fillet back to the edge its flanks meet at, by design), and these
  shapes are left out of the means above, which were measured without them.
"""
import math

import checks
import families

TOL = 0.01          # sampling noise of the max is well below 1%
FLOOR = 1e-4        # % of the diagonal: measurement noise of float meshes
UNCHANGED = 1e-3    # % of the diagonal
CAP = 10.0          # factors are capped in the means (the cube can come out exact)
# (max factor, RMS factor) at about 80% of the measured geometric means
# Designed bevels and fillets beside sharp edges: only the default method must leave them.
DESIGNED_FEATURES = {"bevelled_block", "finished_hexprism"}
MIN_FACTORS = {"paper": {"umr": (1.08, 1.6), "mc": (1.1, 1.3)},
               "extended": {"umr": (1.25, 5.3), "mc": (3.7, 7.7)},
               "auto": {"umr": (1.18, 4.9), "mc": (3.4, 7.7)}}


def gmean(v):
    return math.exp(sum(math.log(x) for x in v) / len(v)) if v else float("nan")


def main():
    results = checks.load_results()
    failures = []
    factors = {}
    made = {"umr": 0, "mc": 0}
    for c in results["cases"]:
        name = f"{c['model']} {c['input']} {c['resolution']}"
        if "before" not in c:
            print(f"  skipped: {name}: {c['make'].get('why', c['make']['status'])}")
            continue
        made[c["input"]] = made.get(c["input"], 0) + 1
        b = c["before"]
        for r in c["runs"]:
            tag = f"{name} {r['method']}"
            if r["status"] != "ok":
                failures.append(f"{tag}: {r['status']}: {r.get('why')}")
                continue
            a = r["after"]
            fmax = max(b["max"], FLOOR) / max(a["max"], FLOOR)
            frms = max(b["rms"], FLOOR) / max(a["rms"], FLOOR)
            print(f"  {tag:42s} max {b['max']:.4f} -> {a['max']:.4f} (x{fmax:.2f})  "
                  f"RMS {b['rms']:.5f} -> {a['rms']:.5f} (x{frms:.2f})")
            designed = c["model"] in DESIGNED_FEATURES
            if designed and r["method"] != "auto":
                continue
            if a["max"] > b["max"] * (1 + TOL) + FLOOR:
                failures.append(f"{tag}: max error grew {b['max']:.4f} -> {a['max']:.4f}")
            if a["rms"] > b["rms"] * (1 + TOL) + FLOOR:
                failures.append(f"{tag}: RMS error grew {b['rms']:.5f} -> {a['rms']:.5f}")
            if c["input"] == "asis" or c["model"] == "sphere":
                ch = r.get("change_max")
                if ch is None or ch > UNCHANGED:
                    failures.append(f"{tag}: a mesh without chamfers was changed by {ch}% of "
                                    "the diagonal")
            elif c["input"] in MIN_FACTORS["paper"] and not designed:
                factors.setdefault((c["input"], r["method"]), []).append(
                    (min(fmax, CAP), min(frms, CAP)))
    if made.get("umr", 0) < 4:
        failures.append(f"only {made.get('umr', 0)} shapes were resampled by MeshLab's Uniform "
                        "Mesh Resampling (expected at least 4 of 10)")
    for (kind, method), v in sorted(factors.items()):
        gm = gmean([x[0] for x in v]), gmean([x[1] for x in v])
        print(f"geometric mean, {kind} 1%, {method}: max x{gm[0]:.2f}, RMS x{gm[1]:.2f} "
              f"over {len(v)} shapes")
        need = MIN_FACTORS[method][kind]
        if gm[0] < need[0] or gm[1] < need[1]:
            failures.append(f"{method} method on {kind} 1%: max x{gm[0]:.2f} / RMS x{gm[1]:.2f}, "
                            f"expected at least x{need[0]} / x{need[1]}")
    check_limit(results, failures)
    checks.finish(failures, "quality fast subset: all assertions hold")


def check_limit(results, failures):
    """Every sharp generated shape's grid inputs have a limit far below the input's error."""
    cases = [c for c in results["cases"] if "before" in c and c["input"] in ("umr", "mc")
             and c["model"] not in families.NO_SHARP_FEATURES]
    for c in cases:
        name = f"{c['model']} {c['input']} {c['resolution']}"
        lim = c.get("limit")
        if lim is None:
            failures.append(f"{name}: no information limit measured")
            continue
        print(f"  {name:30s} limit max {lim['max']:.5f} RMS {lim['rms']:.6f}")
        if c["model"] in DESIGNED_FEATURES:
            continue
        for measure in ("max", "rms"):
            if lim[measure] * 5 > c["before"][measure]:
                failures.append(f"{name}: the limit's {measure} {lim[measure]:.5f} is not 5x "
                                f"below the input's {c['before'][measure]:.5f}")
    table = families.limit_table(cases, results["default_multiplier"])
    print(table)
    for kind in ("umr", "mc"):
        if families.FAMILY_TITLES[kind] not in table:
            failures.append(f"the limit table has no row for {kind}")


if __name__ == "__main__":
    main()
