#!/usr/bin/env bash
# lblock_tilted and cross_prism (generated shapes) scanned by depth cameras and fused in a TSDF
# (noise 0), sharpened by the default method: the scans are rough, their features are left as
# they are, and their planar faces, which the fusion bulges outwards beside every edge, are
# flattened onto their planes. Assertions in check_rough_planes.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
require_open3d
default_method_check cross_prism,lblock_tilted scan_noise0 check_rough_planes.py
