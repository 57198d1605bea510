#!/usr/bin/env python3
"""Assertions on a designed fillet kept (results JSON of run.py --models plate_holes
--input-keys vdbproj_1pct --variants auto).

plate_holes' bottom outline is a fillet of radius 6.35, 2.4 sample spacings across at OpenVDB's
1% cells; its top outline's edges are sharp and meet the grid as the fillet's flanks do. The
default method took the fillet for a sampling chamfer and made the input worse (max 0.880% ->
0.923%, RMS 0.0487% -> 0.105% of the diagonal): its samples lie on one arc, wider than the
sampler leaves at the top edges, and such a feature is now left on the surface
(feature_evidence.h: isDesignedFillet). Asserted: the input made, sharpened and measured, not
made worse (families.is_worse: max up > 2% or RMS up > 1%), and the RMS error down by at least
MIN_RMS_FACTORS (measured x1.09 when this test was written; x0.46 before the rule).
"""
import checks  # first: puts bench/quality on sys.path

MIN_RMS_FACTORS = {"1%": 1.03}

if __name__ == "__main__":
    checks.check_rms_factors_by_resolution(
        "vdbproj", MIN_RMS_FACTORS, "designed fillet kept, the input not made worse")
