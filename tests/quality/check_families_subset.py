#!/usr/bin/env python3
"""Assertions on the new sampler families' fast subset (results JSON of run.py, issue 19).

Three generated shapes (lblock_tilted, cylinder_block, pyramid), resampled by OpenVDB's voxel
remesher at 1% and by TSDF depth scans at noise 0 and 0.2 voxel, sharpened by every method and
variant, and smoothed by MeshLab's UnSharp Mask Geometry (the peer). Asserted:
- every input was made, and is a closed 2-manifold (the sampler's own edge check);
- every run succeeded: the sharpener accepted every input, the peer ran, both were measured;
- per family and method, the geometric means of the max and RMS reduction factors are at least
  MARGIN times the ones measured when this test was written (MEASURED; the runs are
  deterministic: the margin leaves room for legitimate small changes of a method, not for a
  regression), and the count of worse outputs (run by families.is_worse: max up > 2% or RMS up
  > 1%) is no larger than measured then. A method that gets better passes; update MEASURED
  when it does, so that the floors follow. The auto method (the default) was measured with no
  worse output in any of the three families (the no-harm rule, asserted as its worse count 0).
"""
import checks  # first: puts bench/quality on sys.path
import families

MARGIN = 0.9
MULTIPLIER = 2.0
# (input, resolution) -> method -> (max factor, RMS factor, worse count of 3), as measured
MEASURED = {
    ("vdb", "1%"): {"auto": (1.060, 1.360, 0), "paper": (1.0, 1.034, 0), "extended": (2.155, 6.434, 0),
                    "extended-strict": (1.071, 2.277, 0), "extended-grid": (2.155, 6.434, 0),
                    "extended-strict-grid": (1.071, 2.277, 0), "unsharp-mask": (1.297, 1.429, 0)},
    ("scan", "noise 0"): {"auto": (1.0, 1.0, 0), "paper": (1.0, 0.990, 2), "extended": (0.881, 0.944, 3),
                          "extended-strict": (1.0, 0.960, 3), "extended-grid": (0.881, 0.957, 3),
                          "extended-strict-grid": (1.0, 0.964, 3),
                          "unsharp-mask": (0.886, 0.883, 3)},
    ("scan", "noise 0.2 voxel"): {"auto": (1.0, 1.0, 0), "paper": (1.0, 0.989, 2), "extended": (0.943, 0.951, 3),
                                  "extended-strict": (1.005, 0.962, 3),
                                  "extended-grid": (0.942, 0.962, 3),
                                  "extended-strict-grid": (1.005, 0.968, 2),
                                  "unsharp-mask": (0.889, 0.883, 3)},
}
SHAPES = 3


def main():
    results = checks.load_results()
    failures = []
    groups = {}
    for c in results["cases"]:
        name = f"{c['model']} {c['input']} {c['resolution']}"
        mk = c["make"]
        if mk["status"] != "ok" or "before" not in c:
            failures.append(f"{name}: input not made: {mk.get('why', mk['status'])}")
            continue
        sampler = mk.get("sampler", {})
        if not sampler.get("closed_manifold"):
            failures.append(f"{name}: not a closed 2-manifold: {sampler}")
        for r in c["runs"]:
            if r["status"] != "ok":
                failures.append(f"{name} {r['method']} m{r['multiplier']:g}: {r['status']}: "
                                f"{r.get('why')}")
        groups.setdefault((c["input"], c["resolution"]), []).append(c)
    for key, methods in MEASURED.items():
        cases = groups.get(key, [])
        if len(cases) != SHAPES:
            failures.append(f"{key}: {len(cases)} inputs measured, expected {SHAPES}")
            continue
        for method, (mmax, mrms, mworse) in methods.items():
            gmax, grms, worse, measured, failed = families.family_stats(cases, method, MULTIPLIER)
            print(f"  {key[0]} {key[1]:16s} {method:22s} max x{gmax:.3f} (floor "
                  f"{MARGIN * mmax:.3f})  RMS x{grms:.3f} (floor {MARGIN * mrms:.3f})  worse "
                  f"{worse}/{measured} (at most {mworse})")
            if measured != SHAPES:
                failures.append(f"{key} {method}: {measured} outputs measured, {failed} failed")
                continue
            if gmax < MARGIN * mmax or grms < MARGIN * mrms:
                failures.append(f"{key} {method}: max x{gmax:.3f} / RMS x{grms:.3f}, expected at "
                                f"least x{MARGIN * mmax:.3f} / x{MARGIN * mrms:.3f}")
            if worse > mworse:
                failures.append(f"{key} {method}: {worse} outputs worse, at most {mworse} "
                                "were when measured")
    checks.finish(failures, "quality families subset: all assertions hold")


if __name__ == "__main__":
    main()
