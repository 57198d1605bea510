# shellcheck shell=bash disable=SC2034  # variables are used by the sourcing scripts
# Shared setup of the MeshLab plugin tests (sourced by tests/plugin/*.sh).
# Environment (set by tests/plugin_tests.cmake):
#   ES_MESHLAB_PREFIX  private prefix made by the target meshlab_private_prefix
#   ES_TEST_TOOL       plugin_test_tool executable
#   ES_CLI             edge-sharpener CLI (empty when not built)
#   ES_SOURCE_DIR      source tree;  ES_WORK_DIR  scratch dir of this test (wiped)
# Exit status 77 = skipped: only when MeshLab is not installed at all.
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"

SKIP=77

if ! command -v meshlabserver >/dev/null 2>&1 || ! command -v meshlab >/dev/null 2>&1; then
  log "MeshLab is not installed (no meshlab/meshlabserver in PATH): skipped"
  exit $SKIP
fi
command -v xvfb-run >/dev/null 2>&1 || fail "xvfb-run not found (Debian package xvfb)"

: "${ES_MESHLAB_PREFIX:?}" "${ES_TEST_TOOL:?}" "${ES_SOURCE_DIR:?}" "${ES_WORK_DIR:?}"
SERVER="$ES_MESHLAB_PREFIX/bin/meshlabserver"
GUI="$ES_MESHLAB_PREFIX/bin/meshlab"
PLUGIN_LINK="$ES_MESHLAB_PREFIX/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_edge_sharpener.so"
SCRIPTS="$ES_SOURCE_DIR/filter_edge_sharpener/scripts"
[[ -x $SERVER && -e $PLUGIN_LINK ]] ||
  fail "no private MeshLab prefix with the plugin in $ES_MESHLAB_PREFIX: build the target meshlab_private_prefix"
[[ -x $ES_TEST_TOOL ]] || fail "plugin_test_tool not built ($ES_TEST_TOOL)"

rm -rf "$ES_WORK_DIR"
mkdir -p "$ES_WORK_DIR/home" "$ES_WORK_DIR/runtime"
chmod 700 "$ES_WORK_DIR/runtime"
cd "$ES_WORK_DIR"
# MeshLab keeps settings in $HOME/.config: start every test from a clean one.
export HOME="$ES_WORK_DIR/home" XDG_RUNTIME_DIR="$ES_WORK_DIR/runtime"
unset QT_QPA_PLATFORM  # meshlabserver needs a real (virtual) X display with GLX

# Crash = killed by a signal (exit status > 128 from the shell, 124 from timeout).
# meshlabserver itself exits with 255 (exit(-1)) when a filter fails.
is_crash() { (($1 == 124 || ($1 > 128 && $1 != 255))); }

# run_server NAME ARGS...: meshlabserver under Xvfb; stdout+stderr in NAME.out,
# exit status in $rc. Never hangs (timeout), never aborts the calling script.
run_server() {
  local name=$1
  shift
  rc=0
  timeout -k 10 "${ES_SERVER_TIMEOUT:-300}" \
    xvfb-run -a -s "-screen 0 1280x1024x24" "$SERVER" "$@" >"$name.out" 2>&1 || rc=$?
  if grep -q "Current Plugins Dir is: $ES_MESHLAB_PREFIX/" "$name.out"; then :; else
    cat "$name.out" >&2
    fail "$name: meshlabserver did not use the private plugin dir"
  fi
}

# The L-block of chamfered_inputs, resampled by meshlabserver (tests/lib/common.sh).
LBLOCK=lblock_mc
LBLOCK_RUN=run_server
