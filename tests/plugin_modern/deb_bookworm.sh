#!/usr/bin/env bash
# The bookworm .deb (MeshLab 2020.09) installs with apt on this host and is removed
# again at the end (also on failure; unless it was installed before the test):
# installed, the system's meshlabserver finds the filter in its own plugin folder
# and runs sharpen.mlx. The 2020.09 tests tolerate it meanwhile: their private
# prefix never links an installed copy of the plugin.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
command -v meshlabserver >/dev/null || fail "MeshLab 2020.09 is not installed on the host"
debs=("$ES_BUILD_DIR"/meshlab-2020.09/deb/meshlab-plugin-edge-sharpener_*+meshlab2020.09_amd64.deb)
deb=${debs[0]}
[[ -f $deb ]] || fail "no 2020.09 .deb in $ES_BUILD_DIR/meshlab-2020.09/deb"

was_installed=0
status=$(dpkg -s meshlab-plugin-edge-sharpener 2>/dev/null || true)
grep -q '^Status: install ok installed' <<<"$status" && was_installed=1
apt_get() { DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 -y -qq "$@"; }
remove() { ((was_installed)) || apt_get remove meshlab-plugin-edge-sharpener >/dev/null 2>&1 || true; }
trap remove EXIT
apt_get install "$deb" >install.log 2>&1 || { cat install.log >&2; fail "apt-get install $deb failed"; }
so=/usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_edge_sharpener.so
[[ -f $so ]] || fail "the .deb did not install $so"
log "installed ${deb##*/}"

mkdir -p home runtime && chmod 700 runtime
rc=0
HOME="$ES_WORK_DIR/home" XDG_RUNTIME_DIR="$ES_WORK_DIR/runtime" timeout -k 10 300 \
  xvfb-run -a -s "-screen 0 1280x1024x24" meshlabserver -i "$ES_SOURCE_DIR/test_meshes/generated/cube_mc2.ply" \
  -o "$ES_WORK_DIR/cube.ply" -s "$SCRIPTS/sharpen.mlx" -l "$ES_WORK_DIR/run.log" >server.out 2>&1 || rc=$?
((rc == 0)) || { cat server.out >&2; fail "meshlabserver status $rc"; }
grep -q "Current Plugins Dir is: /usr/lib/x86_64-linux-gnu/meshlab/plugins" server.out ||
  { cat server.out >&2; fail "meshlabserver did not use the system plugin folder"; }
grep -q '^  subdivision: ' run.log || fail "no Edge-Sharpener report in meshlabserver's log"
log "the system's meshlabserver 2020.09 finds and runs the installed filter"

remove
trap - EXIT
((was_installed)) || [[ ! -e $so ]] || fail "apt-get remove left $so behind"
log "removed again"
