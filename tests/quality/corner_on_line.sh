#!/usr/bin/env bash
# pyramid (generated, validation half) by OpenVDB as Blender's voxel remesh with Preserve Volume
# (vertices cast onto the input) at 1%: its samples near the apex lie on the edges into it, so
# the apex placed whole leaves faces without area along them, which the cleanup now removes by
# merging those samples into the apex instead of giving the apex up. Assertions in
# check_corner_on_line.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
require_openvdb
default_method_check pyramid vdbproj_1pct check_corner_on_line.py
