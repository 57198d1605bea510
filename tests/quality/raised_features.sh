#!/usr/bin/env bash
# A slab with raised features 1-3 scan voxels high (bosses, ribs), authored by the checker,
# scanned by depth cameras fused in a TSDF (noise 0 and 0.2 voxel) and sharpened by the
# default method: the planar faces are flattened, the raised features kept. Assertions in
# check_raised_features.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
require_open3d
"$PYTHON" "$ES_SOURCE_DIR/tests/quality/check_raised_features.py" --build "$ES_BUILD_DIR" \
  --source "$ES_SOURCE_DIR" --work "$ES_WORK_DIR"
