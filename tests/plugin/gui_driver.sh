#!/usr/bin/env bash
# Runs inside xvfb-run (started by gui.sh, in the test's work dir): drives the
# real MeshLab GUI with xdotool. Every wait is bounded; MeshLab is always stopped.
# Environment: GUI INPUT FILTER MENU_INDEX PARAM_INDEX PARAM_COUNT
set -euo pipefail
: "${GUI:?}" "${INPUT:?}" "${FILTER:?}" "${MENU_INDEX:?}" "${PARAM_INDEX:?}" "${PARAM_COUNT:?}"
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

keys() { xdotool key --clearmodifiers --delay 120 "$@"; }
times() { local k=$1 n=$2; for ((j = 0; j < n; ++j)); do printf '%s ' "$k"; done; }

"$GUI" "$INPUT" >meshlab.stdout 2>meshlab.stderr &
ml_pid=$!
main=$(wait_window '^MeshLab 20' 90) || fail "no MeshLab main window after 90 s"
wait_log 'All files opened' 60 || fail "MeshLab did not open $INPUT"
# No window manager under Xvfb: place and size the window ourselves, and check it
# took (MeshLab may still resize itself while it starts up).
sized=0
for _ in $(seq 20); do
  xdotool windowmove "$main" 0 0
  xdotool windowsize "$main" 1280 1024
  sleep 1
  geometry=$(xdotool getwindowgeometry "$main")
  if grep -q 'Position: 0,0' <<<"$geometry" && grep -q 'Geometry: 1280x1024' <<<"$geometry"; then
    sized=$((sized + 1))
    ((sized == 2)) && break  # stable over two checks
  else
    sized=0
  fi
done
((sized == 2)) || fail "cannot size the MeshLab window to 1280x1024: $geometry"
sleep 2  # let it lay out and render
import -window root before.png
log "MeshLab up, window $main"

# Filters (Alt+L) opens with "Show current filter script" highlighted ("Apply filter"
# is disabled until a filter ran); 7 steps down is "Smoothing, Fairing and
# Deformation" (fixed order, MeshLab 2020.09 mainwindow_Init.cpp); Right opens it
# on its first entry; MENU_INDEX steps down is our filter (order from list_filter_menu).
dlg=""
for attempt in 1 2 3; do
  keys Escape Escape Escape
  xdotool windowfocus --sync "$main"
  sleep 0.5
  keys alt+l
  sleep 1
  # shellcheck disable=SC2046
  keys $(times Down 7) Right
  sleep 1
  import -window root "menu.$attempt.png"
  # shellcheck disable=SC2046
  keys $(times Down "$MENU_INDEX") Return
  if dlg=$(wait_window "^${FILTER}\$" 15); then break; fi
  log "attempt $attempt: no '$FILTER' dialog; windows: $(xdotool search --onlyvisible --name . getwindowname %@ 2>/dev/null | tr '\n' '|')"
  dlg=""
done
[[ -n $dlg ]] || fail "could not open '$FILTER' from the Filters menu"
log "parameter dialog open (window $dlg)"

# The dialog starts with the focus on Apply; Tab goes Apply -> Default -> the
# parameters in order -> Help -> Close -> Apply.
xdotool windowfocus --sync "$dlg"
sleep 0.5
# shellcheck disable=SC2046
keys $(times Tab $((2 + PARAM_INDEX))) space
sleep 0.5
import -window root dialog.png
# shellcheck disable=SC2046
keys $(times Tab $((PARAM_COUNT - PARAM_INDEX + 2))) space
wait_log 'LOG: .*output: [0-9]+ vertices' 180 || fail "the filter did not finish (no report in the log)"
log "filter applied: $(grep -E 'LOG: .*output: ' meshlab.stderr | tail -1)"
xdotool windowunmap "$dlg"  # the dialog stays open after Apply: keep it out of the picture
sleep 2
# Cosmetic, for the picture only (the checks do not depend on it): MeshLab shows the
# new colours per vertex with smooth shading; click Shading "Face" and Color "Face"
# in the layer's render panel (positions for the 1280x1024 window) to show the
# face labels flat-shaded.
xdotool mousemove 1079 578 click 1
sleep 1
xdotool mousemove 1079 627 click 1
xdotool mousemove 1270 1010
sleep 3
import -window root meshlab-sharpen.png
log "screenshot taken"
