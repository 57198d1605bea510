#!/usr/bin/env bash
# fandisk (../shared/meshes) resampled by MeshLab's Uniform Mesh Resampling at 2%, 1% and
# 0.5% cells, sharpened by every method of the benchmark: the headline target that is met,
# asserted (check_fandisk_targets.py). Skipped without ../shared.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
shared="$ES_SOURCE_DIR/../shared/meshes"
if [[ ! -f $shared/fandisk.off ]]; then
  echo "$shared/fandisk.off not found (the reference meshes are not beside the checkout): skipped"
  exit $SKIP
fi
"$PYTHON" "$ES_SOURCE_DIR/bench/quality/run.py" --build "$ES_BUILD_DIR" --shared "$shared" \
  --models fandisk --inputs umr --cache "$ES_WORK_DIR/cache" --results "$ES_WORK_DIR/results.json" \
  --no-report --jobs 2 \
  --distance-sampling uniform --no-peer  # the sampling and methods its targets were measured with
"$PYTHON" "$ES_SOURCE_DIR/tests/quality/check_fandisk_targets.py" "$ES_WORK_DIR/results.json"
