#!/usr/bin/env bash
# The trixie .deb installs with apt into the trixie root (MeshLab 2022.02) and
# removes again; installed, MeshLab finds the filter in its own plugin folder: the
# installed meshlab-filter-runner lists it (no --add-plugin) and runs sharpen.mlx;
# a build given with --add-plugin then replaces the installed copy.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
debs=("$MODERN_BUILD"/deb/meshlab-plugin-edge-sharpener_*+meshlab2022.02_amd64.deb)
deb=${debs[0]}
[[ -f $deb ]] || fail "no 2022.02 .deb in $MODERN_BUILD/deb"

remove() { in_trixie env DEBIAN_FRONTEND=noninteractive apt-get remove -y -qq meshlab-plugin-edge-sharpener >/dev/null 2>&1 || true; }
trap remove EXIT
in_trixie env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$deb" >install.log 2>&1 ||
  { cat install.log >&2; fail "apt-get install $deb failed in the trixie root"; }
status=$(in_trixie dpkg -s meshlab-plugin-edge-sharpener)
grep -q '^Status: install ok installed' <<<"$status" || fail "not installed"
log "installed ${deb##*/}"

in_trixie meshlab-filter-runner --list >list.txt 2>list.err || { cat list.err >&2; fail "installed runner --list failed"; }
grep -q "^Loaded [0-9]* plugins from /usr/lib/x86_64-linux-gnu/meshlab/plugins" list.txt ||
  fail "the installed runner did not use MeshLab's plugin folder"
for name in "Edge-Sharpener: Sharpen Chamfered Edges	sharpen_chamfered_edges" \
  "Edge-Sharpener: Detect Chamfers	detect_chamfers"; do
  grep -qF "$name" list.txt || fail "the installed MeshLab does not list '${name%%	*}'"
done
in_trixie meshlab-filter-runner -i "$ES_SOURCE_DIR/test_meshes/generated/cube_mc2.ply" \
  -o "$ES_WORK_DIR/cube.ply" -s "$SCRIPTS/sharpen.mlx" >run.out 2>&1 ||
  { cat run.out >&2; fail "the installed plugin did not run sharpen.mlx"; }
grep -q 'subdivision: ' run.out || fail "no Edge-Sharpener report"
log "MeshLab 2022.02 finds and runs the installed filter (PyMeshLab names listed too)"
# A build given with --add-plugin replaces the installed copy: each filter once.
in_trixie "$RUNNER" --add-plugin "$PLUGIN" --list >list_both.txt 2>list_both.err ||
  { cat list_both.err >&2; fail "runner --add-plugin with the package installed failed"; }
count=$(grep -c '^Edge-Sharpener: Sharpen Chamfered Edges	' list_both.txt || true)
((count == 1)) || fail "with the package installed, --add-plugin lists the filter $count times"

remove
trap - EXIT
! in_trixie test -e /usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_edge_sharpener.so ||
  fail "apt-get remove left the plugin behind"
log "removed again"
