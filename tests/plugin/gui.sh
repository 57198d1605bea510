#!/usr/bin/env bash
# GUI: the real `meshlab` under Xvfb loads the plugin without errors on stderr;
# xdotool opens a chamfered mesh, finds "Edge-Sharpener: Sharpen Chamfered Edges"
# in Filters > Smoothing, Fairing and Deformation, ticks Colorize and applies it;
# the screenshot (imagemagick) must show the painted verdicts (restored features
# green). Screenshots are kept in the test's work dir (build tree):
# meshlab-sharpen.png is the final one.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
for tool in xdotool import convert; do
  command -v $tool >/dev/null || fail "$tool not found (Debian packages xdotool, imagemagick)"
done
[[ -n ${ES_MENU_TOOL:-} && -x ${ES_MENU_TOOL:-} ]] || fail "list_filter_menu not built"

FILTER="Edge-Sharpener: Sharpen Chamfered Edges"
PARAMS=(method smoothMultiplier edgeLengthCheck colorize colors degenerateAngleDeg Selected)  # dialog order

# Position of the filter in its submenu (0x80 = Smoothing class), as the GUI sorts it.
rc=0
timeout -k 10 120 xvfb-run -a "$ES_MENU_TOOL" "$ES_MESHLAB_PREFIX/lib/x86_64-linux-gnu/meshlab/plugins" 0x80 \
  >smoothing_menu.txt 2>list_filter_menu.err || rc=$?
((rc == 0)) || { cat list_filter_menu.err >&2; fail "list_filter_menu failed ($rc)"; }
index=$(grep -nxF "$FILTER" smoothing_menu.txt | cut -d: -f1) || fail "'$FILTER' not in the Smoothing submenu"
colorize_index=0
while [[ ${PARAMS[$colorize_index]} != colorize ]]; do colorize_index=$((colorize_index + 1)); done

make_lblock
for attempt in 1 2; do  # a second, clean MeshLab if the first one loses the race with Xvfb
  rc=0
  GUI="$GUI" INPUT="$ES_WORK_DIR/lblock_mc.ply" FILTER="$FILTER" MENU_INDEX=$((index - 1)) \
    PARAM_INDEX=$colorize_index PARAM_COUNT=${#PARAMS[@]} \
    timeout -k 15 420 xvfb-run -a -s "-screen 0 1280x1024x24" \
    bash "$ES_SOURCE_DIR/tests/plugin/gui_driver.sh" >"gui_driver.$attempt.log" 2>&1 || rc=$?
  cat "gui_driver.$attempt.log"
  ((rc == 0)) && break
  is_crash $rc && [[ $rc != 124 ]] && break  # a crash is a real failure: no retry
done
((rc == 0)) || fail "GUI run failed (status $rc); screenshots in $ES_WORK_DIR"

# The plugin loaded silently: MeshLab's stderr has no error line, and the filter's
# report reached the log.
grep -iE 'error|fail|cannot|abort|assert|segmentation|undefined symbol|QPluginLoader' meshlab.stderr |
  grep -v '^Current Plugins Dir is: ' >stderr_problems.txt || true
[[ ! -s stderr_problems.txt ]] || { cat stderr_problems.txt >&2; fail "MeshLab wrote errors on stderr"; }
grep -q 'LOG: .*subdivision: ' meshlab.stderr || fail "no Edge-Sharpener report in MeshLab's log"

# The painted verdicts are on screen: the restored features are green (40, 170, 70),
# so the 3D view goes from (almost) no green pixel to some.
green_fraction() {
  convert "$1" -crop 840x780+5+75 +repage \
    -fx '(g > 0.3 && g > 1.6 * r && g > 1.6 * b) ? 1 : 0' -format '%[fx:mean]' info:
}
before=$(green_fraction before.png)
after=$(green_fraction meshlab-sharpen.png)
log "green pixels in the 3D view: $before before, $after after"
awk -v b="$before" -v a="$after" 'BEGIN { exit !(b < 0.002 && a > 0.01) }' ||
  fail "the screenshot does not show the painted verdicts (green fraction $before -> $after)"
log "screenshot: $ES_WORK_DIR/meshlab-sharpen.png"
