#!/usr/bin/env python3
"""Assertions on smooth parts made of planes (the results JSONs of run.py --variants auto on
cross_prism's poisson_depth7 and, when ../shared and OpenVDB are there, rocker-arm's vdb_1pct).

Screened Poisson rounds every edge of cross_prism into a blend on which placement's tests
refuse about 45% of the moves: above the 40% at which a mesh is left whole, below the 60%
allowed on a smooth part made of planes (noise at most 0.018 sample spacings, at least 30% of
the area on planes). Asserted: every input was made and the default method ran on it; no
output is worse (families.is_worse: max up > 2% or RMS up > 1%); cross_prism's Poisson
reconstruction has its RMS error lowered by at least MIN_POISSON_RMS_FACTOR (measured x1.14
when this test was written; x1.00 without the smooth bound). rocker-arm by OpenVDB at 1% is
as smooth and as refused, but a freeform part: sharpened, its max error rose by 3%.
"""
import sys

import checks  # first: puts bench/quality on sys.path

MULTIPLIER = 2.0
MIN_POISSON_RMS_FACTOR = 1.1


def factors(case):
    poisson = (case["model"], case["input"]) == ("cross_prism", "poisson")
    return {"rms": MIN_POISSON_RMS_FACTOR} if poisson else {}


def main():
    expected = {("cross_prism", "poisson")}
    if len(sys.argv) > 2:  # rocker-arm's results too
        expected.add(("rocker-arm", "vdb"))
    checks.check_default_method(
        ("model", "input"), expected,
        "smooth planes: Poisson's cross_prism sharpened, nothing made worse", factors, MULTIPLIER)


if __name__ == "__main__":
    main()
