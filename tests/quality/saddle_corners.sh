#!/usr/bin/env bash
# cross_prism (a generated shape with 8 saddle corners, where a concave edge meets the convex
# top) by MeshLab's Uniform Mesh Resampling at 1% and 0.5%, sharpened by the default method.
# Assertions in check_saddle_corners.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
default_method_check cross_prism umr_1pct,umr_0.5pct check_saddle_corners.py
