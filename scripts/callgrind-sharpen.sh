#!/usr/bin/env bash
# Instructions (callgrind Ir) spent sharpening, per method, on the 1M-face benchmark mesh
# (make-bench-mesh: marching cubes of the tilted L-block), for comparing two builds exactly.
#   scripts/callgrind-sharpen.sh BUILD_DIR [--methods paper,extended,auto] [--mesh PATH]
# BUILD_DIR holds apps/edge-sharpener (and bench/make-bench-mesh, or give --mesh). Counts only
# the sharpening call (not loading, the CLI's checks or writing): the toggle is on the mangled
# name of sharpen<...>() or, where that is inlined, of the three pipelines it picks from
# (detail::sharpenPaper/Extended/Auto). Mangled on purpose: a demangled pattern also matches
# templates instantiated with a lambda of sharpen(), which would toggle counting off inside it.
# One OpenMP thread, a fixed environment and fixed-length paths: glibc's allocator runs on the
# simulated CPU, so argv and environment lengths shift counts by up to 2e-4 otherwise.
set -euo pipefail
build="$(cd "${1:?usage: callgrind-sharpen.sh BUILD_DIR [--methods a,b] [--mesh PATH]}" && pwd)"
shift
methods=paper,extended,auto
mesh="$build/bench-meshes/lblock_tilted_1000000.ply"
while (($#)); do
  case $1 in
    --methods) methods=$2; shift 2 ;;
    --mesh) mesh=$2; shift 2 ;;
    *) echo "callgrind-sharpen.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
cli="$build/apps/edge-sharpener"
[[ -x $cli ]] || { echo "callgrind-sharpen.sh: $cli not found" >&2; exit 1; }
if nm "$cli" | grep ' _ZN14edge_sharpener7sharpenI' >/dev/null; then
  toggles=(--toggle-collect='_ZN14edge_sharpener7sharpenI*')
elif nm "$cli" | grep ' _ZN14edge_sharpener6detail11sharpenAutoI' >/dev/null; then
  toggles=(--toggle-collect='_ZN14edge_sharpener6detail12sharpenPaperI*'
           --toggle-collect='_ZN14edge_sharpener6detail15sharpenExtendedI*'
           --toggle-collect='_ZN14edge_sharpener6detail11sharpenAutoI*')
else
  echo "callgrind-sharpen.sh: no out-of-line sharpen() or pipeline in $cli" >&2
  exit 1
fi
if [[ ! -s $mesh ]]; then
  mkdir -p "$(dirname "$mesh")"
  "$build/bench/make-bench-mesh" "$mesh" 1000000
fi
tmp="$(mktemp -d /tmp/cgsharpen.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT
ln -s "$cli" "$tmp/cli"
ln -s "$(readlink -f "$mesh")" "$tmp/in.ply"
for m in ${methods//,/ }; do
  rm -f "$tmp/out.ply"  # whether it exists changes the CLI's allocations before sharpening
  env -i PATH=/usr/bin:/bin OMP_NUM_THREADS=1 \
    valgrind --tool=callgrind --callgrind-out-file="$tmp/$m.out" --collect-atstart=no \
    --demangle=no "${toggles[@]}" "$tmp/cli" "$tmp/in.ply" "$tmp/out.ply" -q --method "$m" \
    2>"$tmp/$m.log" >/dev/null
  echo "$m $(sed -n 's/.*Collected : *\([0-9]*\).*/\1/p' "$tmp/$m.log")"
done
