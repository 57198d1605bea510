#!/usr/bin/env bash
# The pieces a plugin for a newer MeshLab is built from, as Debian ships them:
#   meshlab-sdk.sh 2022.02   (Debian trixie)   or   meshlab-sdk.sh 2025.07   (Debian sid)
# makes $ES_SYSTEM_CACHE/meshlab-sdk-<version>/ (default /var/cache/edge-sharpener)
#   src/          the upstream tree of the source package's .orig.tar.xz (src/common, src/vcglib)
#   lib/          libmeshlab-common.so from the binary package
#   deb-version   the binary package's exact version (what the plugin's .deb depends on)
# and prints that directory. Idempotent: does nothing when the directory is complete.
# The binary packages ship no headers and `apt-get source` answers 404 for the
# .dsc, hence the .orig tarball (the build needs nothing from Debian's patches).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$here/scripts/lib-debian-scratch.sh"

version=${1:?usage: meshlab-sdk.sh 2022.02|2025.07}
case $version in
  2022.02) suite=trixie ;;
  2025.07) suite=sid ;;
  *) es_log "unknown MeshLab version '$version' (2022.02 or 2025.07)"; exit 2 ;;
esac
sdk="$ES_SYSTEM_CACHE/meshlab-sdk-$version"
mkdir -p "$ES_SYSTEM_CACHE"
exec 9>"$ES_SYSTEM_CACHE/meshlab-sdk-$version.lock"  # one maker at a time (parallel clones)
flock 9
if [[ -f $sdk/complete ]]; then
  echo "$sdk"
  exit 0
fi

mapfile -t apt_opts < <(es_scratch_apt "$suite")
work="$sdk.partial"
rm -rf "$work"
mkdir -p "$work/dl" "$work/src" "$work/lib"
es_log "fetching MeshLab $version from Debian $suite"
(cd "$work/dl" && apt-get "${apt_opts[@]}" source --download-only meshlab >/dev/null 2>&1) || true
tarball=$(ls "$work"/dl/meshlab_*.orig.tar.* 2>/dev/null | head -n1)
if [[ -z $tarball ]]; then
  es_log "Debian $suite's meshlab source tarball could not be downloaded"
  exit 1
fi
tar -xf "$tarball" -C "$work/src" --strip-components=1
(cd "$work/dl" && apt-get "${apt_opts[@]}" download meshlab >/dev/null)
deb=$(ls "$work"/dl/meshlab_*.deb | head -n1)
dpkg-deb -x "$deb" "$work/dl/pkg"
cp "$work/dl/pkg/usr/lib/x86_64-linux-gnu/meshlab/libmeshlab-common.so" "$work/lib/"
dpkg-deb -f "$deb" Version >"$work/deb-version"
found=$(head -c 7 "$work/src/ML_VERSION")
if [[ $found != "$version" ]]; then
  es_log "Debian $suite's meshlab is $found, not $version"
  exit 1
fi
rm -rf "$work/dl"
touch "$work/complete"
rm -rf "$sdk"
mv "$work" "$sdk"
es_log "MeshLab $version SDK in $sdk"
echo "$sdk"
