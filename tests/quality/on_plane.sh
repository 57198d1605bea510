#!/usr/bin/env bash
# MeshLab's Isotropic Explicit Remeshing (features off, reprojection on) puts its samples on
# the surface: lblock_tilted at 2%, whose features each have a few samples far off their
# planes where they meet another part, and plate_holes (test_meshes/real) at 1%, whose notch
# edges' far samples lie on its fillets. Sharpened by the default method. Assertions in
# check_on_plane.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
default_method_check lblock_tilted,plate_holes ier_2pct,ier_1pct check_on_plane.py
