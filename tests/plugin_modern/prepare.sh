#!/usr/bin/env bash
# Fixture of the plugin_modern tests: builds the plugin and its .deb for the three
# MeshLab releases (scripts/build-plugins.sh, into the build dir's meshlab-<release>/)
# and makes the trixie root with MeshLab 2022.02 (scripts/trixie-root.sh: a few
# minutes the first time on a machine, nothing when it is there). releases.sh checks
# the three builds.
set -euo pipefail
: "${ES_BUILD_DIR:?}" "${ES_SOURCE_DIR:?}"
log() { printf '[prepare] %s\n' "$*"; }
fail() {
  printf '[prepare] FAIL: %s\n' "$*" >&2
  exit 1
}

start=$SECONDS
EDGE_SHARPENER_BUILD_DIR="$ES_BUILD_DIR" bash "$ES_SOURCE_DIR/scripts/build-plugins.sh" 2020.09 2022.02 2025.07
log "three builds in $((SECONDS - start)) s"
start=$SECONDS
root=$(bash "$ES_SOURCE_DIR/scripts/trixie-root.sh")
log "trixie root $root ready in $((SECONDS - start)) s"

