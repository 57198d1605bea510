#!/usr/bin/env bash
# Installs the Debian packages the project needs (idempotently) and unpacks the
# matching MeshLab 2020.09 source tree (plugin headers + vcglib) into .cache/.
# Usage: scripts/bootstrap.sh [--core]   (run as root on Debian bookworm)
#   --core: only what the command-line program needs (compiler, CMake, CLI11,
#           nlohmann-json, Eigen, the vcglib source); no MeshLab, Qt, test tools.
# Everything comes from the machine's configured Debian archive; no host name
# is written here: the deb-src entry is derived from the existing deb entry.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cache="${EDGE_SHARPENER_CACHE:-$here/.cache}"
meshlab_version="2020.09+dfsg1-2"
src_dir="$cache/meshlab-src"

core_packages=(
  cmake g++ make dpkg-dev pkg-config
  libeigen3-dev libcli11-dev nlohmann-json3-dev
)
packages=(
  "${core_packages[@]}"
  qtbase5-dev libqt5opengl5-dev libglew-dev
  libgtest-dev libbenchmark-dev
  meshlab xvfb xauth libgl1-mesa-dri xdotool imagemagick
  python3-matplotlib
  pybind11-dev python3-pybind11 python3-dev python3-numpy python3-pytest python3-venv
  python3-setuptools blender
  libopenvdb-dev python3-open3d python3-skimage
  clang libclang-rt-14-dev
)

log() { printf 'bootstrap: %s\n' "$*" >&2; }

if [[ ${1:-} == --core ]]; then
  packages=("${core_packages[@]}")
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

need_source=0
if [[ ! -f "$src_dir/vcglib/vcg/complex/complex.h" || ! -f "$src_dir/src/common/interfaces.h" ]]; then
  need_source=1
fi

if ((${#missing[@]} == 0 && need_source == 0)); then
  exit 0
fi

if [[ $EUID -ne 0 ]]; then
  log "missing packages (${missing[*]:-none}) or MeshLab source; run this script as root"
  exit 1
fi

# A deb-src twin of every Debian 'deb' source, so that 'apt-get source' works.
ensure_deb_src() {
  local out=/etc/apt/sources.list.d/edge-sharpener-deb-src.sources
  [[ -f $out ]] && return 1
  local src=/etc/apt/sources.list.d/debian.sources
  if [[ ! -f $src ]]; then
    log "cannot find $src to derive a deb-src entry from"
    exit 1
  fi
  sed -e 's/^Types:.*/Types: deb-src/' "$src" >"$out"
  return 0
}

export DEBIAN_FRONTEND=noninteractive
updated=0
if ((need_source)) && ensure_deb_src; then
  apt-get update -qq
  updated=1
fi
if ((${#missing[@]})); then
  log "installing: ${missing[*]}"
  ((updated)) || apt-get update -qq
  updated=1
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

if ((need_source)); then
  log "fetching Debian source package meshlab $meshlab_version"
  mkdir -p "$cache/dl"
  (cd "$cache/dl" && apt-get source --download-only "meshlab=$meshlab_version" >/dev/null 2>&1) || {
    ((updated)) || apt-get update -qq
    (cd "$cache/dl" && apt-get source --download-only "meshlab=$meshlab_version" >/dev/null) || {
      log "could not download the Debian source package meshlab=$meshlab_version"
      exit 1
    }
  }
  rm -rf "$src_dir"
  dpkg-source --no-check -x "$cache/dl/meshlab_${meshlab_version#*:}.dsc" "$src_dir" >/dev/null
  if [[ ! -f "$src_dir/vcglib/vcg/complex/complex.h" ]]; then
    log "unpacked source has no vcglib/ (expected $src_dir/vcglib)"
    exit 1
  fi
  log "MeshLab source (with vcglib) in $src_dir"
fi
