#!/usr/bin/env bash
# bevelled_block and lblock_tilted (generated shapes) by the project's own marching cubes at
# 1%, sharpened by the default method: features with a few samples rounded off their planes
# and features whose vertices the other tests partly refused are sharpened. Assertions in
# check_mostly_on_planes.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
"$PYTHON" "$ES_SOURCE_DIR/bench/quality/run.py" --build "$ES_BUILD_DIR" \
  --models bevelled_block,lblock_tilted --input-keys mc_1pct --variants auto --no-peer \
  --cache "$ES_WORK_DIR/cache" --results "$ES_WORK_DIR/results.json" --no-report --jobs 2
"$PYTHON" "$ES_SOURCE_DIR/tests/quality/check_mostly_on_planes.py" "$ES_WORK_DIR/results.json"
