#!/usr/bin/env bash
# The main job on the built-in default input: sharpens a marching-cubes
# resampling of an L-shaped block (test_meshes/generated/lblock_mc2.ply) and
# prints the Metro distance to the exact shape before and after.
# Any arguments replace the default input/output: scripts/demo.sh IN OUT [options].
# Installs and builds only what the command-line program needs, in its own
# build tree (build-demo/, or $EDGE_SHARPENER_DEMO_BUILD_DIR).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${EDGE_SHARPENER_DEMO_BUILD_DIR:-$here/build-demo}"
bash "$here/scripts/bootstrap.sh" --core
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DEDGE_SHARPENER_BUILD_TESTS=OFF \
  -DEDGE_SHARPENER_BUILD_PLUGIN=OFF >/dev/null
cmake --build "$build" --target edge-sharpener -j"$(nproc)"
if (($#)); then
  exec "$build/apps/edge-sharpener" "$@"
fi
out="$build/lblock_mc2_sharpened.ply"
"$build/apps/edge-sharpener" "$here/test_meshes/generated/lblock_mc2.ply" "$out" \
  --reference "$here/test_meshes/generated/lblock_reference.ply"
echo "sharpened mesh written to $out"
