#!/usr/bin/env bash
# cylinder_block and lblock_tilted (generated shapes) by OpenVDB's voxel remesher at 2%,
# sharpened by the default method: a new vertex whose flank bends away near a corner (the
# voxels round a sharp edge most there) moves with its feature when the feature's evidence is
# strong. Assertions in check_bend_with_feature.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
require_openvdb
default_method_check cylinder_block,lblock_tilted vdb_2pct check_bend_with_feature.py
