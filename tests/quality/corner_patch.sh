#!/usr/bin/env bash
# pyramid (validation half) and octahedron (tuning half), generated, by OpenVDB's voxel remesher
# at 1% and 0.5%: where four faces meet, the chamfer holds an edge between two opposite faces
# whose planes meet across it; the corner is now placed whole, at the point its regions' planes
# determine (a QEF with rank detection). Max factors against floors, none made worse.
# Assertions in check_corner_patch.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
require_openvdb
default_method_check pyramid,octahedron vdb_1pct,vdb_0.5pct check_corner_patch.py
