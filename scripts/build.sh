#!/usr/bin/env bash
# Installs dependencies (scripts/bootstrap.sh, idempotent), then configures and
# builds the project into build/ (or $EDGE_SHARPENER_BUILD_DIR).
# Extra arguments are passed to the CMake configure step.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EDGE_SHARPENER_BUILD_DIR:-$here/build}"
bash "$here/scripts/bootstrap.sh"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build" -j"$(nproc)"
