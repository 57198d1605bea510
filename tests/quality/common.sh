# shellcheck shell=bash
# Shared setup of the quality tests (sourced). Environment from tests/quality_tests.cmake:
# ES_BUILD_DIR, ES_MESHLAB_PREFIX, ES_SOURCE_DIR, ES_WORK_DIR (scratch, wiped).
set -euo pipefail
SKIP=77
if ! command -v meshlabserver >/dev/null 2>&1; then
  echo "MeshLab is not installed (no meshlabserver in PATH): skipped"
  exit $SKIP
fi
PYTHON=/usr/bin/python3
[[ -x $PYTHON ]] || PYTHON=$(command -v python3 || true)
if [[ -z $PYTHON ]]; then
  echo "python3 is not installed: skipped"
  exit $SKIP
fi
: "${ES_BUILD_DIR:?}" "${ES_MESHLAB_PREFIX:?}" "${ES_SOURCE_DIR:?}" "${ES_WORK_DIR:?}"
[[ -x $ES_MESHLAB_PREFIX/bin/meshlabserver ]] || {
  echo "FAIL: no private MeshLab prefix in $ES_MESHLAB_PREFIX (build the target meshlab_private_prefix)" >&2
  exit 1
}
rm -rf "$ES_WORK_DIR"
mkdir -p "$ES_WORK_DIR"
cd "$ES_WORK_DIR"
unset QT_QPA_PLATFORM

# Skips the test unless OpenVDB's sampler was built / Open3D is there for /usr/bin/python3.
require_openvdb() {
  if [[ ! -x $ES_BUILD_DIR/bench/samplers/vdb-remesh ]]; then
    echo "OpenVDB is not installed (no $ES_BUILD_DIR/bench/samplers/vdb-remesh; scripts/bootstrap.sh installs libopenvdb-dev): skipped"
    exit $SKIP
  fi
}
require_open3d() {
  if ! /usr/bin/python3 -c "import open3d" 2>/dev/null; then
    echo "Open3D is not installed for /usr/bin/python3 (scripts/bootstrap.sh installs python3-open3d): skipped"
    exit $SKIP
  fi
}

# The default method on the inputs INPUT_KEYS (run.py --input-keys) of MODELS, then CHECK (a
# script in tests/quality) on the results; further arguments go to run.py.
default_method_check() {
  local models=$1 keys=$2 check=$3
  shift 3
  "$PYTHON" "$ES_SOURCE_DIR/bench/quality/run.py" --build "$ES_BUILD_DIR" "$@" \
    --models "$models" --input-keys "$keys" --variants auto --no-peer \
    --cache "$ES_WORK_DIR/cache" --results "$ES_WORK_DIR/results.json" --no-report --jobs 2
  "$PYTHON" "$ES_SOURCE_DIR/tests/quality/$check" "$ES_WORK_DIR/results.json"
}
