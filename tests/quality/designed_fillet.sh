#!/usr/bin/env bash
# plate_holes (test_meshes/real: a plate whose bottom outline is a designed fillet, radius
# 6.35) by OpenVDB as Blender's voxel remesh with Preserve Volume (vertices cast onto the
# input) at 1%, sharpened by the default method: the fillet kept, the input not made worse.
# Assertions in check_designed_fillet.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
require_openvdb
default_method_check plate_holes vdbproj_1pct check_designed_fillet.py
