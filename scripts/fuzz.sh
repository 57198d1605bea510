#!/usr/bin/env bash
# Builds and runs the libFuzzer targets of fuzz/ (clang, ASan+UBSan) in
# build-fuzz/ (or $EDGE_SHARPENER_FUZZ_DIR).
#   scripts/fuzz.sh build                  configure + build only
#   scripts/fuzz.sh run SECONDS [TARGET..] fuzz each target SECONDS (default: all)
#   scripts/fuzz.sh smoke                  fixed seed and input count per target (the test suite's run)
#   scripts/fuzz.sh merge                  minimise the working corpus into
#                                          tests/reliability/fuzz_corpus/ (keeps old entries)
# Seeds: tests/reliability/fuzz_corpus/TARGET/ and tests/reliability/crashes/TARGET/
# (fixed reproducers). A run fails (exit 1) when the fuzzer finds a crash, a
# leak, undefined behaviour or a broken invariant; the reproducer is left in
# build-fuzz/artifacts/TARGET/ (move it to tests/reliability/crashes/TARGET/ once fixed).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EDGE_SHARPENER_FUZZ_DIR:-$here/build-fuzz}"
data="$here/tests/reliability"
targets=(fuzz_read_mesh fuzz_core_soup fuzz_distance)

log() { printf 'fuzz: %s\n' "$*" >&2; }

do_build() {
  command -v clang++ >/dev/null || { log "clang++ not found (apt-get install clang libclang-rt-14-dev)"; exit 1; }
  cmake -S "$here/fuzz" -B "$build" -DCMAKE_CXX_COMPILER=clang++ >/dev/null
  cmake --build "$build" -j2 >/dev/null
}

run_target() {
  local target=$1 seconds=$2 extra=()
  # The smoke run is reproducible: fixed seed and a fixed number of inputs
  # (fresh working corpus), so CI explores exactly what was checked here.
  if [[ $smoke == 1 ]]; then
    extra=(-seed=1 "-runs=${SMOKE_RUNS[$target]}")
    rm -rf "$build/corpus/$target"
  fi
  local corpus="$build/corpus/$target" artifacts="$build/artifacts/$target/"
  mkdir -p "$corpus" "$artifacts"
  local seeds=("$data/fuzz_corpus/$target")
  [[ -d $data/crashes/$target ]] && seeds+=("$data/crashes/$target")
  local out="$build/$target.log" rc=0
  # -rss_limit_mb: a huge declared element count must not exhaust the machine.
  "$build/$target" "$corpus" "${seeds[@]}" -max_total_time="$seconds" -timeout=20 \
    -rss_limit_mb=2048 -max_len=8192 -artifact_prefix="$artifacts" -print_final_stats=1 \
    "${extra[@]}" \
    >"$out" 2>&1 || rc=$?
  local execs
  execs=$(grep -m1 'stat::number_of_executed_units' "$out" | awk '{print $2}')
  if ((rc != 0)); then
    tail -n 60 "$out" >&2
    log "$target: FAILED after ${execs:-?} executions (log $out, reproducer in $artifacts)"
    return 1
  fi
  log "$target: $seconds s, ${execs:-?} executions, no crash (corpus $(ls "$corpus" | wc -l) files)"
}

cmd=${1:-smoke}
case $cmd in
  build) do_build ;;
  run | smoke)
    seconds=120  # smoke: a cap; the run count below ends it first
    smoke=0
    if [[ $cmd == smoke ]]; then
      smoke=1
      declare -A SMOKE_RUNS=([fuzz_read_mesh]=2000 [fuzz_core_soup]=100000 [fuzz_distance]=10000)
    fi
    if [[ $cmd == run ]]; then
      seconds=${2:?usage: fuzz.sh run SECONDS [TARGET...]}
      shift 2
      (($#)) && targets=("$@")
    fi
    do_build
    status=0
    for t in "${targets[@]}"; do run_target "$t" "$seconds" || status=1; done
    exit $status
    ;;
  merge)
    do_build
    for t in "${targets[@]}"; do
      [[ -d $build/corpus/$t ]] || continue
      "$build/$t" -merge=1 -max_len=8192 "$data/fuzz_corpus/$t" "$build/corpus/$t" >/dev/null 2>&1
      log "$t: corpus now $(ls "$data/fuzz_corpus/$t" | wc -l) files"
    done
    ;;
  *) log "unknown command $cmd"; exit 2 ;;
esac
