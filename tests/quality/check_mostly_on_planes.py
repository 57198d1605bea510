#!/usr/bin/env python3
"""Assertions on features mostly on their planes (results JSON of run.py --models
bevelled_block,lblock_tilted --input-keys mc_1pct --variants auto).

A feature whose farthest sample lies more than 0.6 spacings off its plane stays as it was,
unless half of its samples lie within 0.1 spacings of their planes and none beyond one spacing
(feature_evidence.h: featureEvidenceIsWeak; then only the far samples' new vertices stay at
rest); and a feature stays as it was only when most of its new vertices were refused by the
other tests. Asserted: both inputs made, sharpened and measured, none made worse
(families.is_worse: max up > 2% or RMS up > 1%), and the reduction factors at least MIN_FACTORS.
Measured when this test was written (max / RMS factors): bevelled_block x1.11 / x1.83,
lblock_tilted x2.22 / x10.7; with the two rules as they were before
(`--on-plane-median 0 --feature-fallback 0.4`): x1.02 / x1.36 and x2.02 / x9.3.
"""
import checks  # first: puts bench/quality on sys.path

MIN_FACTORS = {"bevelled_block": (1.07, 1.6), "lblock_tilted": (2.1, 10.0)}


if __name__ == "__main__":
    checks.check_min_factors(MIN_FACTORS, "1%",
                             "features mostly on their planes: sharpened, none made worse")
