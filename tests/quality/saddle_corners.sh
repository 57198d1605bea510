#!/usr/bin/env bash
# cross_prism (a generated shape with 8 saddle corners, where a concave edge meets the convex
# top) by MeshLab's Uniform Mesh Resampling at 1% and 0.5%, sharpened by the default method.
# Assertions in check_saddle_corners.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
"$PYTHON" "$ES_SOURCE_DIR/bench/quality/run.py" --build "$ES_BUILD_DIR" \
  --models cross_prism --input-keys umr_1pct,umr_0.5pct --variants auto --no-peer \
  --cache "$ES_WORK_DIR/cache" --results "$ES_WORK_DIR/results.json" --no-report --jobs 2
"$PYTHON" "$ES_SOURCE_DIR/tests/quality/check_saddle_corners.py" "$ES_WORK_DIR/results.json"
