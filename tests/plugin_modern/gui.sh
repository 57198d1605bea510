#!/usr/bin/env bash
# The GUI of MeshLab 2022.02 (trixie root, Xvfb) loads the plugin and lists
# "Edge-Sharpener: Sharpen Chamfered Edges" in Filters > Smoothing, Fairing and
# Deformation: xdotool opens that submenu (screenshot meshlab-2022.02-menu.png in the
# work dir), walks to our entry, opens its dialog and applies it; MeshLab's log
# then holds our report, which proves the entry walked to was ours.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

FILTER="Edge-Sharpener: Sharpen Chamfered Edges"
SMOOTHING=0x80  # FilterPlugin::Smoothing: the submenu, sorted by name (MainWindow::fillFilterMenu)

# A private MeshLab prefix inside the root: a copy of meshlab (it looks for plugins
# relative to its own path) with links to the stock plugins and ours.
prefix="$ES_WORK_DIR/prefix"
in_trixie sh -ec "
  mkdir -p '$prefix/bin' '$prefix/lib/x86_64-linux-gnu/meshlab/plugins'
  cp /usr/bin/meshlab '$prefix/bin/'
  ln -sf /usr/lib/x86_64-linux-gnu/meshlab/libmeshlab-common.so '$prefix/lib/x86_64-linux-gnu/meshlab/'
  for p in /usr/lib/x86_64-linux-gnu/meshlab/plugins/*.so; do ln -sf \"\$p\" '$prefix/lib/x86_64-linux-gnu/meshlab/plugins/'; done
  ln -sf '$PLUGIN' '$prefix/lib/x86_64-linux-gnu/meshlab/plugins/'"

# Our entry's position in the submenu, from the loaded filters' names and classes.
in_trixie "$RUNNER" --add-plugin "$PLUGIN" --list >filters.txt 2>filters.err ||
  { cat filters.err >&2; fail "runner --list failed"; }
while IFS=$'\t' read -r name _ class; do
  [[ $class == 0x* ]] && ((class & SMOOTHING)) && printf '%s\n' "$name"
done <filters.txt | LC_ALL=C sort >smoothing_menu.txt
index=$(grep -nxF "$FILTER" smoothing_menu.txt | cut -d: -f1) || fail "'$FILTER' is not a Smoothing filter"
log "'$FILTER' is entry $index of $(wc -l <smoothing_menu.txt) in the Smoothing submenu"

input="$ES_SOURCE_DIR/test_meshes/generated/lblock_mc2.ply"  # a chamfered (marching-cubes) L-block
[[ -f $input ]] || fail "no $input"
rc=0
in_trixie env QT_QPA_PLATFORM=xcb timeout -k 15 420 xvfb-run -a -s "-screen 0 1280x1024x24" \
  env GUI="$prefix/bin/meshlab" INPUT="$input" MENU_INDEX=$((index - 1)) \
  bash "$ES_SOURCE_DIR/tests/plugin_modern/gui_driver.sh" >gui_driver.log 2>&1 || rc=$?
cat gui_driver.log
((rc == 0)) || fail "GUI run failed (status $rc); screenshots in $ES_WORK_DIR"

grep -iE 'unable to load|undefined symbol|different version|segmentation|abort' meshlab.stderr \
  >stderr_problems.txt || true
[[ ! -s stderr_problems.txt ]] || { cat stderr_problems.txt >&2; fail "MeshLab reported plugin problems"; }
grep -q "LOG: .*Edge-Sharpener: Sharpen Chamfered Edges" meshlab.stderr &&
  grep -q 'LOG: .*subdivision: ' meshlab.stderr || fail "the menu entry did not run our filter (no report in the log)"
[[ -s meshlab-2022.02-menu.png ]] || fail "no screenshot of the menu"
log "MeshLab 2022.02 lists and runs the filter; screenshot: $ES_WORK_DIR/meshlab-2022.02-menu.png"
