#!/usr/bin/env bash
# lblock_tilted and cylinder_block (generated shapes) by Screened Poisson at depth 7,
# sharpened by the default method: a reconstruction rounds a planar region next to its
# features, where placement fits its plane; a region that is a plane in its core gives
# placement that plane instead. Assertions in check_region_planes.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
"$PYTHON" "$ES_SOURCE_DIR/bench/quality/run.py" --build "$ES_BUILD_DIR" \
  --models cylinder_block,lblock_tilted --input-keys poisson_depth7 --variants auto --no-peer \
  --cache "$ES_WORK_DIR/cache" --results "$ES_WORK_DIR/results.json" --no-report --jobs 2
"$PYTHON" "$ES_SOURCE_DIR/tests/quality/check_region_planes.py" "$ES_WORK_DIR/results.json"
