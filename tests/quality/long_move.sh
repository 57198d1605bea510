#!/usr/bin/env bash
# octa-flower17k (../shared/meshes) by MeshLab's Screened Poisson (depth 7): the
# reconstruction rounds each acute petal tip back, and the planes fitted to a petal's curved
# faces meet beyond the reference's tip. Sharpened by the default method. Assertions in
# check_long_move.py. Skipped without ../shared.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
shared="$ES_SOURCE_DIR/../shared/meshes"
if [[ ! -f $shared/octa-flower17k.stl ]]; then
  echo "$shared/octa-flower17k.stl not found (the reference meshes are not beside the checkout): skipped"
  exit $SKIP
fi
default_method_check octa-flower17k poisson_depth7 check_long_move.py --shared "$shared"
