#!/usr/bin/env bash
# cross_prism (generated: convex edges, concave edges and saddle corners) by OpenVDB as
# Blender's voxel remesh with Preserve Volume at 1% and 0.5%: its convex edges come out sharp
# already, its concave ones chamfered; the default method sharpens the chamfered ones, up to the
# saddle corners where they end, neither input made worse. Assertions in check_partly_sharp.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
require_openvdb
default_method_check cross_prism vdbproj_1pct,vdbproj_0.5pct check_partly_sharp.py
