#!/usr/bin/env bash
# The quality benchmark (issues 4, 19): regenerates docs/results.md and docs/images/results-*.png.
#   scripts/bench-quality.sh [run.py options, e.g. --jobs 1, --models fandisk, --inputs vdb,scan,
#                             --input-keys umr_1pct, --no-peer, --distance-sampling uniform, --refresh]
# Builds the project (scripts/build.sh) into build/ (or $EDGE_SHARPENER_BUILD_DIR), then runs
# bench/quality/run.py over every reference (generated shapes, test_meshes/real, ../shared/meshes
# when present; tuning and validation halves fixed in bench/quality/split.json) and every
# sampler family (MeshLab's UMR, IER, CSG, Screened Poisson, RIMLS; the project's MC; OpenVDB's
# voxel remesher, bench/samplers/vdb-remesh; TSDF depth scans, bench/samplers/tsdf_scan.py):
# inputs and MeshLab's UnSharp Mask peer outputs are cached in BUILD/quality-cache (--refresh
# remakes them); every run re-sharpens (paper, extended, auto) and
# re-measures (mesh-distance --sampling meshlab). The time of a full run is in docs/results.md.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EDGE_SHARPENER_BUILD_DIR:-$here/build}"
bash "$here/scripts/build.sh"
python=/usr/bin/python3  # Debian's, with python3-matplotlib for the figures
[[ -x $python ]] || python=python3
exec "$python" "$here/bench/quality/run.py" --build "$build" "$@"
