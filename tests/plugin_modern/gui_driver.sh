#!/usr/bin/env bash
# Runs in the trixie root inside xvfb-run (started by gui.sh, in the test's work
# dir): drives MeshLab 2022.02 with xdotool. Every wait is bounded; MeshLab is
# always stopped. Environment: GUI INPUT MENU_INDEX (0-based, in the Smoothing submenu)
set -euo pipefail
: "${GUI:?}" "${INPUT:?}" "${MENU_INDEX:?}"
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
wait_window() {  # REGEX SECONDS: id of a visible window whose name matches
  local i id
  for ((i = 0; i < $2 * 4; ++i)); do
    alive
    id=$(xdotool search --onlyvisible --name "$1" 2>/dev/null | head -1) || true
    [[ -n $id ]] && { echo "$id"; return 0; }
    sleep 0.25
  done
  return 1
}
wait_log() {  # REGEX SECONDS
  local i
  for ((i = 0; i < $2 * 4; ++i)); do
    grep -qE "$1" meshlab.stderr && return 0
    alive
    sleep 0.25
  done
  return 1
}
keys() { xdotool key --clearmodifiers --delay 150 "$@"; }
times() { local k=$1 n=$2; for ((j = 0; j < n; ++j)); do printf '%s ' "$k"; done; }

"$GUI" "$INPUT" >meshlab.stdout 2>meshlab.stderr &
ml_pid=$!
main=$(wait_window '^MeshLab 2022' 120) || fail "no MeshLab 2022.02 main window after 120 s"
sleep 3
for _ in 1 2 3; do
  xdotool windowmove "$main" 0 0 windowsize "$main" 1280 1024
  sleep 1
done
log "MeshLab up, window $main"

# Filters (Alt+L) opens on "Show current filter script" ("Apply filter" is disabled
# until a filter ran); 7 steps down is "Smoothing, Fairing and Deformation" (fixed
# order, MeshLab 2022.02 MainWindow::fillFilterMenu); Right opens it on its first
# entry; MENU_INDEX steps down is ours.
xdotool windowfocus --sync "$main"
sleep 0.5
keys alt+l
sleep 1
# shellcheck disable=SC2046
keys $(times Down 7) Right
sleep 1
# shellcheck disable=SC2046
((MENU_INDEX == 0)) || keys $(times Down "$MENU_INDEX")
sleep 1.5  # the entry's tooltip
import -window root meshlab-2022.02-menu.png
log "menu screenshot taken"
keys Return
# The filter's parameter dialog: a floating dock window named after the filter, not
# focused; click its Apply button (bottom right of the dock).
dialog=$(wait_window "^Edge-Sharpener: Sharpen Chamfered Edges" 30) || fail "no parameter dialog"
sleep 2
import -window root dialog.png
eval "$(xdotool getwindowgeometry --shell "$dialog")"
log "parameter dialog $dialog at ${X},${Y} ${WIDTH}x${HEIGHT}"
xdotool mousemove $((X + WIDTH * 3 / 4)) $((Y + HEIGHT - 20)) click 1
wait_log 'subdivision: ' 120 || fail "the filter did not run (no report in MeshLab's log)"
sleep 2
import -window root after.png
log "filter applied from the menu"
