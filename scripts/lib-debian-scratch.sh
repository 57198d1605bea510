# Sourced by the scripts that reach other Debian suites (trixie, sid) than the
# host's: a scratch apt configuration under $ES_SYSTEM_CACHE/apt-<suite> that
# never touches the system's apt state. The mirror is the host's own (the URIs:
# value of /etc/apt/sources.list.d/debian.sources), read at run time.
ES_SYSTEM_CACHE="${ES_SYSTEM_CACHE:-/var/cache/edge-sharpener}"

es_log() { printf '%s: %s\n' "${0##*/}" "$*" >&2; }

# The host's Debian mirror (first URIs: line of the deb822 sources file).
es_debian_mirror() {
  local src=/etc/apt/sources.list.d/debian.sources mirror
  mirror="$(awk '/^URIs:/ {print $2; exit}' "$src" 2>/dev/null || true)"
  if [[ -z $mirror ]]; then
    es_log "cannot read the Debian mirror from $src"
    return 1
  fi
  printf '%s\n' "$mirror"
}

# es_scratch_apt SUITE: prints the apt options of a scratch configuration for
# SUITE (creating it, and running `apt-get update` on it when older than a day).
es_scratch_apt() {
  local suite=$1 dir="$ES_SYSTEM_CACHE/apt-$1" mirror
  mirror="$(es_debian_mirror)" || return 1
  mkdir -p "$dir/sources.list.d" "$dir/lists/partial" "$dir/cache/archives/partial"
  cat >"$dir/sources.list.d/$suite.sources" <<SOURCES
Types: deb deb-src
URIs: $mirror
Suites: $suite
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SOURCES
  local opts=(-o "Dir::Etc::sourcelist=/dev/null" -o "Dir::Etc::sourceparts=$dir/sources.list.d"
    -o "Dir::State::Lists=$dir/lists" -o "Dir::Cache=$dir/cache" -o "Debug::NoLocking=1"
    -o "APT::Sandbox::User=root")  # downloads go to root-owned scratch dirs
  if [[ ! -f $dir/updated || -n $(find "$dir/updated" -mmin +1440) ]]; then
    apt-get "${opts[@]}" update -qq >&2 || return 1
    touch "$dir/updated"
  fi
  printf '%s\n' "${opts[@]}"
}
