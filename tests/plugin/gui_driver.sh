#!/usr/bin/env bash
# Runs inside xvfb-run (started by gui.sh, in the test's work dir): drives the
# real MeshLab GUI with xdotool (helpers in tests/lib/gui_driver.sh).
# Environment: GUI INPUT FILTER MENU_INDEX PARAM_INDEX PARAM_COUNT
source "$(dirname "${BASH_SOURCE[0]}")/../lib/gui_driver.sh"
: "${GUI:?}" "${INPUT:?}" "${FILTER:?}" "${MENU_INDEX:?}" "${PARAM_INDEX:?}" "${PARAM_COUNT:?}"
start_meshlab '^MeshLab 20' 90
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

# In Filters > Smoothing, Fairing and Deformation, MENU_INDEX steps down is our filter
# (order from list_filter_menu).
dlg=""
for attempt in 1 2 3; do
  keys Escape Escape Escape
  open_smoothing_submenu
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
