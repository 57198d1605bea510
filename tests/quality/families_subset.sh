#!/usr/bin/env bash
# The quality benchmark's sampler families (issue 19) on small generated shapes: OpenVDB's voxel
# remesher, MeshLab's isotropic remeshing and Screened Poisson, TSDF depth scans at noise 0
# and 0.2 voxel; every method and variant and MeshLab's UnSharp Mask peer; assertions in
# check_families_subset.py (UMR and the project's marching cubes: fast_subset).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
require_openvdb
require_open3d
"$PYTHON" "$ES_SOURCE_DIR/bench/quality/run.py" --build "$ES_BUILD_DIR" \
  --models lblock_tilted,cylinder_block,cross_prism \
  --input-keys vdb_1pct,ier_1pct,poisson_depth7,scan_noise0,scan_noise0.2voxel \
  --cache "$ES_WORK_DIR/cache" --results "$ES_WORK_DIR/results.json" --no-report --jobs 2
"$PYTHON" "$ES_SOURCE_DIR/tests/quality/check_families_subset.py" "$ES_WORK_DIR/results.json"
