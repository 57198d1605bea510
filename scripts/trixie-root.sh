#!/usr/bin/env bash
# A Debian trixie root with MeshLab 2022.02, to test the 2022.02 plugin in a real
# MeshLab (the host is bookworm, whose MeshLab is 2020.09):
#   trixie-root.sh            makes it when missing or stale; prints its path
#   trixie-root.sh run CMD..  runs CMD in it (as root, via chroot)
# The root lives outside the clone, keyed by the MeshLab version:
#   $ES_SYSTEM_CACHE/trixie-meshlab-2022.02   (default /var/cache/edge-sharpener)
# so that fresh clones on the same machine reuse it. "Stale" = made by another
# package list than the one below (the stamp file records it); the first run
# downloads a few hundred MB from the host's own Debian mirror.
# `run` mounts proc, sys, dev, /tmp and the directories listed in ES_ROOT_BINDS
# (colon-separated, each at the same path inside) in a private mount namespace
# (unshare -m): they disappear with the command, whatever way it ends.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$here/scripts/lib-debian-scratch.sh"

root="$ES_SYSTEM_CACHE/trixie-meshlab-2022.02"
# Trixie's meshlab forgets some of its plugins' libraries (without them the GUI
# reports "Unable to load the following plugins"): lib3ds-1-3 ... libxerces-c3.2t64.
packages=(meshlab xvfb xauth xdotool imagemagick libgl1-mesa-dri
  lib3ds-1-3 libgomp1 libmpfr6 libmuparser2v5 libopenctm1 libqhull-r8.0 libxerces-c3.2t64)
stamp_text="trixie minbase + ${packages[*]}"

# in_root CMD...: CMD inside the root with the mounts described above.
in_root() {
  local binds=${ES_ROOT_BINDS:-}
  unshare -m --propagation private -- bash -euo pipefail -c '
    root=$1; binds=$2; shift 2
    mount -t proc proc "$root/proc"
    mount -t sysfs sys "$root/sys"
    mount --rbind /dev "$root/dev"
    mount --bind /tmp "$root/tmp"
    IFS=: read -ra dirs <<<"$binds"
    for d in "${dirs[@]}"; do
      [[ -n $d ]] || continue
      mkdir -p "$root$d"
      mount --bind "$d" "$root$d"
    done
    exec chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
      LANG=C.UTF-8 TERM=dumb "$@"
  ' in_root "$root" "$binds" "$@"
}

make_root() {
  local mirror work="$root.partial"
  mirror="$(es_debian_mirror)"
  if [[ ! -f $work/.debootstrap-done ]]; then
    rm -rf "$work"
    # Trixie's own debootstrap (it knows trixie), unpacked, not installed.
    local dbs="$ES_SYSTEM_CACHE/debootstrap-trixie"
    if [[ ! -x $dbs/usr/sbin/debootstrap ]]; then
      local opts
      mapfile -t opts < <(es_scratch_apt trixie)
      rm -rf "$dbs.dl" && mkdir -p "$dbs.dl"
      (cd "$dbs.dl" && apt-get "${opts[@]}" download debootstrap >/dev/null)
      dpkg-deb -x "$dbs.dl"/debootstrap_*.deb "$dbs"
      rm -rf "$dbs.dl"
    fi
    es_log "debootstrap trixie into $work (a few minutes, once per machine)"
    DEBOOTSTRAP_DIR="$dbs/usr/share/debootstrap" "$dbs/usr/sbin/debootstrap" --variant=minbase \
      --keyring=/usr/share/keyrings/debian-archive-keyring.gpg trixie "$work" "$mirror" \
      >"$ES_SYSTEM_CACHE/debootstrap.log" 2>&1 ||
      { tail -20 "$ES_SYSTEM_CACHE/debootstrap.log" >&2; es_log "debootstrap failed"; exit 1; }
    touch "$work/.debootstrap-done"
  fi
  es_log "installing MeshLab 2022.02 into the trixie root"
  root="$work" in_root sh -c "DEBIAN_FRONTEND=noninteractive apt-get update -qq &&
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends ${packages[*]} >/dev/null &&
    apt-get clean"
  local got
  got=$(root="$work" in_root meshlab --version 2>/dev/null | tr -d '\r' | grep -o 'MeshLab 20[0-9.]*' || true)
  [[ $got == "MeshLab 2022.02" ]] || { es_log "the root's meshlab says '$got', not MeshLab 2022.02"; exit 1; }
  printf '%s\n' "$stamp_text" >"$work/.edge-sharpener-stamp"
  rm -rf "$root"
  mv "$work" "$root"
}

mkdir -p "$ES_SYSTEM_CACHE"
# One maker at a time (parallel tests, parallel clones on one machine).
exec 9>"$ES_SYSTEM_CACHE/trixie-root.lock"
flock 9
if [[ ! -f $root/.edge-sharpener-stamp || $(cat "$root/.edge-sharpener-stamp") != "$stamp_text" ]]; then
  [[ -d $root && ! -d $root.partial ]] && mv "$root" "$root.partial"  # stale: update it in place
  make_root
fi
flock -u 9

if [[ ${1:-} == run ]]; then
  shift
  in_root "$@"
else
  echo "$root"
fi
