#!/usr/bin/env bash
# pyramid and hexagonal_pyramid (validation half) and octahedron (tuning half), generated, by
# OpenVDB's voxel remesher at 1% and 0.5%: where four or more faces meet, the chamfer holds edges
# between faces that touch only at the corner; the corner is now placed whole, at the point its
# regions' planes determine (a QEF with rank detection). Max factors against floors, none made
# worse.
# Assertions in check_corner_patch.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
require_openvdb
default_method_check pyramid,octahedron,hexagonal_pyramid vdb_1pct,vdb_0.5pct check_corner_patch.py
