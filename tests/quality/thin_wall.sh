#!/usr/bin/env bash
# The tube (test_meshes/real/tube.off: a wall 1.3 cells thick between coarse 16- and 14-gon
# facets) resampled by OpenVDB's voxel remesher and by MeshLab's CSG (marching
# intersections) at 1%, sharpened by the default method: never worse than its input.
# Assertions in check_thin_wall.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
require_openvdb
default_method_check tube vdb_1pct,csg_1pct check_thin_wall.py
