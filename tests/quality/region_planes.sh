#!/usr/bin/env bash
# lblock_tilted and cylinder_block (generated shapes) by Screened Poisson at depth 7,
# sharpened by the default method: a reconstruction rounds a planar region next to its
# features, where placement fits its plane; a region that is a plane in its core gives
# placement that plane instead. Assertions in check_region_planes.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
default_method_check cylinder_block,lblock_tilted poisson_depth7 check_region_planes.py
