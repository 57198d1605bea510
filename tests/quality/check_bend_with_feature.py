#!/usr/bin/env python3
"""Assertions on vertices moved with their feature across a bending flank (results JSON of
run.py --models cylinder_block,lblock_tilted --input-keys vdb_2pct --variants auto).

A new vertex the bend test would keep at rest (a flank's fitted faces curve away before its
target, as a blend's do) moves when its move is at most one sample spacing and nothing else
refuses it, stays moved only with a feature whose evidence is strong, and counts as refused in
that evidence (SharpenOptions::maxBentMoveSpacings). Asserted (checks.check_min_factors): both
inputs made, sharpened and measured, neither made worse (families.is_worse: max up > 2% or RMS
up > 1%), and the reduction factors at least MIN_FACTORS. Measured when this test was written
(max / RMS factors): cylinder_block x2.29 / x2.75, lblock_tilted x1.85 / x2.41; with the bend
keeping its vertices at rest (`--bent-move 0`): x1.08 / x2.08 and x1.49 / x2.11.
"""
import checks  # first: puts bench/quality on sys.path

MIN_FACTORS = {"cylinder_block": (1.8, 2.4), "lblock_tilted": (1.7, 2.25)}


if __name__ == "__main__":
    checks.check_min_factors(MIN_FACTORS, "2%",
                             "moved with their feature across a bending flank: none made worse")
