#!/usr/bin/env bash
# Builds the MeshLab plugin and its .deb for each MeshLab release given
# (default: all three), one build dir each: build/meshlab-<release>/
# (or $EDGE_SHARPENER_BUILD_DIR/meshlab-<release>).
#   2020.09  Debian bookworm (this host's MeshLab)
#   2022.02  Debian trixie: headers + library via scripts/meshlab-sdk.sh; the
#            tests run it in a trixie root (scripts/trixie-root.sh)
#   2025.07  Debian sid: compile-and-link check (running it needs sid's C library)
# Prints, per release, the plugin and the .deb made.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EDGE_SHARPENER_BUILD_DIR:-$here/build}"
cache="${EDGE_SHARPENER_CACHE:-$here/.cache}"
releases=("$@")
((${#releases[@]})) || releases=(2020.09 2022.02 2025.07)

bash "$here/scripts/bootstrap.sh"
for release in "${releases[@]}"; do
  dir="$build/meshlab-$release"
  args=(-DMESHLAB_RELEASE="$release" -DCMAKE_BUILD_TYPE=Release)
  case $release in
    2020.09) args+=(-DMESHLAB_SOURCE_DIR="$cache/meshlab-src") ;;
    2022.02 | 2025.07) args+=(-DMESHLAB_SDK_DIR="$(bash "$here/scripts/meshlab-sdk.sh" "$release")") ;;
    *) echo "build-plugins.sh: unknown MeshLab release '$release'" >&2; exit 2 ;;
  esac
  cmake -S "$here/filter_edge_sharpener/package" -B "$dir" "${args[@]}" >/dev/null
  cmake --build "$dir" -j"$(nproc)"
  (cd "$dir" && cpack -G DEB >/dev/null)
  echo "MeshLab $release: $dir/libfilter_edge_sharpener.so $(ls "$dir"/deb/*.deb)"
done
