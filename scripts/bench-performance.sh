#!/usr/bin/env bash
# Performance benchmark of Edge-Sharpener (issue 5), one command:
#   scripts/bench-performance.sh
# Builds the benchmarks (bench/) in build-bench/, makes the benchmark meshes
# (marching cubes of a shape with sharp features, ~10k/100k/1M/4M faces; cached),
# runs Google Benchmark (core, stages, and the floor: vcglib FF + face normals),
# the CLI end to end under /usr/bin/time -v, and meshlabserver when the plugin's
# private MeshLab prefix builds, then writes docs/performance.md and
# docs/images/performance.png. Takes about 10 minutes. Not part of CTest.
# Environment:
#   EDGE_SHARPENER_BENCH_BUILD_DIR  build directory (default: build-bench)
#   BENCH_SIZES                     face counts (default: "10000 100000 1000000 4000000")
#   BENCH_REPETITIONS               Google Benchmark repetitions, medians reported (default: 3)
#   BENCH_MESHLAB=0                 skip the meshlabserver measurement
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EDGE_SHARPENER_BENCH_BUILD_DIR:-$here/build-bench}"
sizes="${BENCH_SIZES:-10000 100000 1000000 4000000}"
reps="${BENCH_REPETITIONS:-3}"
out="$build/bench-results"
meshes="$build/bench-meshes"

bash "$here/scripts/bootstrap.sh"
plugin=OFF
[ "${BENCH_MESHLAB:-1}" != 0 ] && command -v meshlabserver >/dev/null && plugin=ON
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DEDGE_SHARPENER_BUILD_BENCH=ON \
  -DEDGE_SHARPENER_BUILD_TESTS=OFF -DEDGE_SHARPENER_BUILD_PLUGIN=$plugin >/dev/null
cmake --build "$build" -j"$(nproc)" --target make-bench-mesh edge-sharpener-bench mesh-roundtrip \
  bench-report edge-sharpener
mkdir -p "$out" "$meshes"

# --- Meshes (cached: the 4M one takes about half a minute).
list=()
for n in $sizes; do
  mesh="$meshes/lblock_tilted_$n.ply"
  [ -s "$mesh" ] || "$build/bench/make-bench-mesh" "$mesh" "$n"
  list+=("$mesh")
done
joined="$(IFS=,; echo "${list[*]}")"

# --- Google Benchmark: medians of $reps repetitions, interleaved at random so that a
# change in the shared machine's load falls on every benchmark alike.
echo "== Google Benchmark (${reps} repetitions)"
"$build/bench/edge-sharpener-bench" --meshes="$joined" --benchmark_repetitions="$reps" \
  --benchmark_report_aggregates_only=true --benchmark_enable_random_interleaving=true \
  --benchmark_out="$out/bench.json" \
  --benchmark_out_format=json --benchmark_counters_tabular=true

# --- CLI end to end: wall time (best of 2) and peak RSS, beside read+write only.
timed() {  # timed LOG CMD...: runs CMD under /usr/bin/time -v; prints "seconds kbytes"
  local log="$1"; shift
  /usr/bin/time -v "$@" 2>"$log" >/dev/null
  awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, p, ":"); s = 0;
                 for (i = 1; i <= n; ++i) s = s * 60 + p[i]; wall = s }
              /Maximum resident set size/ { rss = $2 }
              END { printf "%s %s\n", wall, rss }' "$log"
}
best() {  # best LOG CMD...: min wall of two runs, max RSS
  local a b
  a=$(timed "$@"); b=$(timed "$@")
  echo "$a $b" | awk '{ w = $1 < $3 ? $1 : $3; r = $2 > $4 ? $2 : $4; print w, r }'
}
echo "== CLI end to end"
: >"$out/cli.tsv"
for mesh in "${list[@]}"; do
  faces=$(awk '/^element face/ { print $3; exit }' "$mesh")
  rt=$(best "$out/time-roundtrip.log" "$build/bench/mesh-roundtrip" "$mesh" "$out/roundtrip.ply")
  cli=$(best "$out/time-cli.log" "$build/apps/edge-sharpener" -q "$mesh" "$out/sharpened.ply")
  echo "$faces $rt $cli" | tee -a "$out/cli.tsv"
