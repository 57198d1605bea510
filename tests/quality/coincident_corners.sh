#!/usr/bin/env bash
# The cube (generated) by OpenVDB's voxel remesher at 2% and 1%: along its grid-aligned edges
# two new vertices share one target, so the faces between them lose their area before the
# zone projection runs; such a face no longer refuses the projection of the remesher's middle
# row onto a face's plane. Max factors against floors, none made worse. Assertions in
# check_coincident_corners.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
require_openvdb
default_method_check cube vdb_2pct,vdb_1pct check_coincident_corners.py
