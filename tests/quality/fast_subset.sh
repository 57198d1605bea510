#!/usr/bin/env bash
# The quality benchmark's fast subset (bench/quality/run.py --fast) with assertions
# on its results (check_fast_subset.py).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
"$PYTHON" "$ES_SOURCE_DIR/bench/quality/run.py" --build "$ES_BUILD_DIR" --fast \
  --cache "$ES_WORK_DIR/cache" --results "$ES_WORK_DIR/results.json" --no-report --jobs 2 \
  --distance-sampling uniform --no-peer  # the sampling and methods its floors were measured with
"$PYTHON" "$ES_SOURCE_DIR/tests/quality/check_fast_subset.py" "$ES_WORK_DIR/results.json"
