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

# check_selection_run RUN: "Affect only selected faces" in a real MeshLab, RUN its runner
# (run_server, run_filter). The marching-cubes bevelled block
# (test_meshes/generated/bevelled_block_mc2.ply) with the faces of its wide designed bevel
# marked in face quality (plugin_test_tool mark-faces); MeshLab's own Conditional Face
# Selection selects every other face (fq < 0.5) and Sharpen affects only the selection
# (tests/plugin/sharpen_selected.mlx). The bevel's vertices come out as they came, the log
# gives the selection, the mesh is the CLI's with --skip-faces and something was sharpened.
# Then Sharpen with the option and nothing selected: the mesh as it came, and the log says so.
check_selection_run() {
  local run=$1 generated="$ES_SOURCE_DIR/test_meshes/generated" w=$ES_WORK_DIR
  local bevel="$generated/bevelled_block_mc2_bevel.txt"
  "$ES_TEST_TOOL" mark-faces "$generated/bevelled_block_mc2.ply" "$bevel" "$w/marked.ply" ||
    fail "cannot mark the bevel's faces"
  "$run" selected -i "$w/marked.ply" -o "$w/selected.ply" -s "$ES_SOURCE_DIR/tests/plugin/sharpen_selected.mlx" \
    -l "$w/selected.log"
  ((rc == 0)) && [[ -f $w/selected.ply ]] || { cat selected.out "$w/selected.log" >&2; fail "selected: status $rc"; }
  "$ES_TEST_TOOL" kept-vertices "$w/marked.ply" "$w/selected.ply" "$bevel" >kept.txt ||
    { cat kept.txt; fail "the bevel's vertices moved"; }
  local faces listed
  faces=$("$ES_TEST_TOOL" info "$w/marked.ply" | sed -n 's/^faces=//p')
  listed=$(grep -vc '^#' "$bevel")
  grep -q "selection: $((faces - listed)) of $faces faces" "$w/selected.log" ||
    { cat "$w/selected.log" >&2; fail "the log does not give the selection ($((faces - listed)) of $faces faces)"; }
  "$ES_CLI" "$generated/bevelled_block_mc2.ply" "$w/cli.ply" --skip-faces "$bevel" >cli.txt 2>&1 ||
    { cat cli.txt >&2; fail "CLI --skip-faces failed"; }
  "$ES_TEST_TOOL" compare "$w/selected.ply" "$w/cli.ply" --rel-tol 1e-5 >compare.txt ||
    { cat compare.txt; fail "MeshLab's selection and the CLI's --skip-faces differ"; }
  local out_faces
  out_faces=$("$ES_TEST_TOOL" info "$w/selected.ply" | sed -n 's/^faces=//p')
  ((out_faces > faces)) || fail "nothing was sharpened ($faces -> $out_faces faces)"
  log "selection: $(cat kept.txt); $(grep -m1 -o 'selection: .*' "$w/selected.log"); MeshLab == CLI"

  # Nothing selected (a fresh load selects nothing).
  sed '/<filter name="Conditional Face Selection">/,/<\/filter>/d' "$ES_SOURCE_DIR/tests/plugin/sharpen_selected.mlx" \
    >"$w/sharpen_only_selected.mlx"
  grep -q '<filter name="Conditional' "$w/sharpen_only_selected.mlx" && fail "cannot derive sharpen_only_selected.mlx"
  "$run" none -i "$w/marked.ply" -o "$w/none.ply" -s "$w/sharpen_only_selected.mlx" -l "$w/none.log"
  ((rc == 0)) && [[ -f $w/none.ply ]] || { cat none.out "$w/none.log" >&2; fail "none: status $rc"; }
  grep -q 'nothing selected: the mesh is left as it came' "$w/none.log" ||
    { cat "$w/none.log" >&2; fail "nothing selected: the log does not say so"; }
  "$ES_TEST_TOOL" compare "$w/marked.ply" "$w/none.ply" --rel-tol 0 >none_compare.txt ||
    { cat none_compare.txt; fail "nothing selected, yet the mesh changed"; }
  log "nothing selected: the mesh as it came"
}
