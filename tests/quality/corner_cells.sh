#!/usr/bin/env bash
# cylinder_block and lblock_tilted (generated) by OpenVDB's voxel remesher at 1% and 0.5%: the
# remesher's vertex in a convex corner's cell lies inside the solid, off all three faces; once
# the corner is restored it goes onto a neighbouring face's plane where its own would fold a
# face. Max factors against floors, none made worse. Assertions in check_corner_cells.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
require_openvdb
default_method_check cylinder_block,lblock_tilted vdb_1pct,vdb_0.5pct check_corner_cells.py
