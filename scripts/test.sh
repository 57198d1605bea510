#!/usr/bin/env bash
# The whole test suite: installs what it needs, builds, runs CTest.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EDGE_SHARPENER_BUILD_DIR:-$here/build}"
bash "$here/scripts/build.sh" -DEDGE_SHARPENER_BUILD_TESTS=ON
cd "$build"
ctest --output-on-failure -j"$(nproc)" --timeout 900
