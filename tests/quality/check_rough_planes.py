#!/usr/bin/env python3
"""Assertions on a rough input's planar faces flattened (results JSON of run.py --models
cross_prism,lblock_tilted --input-keys scan_noise0 --variants auto).

A depth scan fused in a TSDF is rough (its noise is above the smooth bound), and the default
method leaves its features as they are; its fusion bulges each planar face outwards for a few
samples beside every edge, and the vertices of a face that is a plane in its core, lying outside
that plane by at most one sample spacing, are moved onto it
(SharpenOptions::flattenRoughPlanes, planar_regions.h: flattenPlanarRegions). Asserted
(checks.check_min_factors): both inputs made, sharpened and measured, neither made worse
(families.is_worse: max up > 2% or RMS up > 1%), and the reduction factors at least
MIN_FACTORS. Measured when this test was written (max / RMS factors): cross_prism x1.00 /
x1.25, lblock_tilted x1.00 / x1.14; without the flattening (`--keep-rough-planes`) x1.00 /
x1.00 for both, which fails the RMS floors.
"""
import checks  # first: puts bench/quality on sys.path

MIN_FACTORS = {"cross_prism": (0.98, 1.2), "lblock_tilted": (0.98, 1.1)}


def main():
    checks.check_min_factors(MIN_FACTORS, "noise 0",
                             "a rough input's planar faces flattened: none made worse")


if __name__ == "__main__":
    main()
