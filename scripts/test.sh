#!/usr/bin/env bash
# The whole test suite: installs what it needs, builds (with the Python package
# and the Blender add-on), runs CTest; then the
# core, meshes and reliability tests again under AddressSanitizer +
# UndefinedBehaviorSanitizer (build-asan/, no plugin, at -O1: half the compile time of
# Release's -O3, and what AddressSanitizer's documentation advises), then a short fuzz run
# (scripts/fuzz.sh smoke: 30 s per libFuzzer target, clang).
# ES_SKIP_SANITIZERS=1 / ES_SKIP_FUZZ=1 skip the last two stages (local runs).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EDGE_SHARPENER_BUILD_DIR:-$here/build}"
asan="${EDGE_SHARPENER_ASAN_BUILD_DIR:-$here/build-asan}"
bash "$here/scripts/build.sh" -DEDGE_SHARPENER_BUILD_TESTS=ON -DEDGE_SHARPENER_BUILD_PYTHON=ON
(cd "$build" && ctest --output-on-failure -j"$(nproc)" --timeout 900)

if [[ ${ES_SKIP_SANITIZERS:-0} != 1 ]]; then
  EDGE_SHARPENER_BUILD_DIR="$asan" bash "$here/scripts/build.sh" -DEDGE_SHARPENER_BUILD_TESTS=ON \
    -DEDGE_SHARPENER_SANITIZE=ON -DEDGE_SHARPENER_BUILD_PLUGIN=OFF -DEDGE_SHARPENER_BUILD_PYTHON=OFF \
    "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" \
    "-DEDGE_SHARPENER_TEST_AREAS=core;meshes;reliability"
  # detect_leaks: vcglib's importers and walkers are checked too.
  (cd "$asan" && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --output-on-failure -j"$(nproc)" --timeout 1800)
fi

if [[ ${ES_SKIP_FUZZ:-0} != 1 ]]; then
  bash "$here/scripts/fuzz.sh" smoke
fi
