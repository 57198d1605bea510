#!/usr/bin/env bash
# MeshLab 2022.02 (trixie root, meshlab-filter-runner) gives the CLI's results:
# Sharpen (sharpen.mlx: plain, with colours, the extended method)
# and Detect (detect.mlx, paints and selects) on the generated marching-cubes
# meshes and on an L-block resampled by stock 2022.02 Uniform Mesh Resampling.
# Compared: vertices, faces, face and vertex colours, selected faces. Then each
# method's tuning: Sharpen's advanced parameters (every tuning option of the
# CLI's --help-all, by the name of its key in camelCase; Detect has none), set
# with -p, give what the CLI's tuning flags give.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[[ -x ${ES_CLI:-} ]] || fail "the edge-sharpener CLI is not built (ES_CLI='${ES_CLI:-}')"

sharpen_variants  # sharpen_colorize.mlx, sharpen_extended.mlx

# same NAME CLI-ARGS -- COMPARE-ARGS: the runner's NAME.plugin.ply vs the CLI's NAME.cli.ply.
same() {
  local name=$1 in=$2
  shift 2
  local cli_args=() cmp_args=()
  while [[ $1 != -- ]]; do cli_args+=("$1"); shift; done
  shift
  cmp_args=("$@")
  "$ES_CLI" "$in" "$name.cli.ply" "${cli_args[@]}" >"$name.cli.txt" 2>&1 ||
    { cat "$name.cli.txt" >&2; fail "$name: CLI failed"; }
  "$ES_TEST_TOOL" compare "$name.plugin.ply" "$name.cli.ply" "${cmp_args[@]}" >"$name.compare.txt" ||
    { cat "$name.compare.txt"; fail "$name: MeshLab 2022.02 and the CLI differ"; }
}

