#!/usr/bin/env bash
# The tube (test_meshes/real/tube.off: a wall 1.3 cells thick between coarse 16- and 14-gon
# facets) resampled by OpenVDB's voxel remesher and by MeshLab's CSG (marching
# intersections) at 1%, sharpened by the default method: never worse than its input.
# Assertions in check_thin_wall.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
if [[ ! -x $ES_BUILD_DIR/bench/samplers/vdb-remesh ]]; then
  echo "OpenVDB is not installed (no $ES_BUILD_DIR/bench/samplers/vdb-remesh; scripts/bootstrap.sh installs libopenvdb-dev): skipped"
  exit $SKIP
fi
"$PYTHON" "$ES_SOURCE_DIR/bench/quality/run.py" --build "$ES_BUILD_DIR" \
  --models tube --input-keys vdb_1pct,csg_1pct --variants auto --no-peer \
  --cache "$ES_WORK_DIR/cache" --results "$ES_WORK_DIR/results.json" --no-report --jobs 2
"$PYTHON" "$ES_SOURCE_DIR/tests/quality/check_thin_wall.py" "$ES_WORK_DIR/results.json"
