#!/usr/bin/env bash
# bevelled_block and lblock_tilted (generated shapes) by the project's own marching cubes at
# 1%, sharpened by the default method: features with a few samples rounded off their planes
# and features whose vertices the other tests partly refused are sharpened. Assertions in
# check_mostly_on_planes.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
default_method_check bevelled_block,lblock_tilted mc_1pct check_mostly_on_planes.py
