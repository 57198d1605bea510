#!/usr/bin/env bash
# bevelled_block (generated: designed bevels beside sharp edges) by OpenVDB as Blender's voxel
# remesh with Preserve Volume (vertices cast onto the input) at 1% and 0.5%, sharpened by the
# default method: its bevels kept, neither input made worse. Assertions in
# check_exact_sampling.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
require_openvdb
default_method_check bevelled_block vdbproj_1pct,vdbproj_0.5pct check_exact_sampling.py
