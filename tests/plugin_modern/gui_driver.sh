#!/usr/bin/env bash
# Runs in the trixie root inside xvfb-run (started by gui.sh, in the test's work
# dir): drives MeshLab 2022.02 with xdotool (helpers in tests/lib/gui_driver.sh).
# Environment: GUI INPUT MENU_INDEX (0-based, in the Smoothing submenu)
KEY_DELAY_MS=150
source "$(dirname "${BASH_SOURCE[0]}")/../lib/gui_driver.sh"
: "${GUI:?}" "${INPUT:?}" "${MENU_INDEX:?}"
start_meshlab '^MeshLab 2022' 120
sleep 3
for _ in 1 2 3; do
  xdotool windowmove "$main" 0 0 windowsize "$main" 1280 1024
  sleep 1
done
log "MeshLab up, window $main"

# In Filters > Smoothing, Fairing and Deformation, MENU_INDEX steps down is ours.
open_smoothing_submenu
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
