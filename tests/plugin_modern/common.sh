# shellcheck shell=bash disable=SC2034  # variables are used by the sourcing scripts
# Shared setup of the MeshLab 2022.02 plugin tests (sourced by tests/plugin_modern/*.sh).
# They run the real MeshLab 2022.02 of Debian trixie in the root made by
# scripts/trixie-root.sh, on the plugin and runner of scripts/build-plugins.sh
# (the fixture plugin_modern.prepare makes both). Environment (tests/plugin_modern_tests.cmake):
#   ES_BUILD_DIR   main build dir (meshlab-<release>/ inside)
#   ES_TEST_TOOL   plugin_test_tool (host)     ES_CLI   edge-sharpener CLI (host)
#   ES_SOURCE_DIR  source tree;  ES_WORK_DIR  scratch dir of this test (wiped)
source "$(dirname "${BASH_SOURCE[0]}")/../lib/common.sh"

: "${ES_BUILD_DIR:?}" "${ES_TEST_TOOL:?}" "${ES_SOURCE_DIR:?}" "${ES_WORK_DIR:?}"
MODERN_BUILD="$ES_BUILD_DIR/meshlab-2022.02"
PLUGIN="$MODERN_BUILD/libfilter_edge_sharpener.so"
RUNNER="$MODERN_BUILD/meshlab-filter-runner"
SCRIPTS="$ES_SOURCE_DIR/filter_edge_sharpener/scripts"
ROOT_TOOL="$ES_SOURCE_DIR/scripts/trixie-root.sh"
[[ -f $PLUGIN && -x $RUNNER ]] || fail "no 2022.02 build in $MODERN_BUILD (scripts/build-plugins.sh 2022.02)"
[[ -x $ES_TEST_TOOL ]] || fail "plugin_test_tool not built ($ES_TEST_TOOL)"

rm -rf "$ES_WORK_DIR"
mkdir -p "$ES_WORK_DIR"
cd "$ES_WORK_DIR"

# in_trixie CMD...: CMD in the trixie root, with the source and build trees at
# their own paths, in this test's work dir, with Qt's offscreen platform.
in_trixie() {
  ES_ROOT_BINDS="$ES_SOURCE_DIR:$ES_BUILD_DIR:$ES_WORK_DIR" bash "$ROOT_TOOL" run \
    /usr/bin/env -C "$ES_WORK_DIR" QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR=/tmp/runtime-es HOME=/root "$@"
}

# Crash = killed by a signal (status > 128; 124 = timeout).
is_crash() { (($1 == 124 || $1 > 128)); }

# run_filter NAME RUNNER-ARGS...: MeshLab 2022.02 (stock plugins + ours) applies a
# filter or script in the root; stdout+stderr in NAME.out, status in $rc.
run_filter() {
  local name=$1
  shift
  rc=0
  # timeout inside the root: it stops the runner itself, not only the chroot's parent.
  in_trixie timeout -k 10 "${ES_RUNNER_TIMEOUT:-600}" "$RUNNER" --add-plugin "$PLUGIN" "$@" \
    >"$name.out" 2>&1 || rc=$?
  grep -q '^Loaded [0-9]* plugins' "$name.out" || { cat "$name.out" >&2; fail "$name: the runner did not start"; }
}

# The L-block of chamfered_inputs, resampled by stock MeshLab 2022.02 (tests/lib/common.sh).
LBLOCK=lblock_umr
LBLOCK_RUN=run_filter
