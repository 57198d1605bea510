# shellcheck shell=bash
# Shared by the GUI drivers tests/plugin/gui_driver.sh (MeshLab 2020.09) and
# tests/plugin_modern/gui_driver.sh (2022.02, in the trixie root), sourced first: they
# run inside xvfb-run, in the test's work dir, and drive MeshLab with xdotool. Every
# wait is bounded; MeshLab is always stopped. KEY_DELAY_MS: xdotool's delay between keys.
set -euo pipefail
log() { printf '[gui] %s\n' "$*"; }
fail() {
  printf '[gui] FAIL: %s\n' "$*" >&2
  import -window root failure.png 2>/dev/null || true
  exit 1
}

ml_pid=""
stop_meshlab() {
  [[ -n $ml_pid ]] || return 0
  kill "$ml_pid" 2>/dev/null || true
  for _ in $(seq 40); do kill -0 "$ml_pid" 2>/dev/null || break; sleep 0.25; done
  kill -9 "$ml_pid" 2>/dev/null || true
  wait "$ml_pid" 2>/dev/null || true
  ml_pid=""
}
trap stop_meshlab EXIT

alive() { kill -0 "$ml_pid" 2>/dev/null || fail "MeshLab exited (see meshlab.stderr)"; }

# wait_window REGEX SECONDS: prints the id of a visible window whose name matches.
wait_window() {
  local i id
  for ((i = 0; i < $2 * 4; ++i)); do
    alive
    id=$(xdotool search --onlyvisible --name "$1" 2>/dev/null | head -1) || true
    [[ -n $id ]] && { echo "$id"; return 0; }
    sleep 0.25
  done
  return 1
}

# wait_log REGEX SECONDS: waits for a line of MeshLab's stderr log.
wait_log() {
  local i
  for ((i = 0; i < $2 * 4; ++i)); do
    grep -qE "$1" meshlab.stderr && return 0
    alive
    sleep 0.25
  done
  return 1
}

keys() { xdotool key --clearmodifiers --delay "${KEY_DELAY_MS:-120}" "$@"; }
times() { local k=$1 n=$2; for ((j = 0; j < n; ++j)); do printf '%s ' "$k"; done; }

# start_meshlab REGEX SECONDS: $GUI opens $INPUT (stdout and stderr in meshlab.stdout
# and meshlab.stderr); main = the id of its main window, whose name matches REGEX.
start_meshlab() {
  "$GUI" "$INPUT" >meshlab.stdout 2>meshlab.stderr &
  ml_pid=$!
  main=$(wait_window "$1" "$2") || fail "no MeshLab main window ('$1') after $2 s"
}

# open_smoothing_submenu: Filters (Alt+L) opens on "Show current filter script" ("Apply
# filter" is disabled until a filter ran); 7 steps down is "Smoothing, Fairing and
# Deformation" (a fixed order: MeshLab 2020.09 mainwindow_Init.cpp, 2022.02
# MainWindow::fillFilterMenu); Right opens it on its first entry.
open_smoothing_submenu() {
  xdotool windowfocus --sync "$main"
  sleep 0.5
  keys alt+l
  sleep 1
  # shellcheck disable=SC2046
  keys $(times Down 7) Right
  sleep 1
}
