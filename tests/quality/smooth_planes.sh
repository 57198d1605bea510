#!/usr/bin/env bash
# Smooth parts made of planes may refuse more of their moves (guards/surface_measures.h):
# cross_prism reconstructed by MeshLab's Screened Poisson (depth 7) is sharpened by the
# default method (it was left whole before), and rocker-arm (../shared: a freeform part,
# as smooth but with almost none of its area on planes) resampled by OpenVDB at 1% is not
# made worse. Assertions in check_smooth_planes.py.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
run() {  # run MODEL KEY: the default method on one input, results in $ES_WORK_DIR/MODEL.json
  "$PYTHON" "$ES_SOURCE_DIR/bench/quality/run.py" --build "$ES_BUILD_DIR" --shared "$shared" \
    --models "$1" --input-keys "$2" --variants auto --no-peer \
    --cache "$ES_WORK_DIR/cache" --results "$ES_WORK_DIR/$1.json" --no-report --jobs 2
}
shared="$ES_SOURCE_DIR/../shared/meshes"
run cross_prism poisson_depth7
results=("$ES_WORK_DIR/cross_prism.json")
if [[ -f $shared/rocker-arm.obj && -x $ES_BUILD_DIR/bench/samplers/vdb-remesh ]]; then
  run rocker-arm vdb_1pct
  results+=("$ES_WORK_DIR/rocker-arm.json")
else
  echo "no ../shared/meshes/rocker-arm.obj or no OpenVDB: only cross_prism is checked"
fi
"$PYTHON" "$ES_SOURCE_DIR/tests/quality/check_smooth_planes.py" "${results[@]}"
