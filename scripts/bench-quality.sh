#!/usr/bin/env bash
# The quality benchmark (issue 4): regenerates docs/results.md and docs/images/results-*.png.
#   scripts/bench-quality.sh [run.py options, e.g. --jobs 1, --models fandisk, --refresh]
# Builds the project (scripts/build.sh) into build/ (or $EDGE_SHARPENER_BUILD_DIR), then runs
# bench/quality/run.py: MeshLab-made inputs are cached in BUILD/quality-cache (--refresh remakes
# them); every run re-sharpens and re-measures. Full run: ~30 min on 2 cores.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EDGE_SHARPENER_BUILD_DIR:-$here/build}"
bash "$here/scripts/build.sh"
python=/usr/bin/python3  # Debian's, with python3-matplotlib for the figures
[[ -x $python ]] || python=python3
exec "$python" "$here/bench/quality/run.py" --build "$build" "$@"