done
rm -f "$out/roundtrip.ply" "$out/sharpened.ply"

# --- meshlabserver: "Select Crease Edges" then our Sharpen in one run, ~1M faces.
meshlab_args=()
measure_meshlab() {
  local prefix="$build/meshlab-prefix"
  if [ "$plugin" != ON ]; then echo "skipped: meshlabserver not installed or BENCH_MESHLAB=0"; return; fi
  if ! cmake --build "$build" -j"$(nproc)" --target meshlab_private_prefix >"$out/plugin-build.log" 2>&1 \
      || [ ! -x "$prefix/bin/meshlabserver" ]; then
    echo "skipped: the plugin's private MeshLab prefix (target meshlab_private_prefix) did not build, see $out/plugin-build.log"
    return
  fi
  local mlx="$out/crease_then_sharpen.mlx"
  # Our filter's block comes from the plugin's own script (every parameter written).
  {
    echo '<!DOCTYPE FilterScript>'
    echo '<FilterScript>'
    echo ' <filter name="Select Crease Edges">'
    echo '  <Param name="AngleDegNeg" type="RichFloat" value="-45" description="Concave Angle Thr. (deg)"/>'
    echo '  <Param name="AngleDegPos" type="RichFloat" value="45" description="Convex Angle Thr. (deg)"/>'
    echo ' </filter>'
    sed -n '/<filter /,/<\/filter>/p' "$here/filter_edge_sharpener/scripts/sharpen.mlx"
    echo '</FilterScript>'
  } >"$mlx"
  local n faces mesh
  for n in $sizes; do
    [ "$n" -ge 100000 ] && [ "$n" -le 1000000 ] || continue
    mesh="$meshes/lblock_tilted_$n.ply"
    faces=$(awk '/^element face/ { print $3; exit }' "$mesh")
    # meshlabserver logs no filter times: stamp each output line as it arrives.
    (cd "$out" && timeout 600 xvfb-run -a stdbuf -oL -eL "$prefix/bin/meshlabserver" -i "$mesh" \
        -o "$out/meshlab_out.ply" -s "$mlx" 2>&1 || true) |
      while IFS= read -r line; do echo "$(date +%s.%N) $line"; done >"$out/meshlab-$n.log"
    awk -v faces="$faces" '
      /filter: Select Crease Edges/ && !c0 { c0 = $1; next }
      /filter: Edge-Sharpener/ && !s0 { s0 = $1; next }
      s0 && !s1 && (/ LOG: / || / saved as /) { s1 = $1 }
      END { if (c0 && s0 && s1) printf "%d %.3f %.3f\n", faces, s0 - c0, s1 - s0;
            else print "skipped: meshlabserver did not run both filters (see meshlab-*.log)" }' \
      "$out/meshlab-$n.log"
  done
  rm -f "$out/meshlab_out.ply"
}
echo "== meshlabserver"
measure_meshlab | tee "$out/meshlab.tsv"
grep -q '^skipped' "$out/meshlab.tsv" && sed -i -n '/^skipped/{p;q}' "$out/meshlab.tsv"

# --- Machine and report.
{
  echo "CPU: $(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo), $(nproc) cores"
  echo "Memory: $(awk '/MemTotal/ { printf "%.1f GB", $2 / 1048576 }' /proc/meminfo)"
  echo "OS: $(. /etc/os-release && echo "$PRETTY_NAME"), kernel $(uname -r)"
  echo "Compiler: $(c++ --version | head -1), -O3 (CMake Release), OpenMP"
  echo "Load average when the report was written: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "Date: $(date -u +%Y-%m-%d)"
} >"$out/machine.txt"
mkdir -p "$here/docs/images"
"$build/bench/bench-report" --bench "$out/bench.json" --cli "$out/cli.tsv" \
  --meshlab "$out/meshlab.tsv" --machine "$out/machine.txt" \
  --md "$here/docs/performance.md" --png "$here/docs/images/performance.png" >/dev/null
echo "wrote docs/performance.md and docs/images/performance.png"
