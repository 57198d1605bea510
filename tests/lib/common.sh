# shellcheck shell=bash
# Shared by the MeshLab plugin tests of both releases: sourced first by
# tests/plugin/common.sh (2020.09, meshlabserver) and tests/plugin_modern/common.sh
# (2022.02, meshlab-filter-runner in the trixie root). Each of those sets LBLOCK_RUN,
# its function that runs MeshLab (NAME ARGS...: stdout+stderr in NAME.out, status in
# $rc), and LBLOCK, the name of its resampled L-block.
set -euo pipefail

TEST_NAME=${0##*/}
TEST_NAME=${TEST_NAME%.sh}
log() { printf '[%s] %s\n' "$TEST_NAME" "$*"; }
fail() {
  printf '[%s] FAIL: %s\n' "$TEST_NAME" "$*" >&2
  exit 1
}

# make_lblock: $ES_WORK_DIR/$LBLOCK.ply, an L-shaped block of plugin_test_tool (sharp
# convex and concave edges, corners, in lblock.ply) resampled by the MeshLab under test
# with "Uniform Mesh Resampling", so that every sharp edge is chamfered.
make_lblock() {
  [[ -f $ES_WORK_DIR/$LBLOCK.ply ]] && return 0
  "$ES_TEST_TOOL" make-lblock "$ES_WORK_DIR/lblock.ply"
  "$LBLOCK_RUN" "$LBLOCK" -i "$ES_WORK_DIR/lblock.ply" -o "$ES_WORK_DIR/$LBLOCK.ply" \
    -s "$ES_SOURCE_DIR/tests/plugin/resample.mlx"
  ((rc == 0)) && [[ -f $ES_WORK_DIR/$LBLOCK.ply ]] || {
    cat "$LBLOCK.out" >&2
    fail "could not resample the L-block with Uniform Mesh Resampling (status $rc)"
  }
}

# The chamfered (marching-cubes) meshes to test on: the project's generated ones
# when present, plus the L-block resampled by MeshLab itself (make_lblock).
chamfered_inputs() {
  local f
  for f in "$ES_SOURCE_DIR"/test_meshes/generated/*_mc*.ply; do
    [[ -f $f ]] && echo "$f"
  done
  make_lblock >&2
  echo "$ES_WORK_DIR/$LBLOCK.ply"
}

# sharpen_variants: in the work dir, sharpen_colorize.mlx (colorize on) and
# sharpen_extended.mlx (the extended method), derived from the shipped sharpen.mlx.
sharpen_variants() {
  local mlx="$ES_SOURCE_DIR/filter_edge_sharpener/scripts/sharpen.mlx"
  sed 's/name="colorize" type="RichBool" value="false"/name="colorize" type="RichBool" value="true"/' \
    "$mlx" >sharpen_colorize.mlx
  grep -q 'name="colorize" type="RichBool" value="true"' sharpen_colorize.mlx || fail "cannot derive sharpen_colorize.mlx"
  sed 's/name="method" type="RichEnum" value="2"/name="method" type="RichEnum" value="1"/' \
    "$mlx" >sharpen_extended.mlx
  grep -q 'name="method" type="RichEnum" value="1"' sharpen_extended.mlx || fail "cannot derive sharpen_extended.mlx"
}

# check_spots_kept INPUT OUTPUT LOG: every face of INPUT at a non-manifold spot is in
# OUTPUT as it came (plugin_test_tool spot-faces) and LOG reports the spots.
check_spots_kept() {
  local in=$1 out=$2 log_file=$3 name=${2%.ply}
  "$ES_TEST_TOOL" spot-faces "$in" "$out" >"$name.spots" ||
    { cat "$name.spots"; fail "$name: a face at a non-manifold spot changed"; }
  grep -q 'non-manifold: ' "$log_file" || { cat "$log_file" >&2; fail "$name: the log does not report the spots"; }
  log "$name: $(cat "$name.spots"); $(grep -m1 -o 'non-manifold: .*' "$log_file")"
}