mapfile -t inputs < <(chamfered_inputs)
((${#inputs[@]} >= 2)) || fail "no chamfered input meshes"
for in in "${inputs[@]}"; do
  n=$(basename "$in" .ply)
  in_faces=$("$ES_TEST_TOOL" info "$in" | sed -n 's/^faces=//p')

  run_filter "$n.sharpen" -i "$in" -o "$ES_WORK_DIR/$n.sharpen.plugin.ply" --mask vc,fc,ff \
    -s "$SCRIPTS/sharpen.mlx" -l "$ES_WORK_DIR/$n.sharpen.log"
  ((rc == 0)) || { cat "$n.sharpen.out" >&2; fail "$n: runner status $rc"; }
  grep -q '^  subdivision: ' "$n.sharpen.log" || fail "$n: no Edge-Sharpener report in the log"
  same "$n.sharpen" "$in" -- --rel-tol 1e-5
  out_faces=$("$ES_TEST_TOOL" info "$n.sharpen.plugin.ply" | sed -n 's/^faces=//p')
  ((out_faces > in_faces)) || fail "$n: nothing was sharpened ($in_faces -> $out_faces faces)"

  run_filter "$n.color" -i "$in" -o "$ES_WORK_DIR/$n.color.plugin.ply" --mask vc,fc,ff -s sharpen_colorize.mlx
  ((rc == 0)) || { cat "$n.color.out" >&2; fail "$n: runner (colorize) status $rc"; }
  colours=$("$ES_TEST_TOOL" info "$n.color.plugin.ply" | sed -n 's/^face_colors=//p')
  ((colours >= 2)) || fail "$n: only $colours face colour(s): verdicts not painted"
  same "$n.color" "$in" --colorize -- --rel-tol 1e-5 --colors --vertex-colors

  run_filter "$n.extended" -i "$in" -o "$ES_WORK_DIR/$n.extended.plugin.ply" --mask vc,fc,ff \
    -s sharpen_extended.mlx
  ((rc == 0)) || { cat "$n.extended.out" >&2; fail "$n: runner (extended) status $rc"; }
  same "$n.extended" "$in" --method extended -- --rel-tol 1e-5

  run_filter "$n.detect" -i "$in" -o "$ES_WORK_DIR/$n.detect.plugin.ply" --mask vc,fc,ff \
    -s "$SCRIPTS/detect.mlx" -l "$ES_WORK_DIR/$n.detect.log"
  ((rc == 0)) || { cat "$n.detect.out" >&2; fail "$n: runner (detect) status $rc"; }
  "$ES_TEST_TOOL" compare "$in" "$n.detect.plugin.ply" --rel-tol 0 >/dev/null ||
    fail "$n: detection changed the geometry"
  selected=$("$ES_TEST_TOOL" info "$n.detect.plugin.ply" | sed -n 's/^selected_faces=//p')
  ((selected > 0)) || fail "$n: no chamfer/corner face selected"
  same "$n.detect" "$in" --detect-only --colorize -- --rel-tol 0 --colors --vertex-colors --selection
  log "$n: MeshLab 2022.02 == CLI (sharpen $in_faces -> $out_faces faces, $colours face colours," \
    "extended method, detect $selected faces selected)"
done

# The tuning options: advanced parameters of Sharpen, named after their keys in camelCase.
FILTER="Edge-Sharpener: Sharpen Chamfered Edges"
in=${inputs[0]}
in_trixie "$RUNNER" --add-plugin "$PLUGIN" -i "$in" --params "$FILTER" >params.txt 2>params.err ||
  { cat params.err >&2; fail "runner --params failed"; }
in_trixie "$RUNNER" --add-plugin "$PLUGIN" -i "$in" --params "Edge-Sharpener: Detect Chamfers" \
  >detect_params.txt 2>>params.err || { cat params.err >&2; fail "runner --params (Detect) failed"; }
shown=$(awk -F'\t' '$3 == "shown" {print $1}' params.txt | tr '\n' ' ')
[[ $shown == "method smoothMultiplier edgeLengthCheck colorize colors degenerateAngleDeg Selected " ]] ||
  fail "Sharpen's shown parameters: '$shown'"
! grep -q $'\tadvanced\t' detect_params.txt || fail "Detect has advanced parameters"
"$ES_CLI" --help-all >help_all.txt
# The flags listed under the "Tuning: ..." group titles of --help-all.
tuning_flags=$(awk '/^[^ ].*:$/ { tuning = /^Tuning: / } tuning && /^  --/' help_all.txt | wc -l)
advanced=$(grep -c $'\tadvanced\t' params.txt)
((tuning_flags > 20 && advanced == tuning_flags)) ||
  fail "$advanced advanced parameters, the CLI has $tuning_flags tuning flags"
grep -qP '^maxLabelHops\tRichInt\tadvanced\tMaximum label distance$' params.txt &&
  grep -qP '^flattenRoughPlanes\tRichBool\tadvanced\t' params.txt &&
  grep -qP '^exactSamplingSpacings\tRichFloat\tadvanced\t' params.txt ||
  { cat params.txt; fail "tuning parameters missing or misnamed"; }
log "Sharpen: $advanced advanced (tuning) parameters, 5 shown; Detect: none advanced"

# A tuning value reaches the core as the CLI's flag does (one of each kind).
tuned() {
  local name=$1 param=$2
  shift 2
  run_filter "$name" -i "$in" -o "$ES_WORK_DIR/$name.plugin.ply" --mask vc,fc,ff -f "$FILTER" -p "$param"
  ((rc == 0)) || { cat "$name.out" >&2; fail "$name: runner status $rc"; }
  same "$name" "$in" "$@" -- --rel-tol 1e-5
}
tuned tuned_int "minFeatureVertices=1000" --min-feature-vertices 1000
tuned tuned_real "maxFeatureOffPlaneSpacings=0.3" --feature-off-plane 0.3
tuned tuned_flag "regionPlanes=false" --local-planes-only
in_faces=$("$ES_TEST_TOOL" info "$in" | sed -n 's/^faces=//p')
out_faces=$("$ES_TEST_TOOL" info tuned_int.plugin.ply | sed -n 's/^faces=//p')
((out_faces == in_faces)) || fail "minFeatureVertices=1000 did not leave every feature ($in_faces -> $out_faces faces)"
grep -q 'LOG: .*features: 0 restored, [0-9]* left as they were: [0-9]* too short' tuned_int.out ||
  { cat tuned_int.out >&2; fail "the log does not say why the features were left"; }
log "tuning parameters (integer, real, flag) give the CLI's results; the log names the verdicts"
