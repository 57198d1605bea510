#!/usr/bin/env bash
# The three builds of plugin_modern.prepare: each plugin has its release's plugin
# interface, each .deb depends on that release of meshlab (any Debian revision)
# and installs into MeshLab's plugin folder; MeshLab 2022.02 refuses the 2025.07
# build ("different version"): the release is compiled into each plugin, and the
# 2022.02 build is the one the other tests load.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

for release in 2020.09 2022.02 2025.07; do
  dir="$ES_BUILD_DIR/meshlab-$release"
  so="$dir/libfilter_edge_sharpener.so"
  [[ -f $so ]] || fail "$release: no $so"
  debs=("$dir"/deb/meshlab-plugin-edge-sharpener_*+meshlab${release}_amd64.deb)
  [[ -f ${debs[0]} ]] || fail "$release: no .deb in $dir/deb"
  next=$(awk -F. -v r="$release" 'BEGIN { split(r, p, "."); printf "%s.%02d", p[1], p[2] + 1 }')
  depends=$(dpkg-deb -f "${debs[0]}" Depends)
  [[ $depends == "meshlab (>= $release), meshlab (<< $next)" ]] || fail "$release: .deb depends on '$depends'"
  contents=$(dpkg-deb -c "${debs[0]}")
  grep -q "\./usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_edge_sharpener.so$" <<<"$contents" ||
    fail "$release: the .deb does not install into MeshLab's plugin folder"
  text=$(strings "$so")  # (not piped into grep -q: under pipefail, SIGPIPE would fail it)
  iid=vcg.meshlab.FilterPlugin/1.0
  [[ $release == 2020.09 ]] && iid=vcg.meshlab.MeshFilterInterface/1.0
  grep -qxF "$iid" <<<"$text" || fail "$release: no $iid plugin"
  log "MeshLab $release: $so, ${debs[0]##*/} (Depends: $depends)"
done

rc=0
in_trixie "$RUNNER" --add-plugin "$ES_BUILD_DIR/meshlab-2025.07/libfilter_edge_sharpener.so" --list \
  >refused.out 2>&1 || rc=$?
((rc == 2)) && grep -q 'different version from the running MeshLab' refused.out ||
  { cat refused.out >&2; fail "MeshLab 2022.02 did not refuse the 2025.07 build (status $rc)"; }
log "MeshLab 2022.02 refuses the 2025.07 build: different version"
