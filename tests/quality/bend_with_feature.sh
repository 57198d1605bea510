#!/usr/bin/env bash
# cylinder_block and lblock_tilted (generated shapes) by OpenVDB's voxel remesher at 2%,
# sharpened by the default method: a new vertex whose flank bends away near a corner (the
# voxels round a sharp edge most there) moves with its feature when the feature's evidence is
# strong. Assertions in check_bend_with_feature.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
if [[ ! -x $ES_BUILD_DIR/bench/samplers/vdb-remesh ]]; then
  echo "OpenVDB is not installed (no $ES_BUILD_DIR/bench/samplers/vdb-remesh; scripts/bootstrap.sh installs libopenvdb-dev): skipped"
  exit $SKIP
fi
"$PYTHON" "$ES_SOURCE_DIR/bench/quality/run.py" --build "$ES_BUILD_DIR" \
  --models cylinder_block,lblock_tilted --input-keys vdb_2pct --variants auto --no-peer \
  --cache "$ES_WORK_DIR/cache" --results "$ES_WORK_DIR/results.json" --no-report --jobs 2
"$PYTHON" "$ES_SOURCE_DIR/tests/quality/check_bend_with_feature.py" "$ES_WORK_DIR/results.json"
