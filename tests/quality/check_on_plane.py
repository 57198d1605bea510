#!/usr/bin/env python3
"""Assertions on exactly sampled features with a few far samples (results JSON of run.py
--models lblock_tilted,plate_holes --input-keys ier_2pct,ier_1pct --variants auto).

A feature with one source vertex far off its plane (more than 0.6 sample spacings) used to
stay chamfered whole. Where nine in ten of its samples lie within 0.05 spacings of their
planes (a remesher that reprojects onto the surface), it is sharpened and only the new
vertices of its far samples stay at rest (feature_evidence.h: Feature::offPlaneQ90,
vertexIsWeak). Asserted: every input made was sharpened and measured and none came out
worse (families.is_worse: max up > 2% or RMS up > 1%); lblock_tilted at IER 2% gains at least
MIN_LBLOCK_RMS_FACTOR in RMS (measured x3.86 when this test was written, x2.50 with the far
samples counting, `--on-plane 0`); plate_holes at IER 1%, whose far samples lie on its
fillets (with the features sharpened whole its max rose 0.625% -> 0.985%), gains at least
MIN_PLATE_RMS_FACTOR (measured x1.30; x1.00 with `--on-plane 0`).
"""
import checks  # first: puts bench/quality on sys.path

MULTIPLIER = 2.0
MIN_LBLOCK_RMS_FACTOR = 3.2
MIN_PLATE_RMS_FACTOR = 1.15
EXPECTED = {("lblock_tilted", "2%"), ("lblock_tilted", "1%"), ("plate_holes", "2%"),
            ("plate_holes", "1%")}


MIN_RMS_FACTORS = {("lblock_tilted", "2%"): MIN_LBLOCK_RMS_FACTOR,
                   ("plate_holes", "1%"): MIN_PLATE_RMS_FACTOR}


def factors(case):
    bound = MIN_RMS_FACTORS.get((case["model"], case["resolution"]))
    return {"rms": bound} if bound else {}


if __name__ == "__main__":
    checks.check_default_method(("model", "resolution"), EXPECTED,
                                "on-plane features: sharpened, none made worse", factors,
                                MULTIPLIER, width=24)
