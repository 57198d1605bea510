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
