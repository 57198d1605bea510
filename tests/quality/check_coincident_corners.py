#!/usr/bin/env python3
"""Assertions on faces without area in the zone projection (results JSON of run.py --models
cube --input-keys vdb_2pct,vdb_1pct --variants auto).

OpenVDB's voxel remesher leaves a middle row of vertices along a grid-aligned convex edge,
inside the solid and off both faces. Placement puts the new vertices on the edge's line, two of
them often on one point, and the faces between them lose their area. The zone projection then
refused to move the middle row onto a face's plane (such a face cannot keep facing the way it
faced: it faced no way), and the row stayed, 0.43 cells off both faces. A face without area no
longer refuses (extended/projection.h: moveKeepsFaces). Asserted: both inputs made, sharpened
and measured, none made worse (families.is_worse), and each max error lowered by at least its
floor, set between the factors before the change and after it (docs/auto-method-decisions.md
has the figures).
"""
import checks  # first: puts bench/quality on sys.path

MULTIPLIER = 2.0
# (model, resolution) -> the least max reduction factor.
MIN_MAX_FACTORS = {
    ("cube", "2%"): 20.0,
    ("cube", "1%"): 20.0,
}


def main():
    checks.check_max_factors_by_model(
        MIN_MAX_FACTORS, "coincident corners: the middle row onto a face, max down", MULTIPLIER)


if __name__ == "__main__":
    main()
