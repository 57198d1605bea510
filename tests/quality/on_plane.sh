#!/usr/bin/env bash
# MeshLab's Isotropic Explicit Remeshing (features off, reprojection on) puts its samples on
# the surface: lblock_tilted at 2%, whose features each have a few samples far off their
# planes where they meet another part, and plate_holes (test_meshes/real) at 1%, whose notch
# edges' far samples lie on its fillets. Sharpened by the default method. Assertions in
# check_on_plane.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
"$PYTHON" "$ES_SOURCE_DIR/bench/quality/run.py" --build "$ES_BUILD_DIR" \
  --models lblock_tilted,plate_holes --input-keys ier_2pct,ier_1pct --variants auto --no-peer \
  --cache "$ES_WORK_DIR/cache" --results "$ES_WORK_DIR/results.json" --no-report --jobs 2
"$PYTHON" "$ES_SOURCE_DIR/tests/quality/check_on_plane.py" "$ES_WORK_DIR/results.json"
