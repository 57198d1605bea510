#!/usr/bin/env bash
# sharpen.mlx through meshlabserver gives the same mesh as the CLI with the same
# parameters (plain, with colours, and the extended method), on chamfered marching-cubes
# meshes.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[[ -n ${ES_CLI:-} && -x ${ES_CLI:-} ]] || fail "the edge-sharpener CLI is not built (ES_CLI='${ES_CLI:-}')"

sharpen_variants  # sharpen_colorize.mlx, sharpen_extended.mlx

mapfile -t inputs < <(chamfered_inputs)
for in in "${inputs[@]}"; do
  n=$(basename "$in" .ply)
  in_faces=$("$ES_TEST_TOOL" info "$in" | sed -n 's/^faces=//p')
  log "$n: $in_faces faces"

  run_server "$n.plugin" -i "$in" -o "$n.plugin.ply" -m vc fc ff -s "$SCRIPTS/sharpen.mlx" -l "$n.plugin.log"
  ((rc == 0)) && [[ -f $n.plugin.ply ]] || { cat "$n.plugin.out" >&2; fail "$n: meshlabserver status $rc"; }
  grep -q '^  subdivision: ' "$n.plugin.log" || fail "$n: no Edge-Sharpener report in the log"
  grep -q '^  evidence: ' "$n.plugin.log" || fail "$n: no evidence guard in the log of the default method"
  "$ES_CLI" "$in" "$n.cli.ply" >"$n.cli.txt" 2>&1 || { cat "$n.cli.txt" >&2; fail "$n: CLI failed"; }
  "$ES_TEST_TOOL" compare "$n.plugin.ply" "$n.cli.ply" --rel-tol 1e-5 || fail "$n: plugin and CLI differ"
  out_faces=$("$ES_TEST_TOOL" info "$n.plugin.ply" | sed -n 's/^faces=//p')
  ((out_faces > in_faces)) || fail "$n: nothing was sharpened ($in_faces -> $out_faces faces)"

  run_server "$n.plugin_color" -i "$in" -o "$n.plugin_color.ply" -m vc fc ff -s sharpen_colorize.mlx
  ((rc == 0)) || { cat "$n.plugin_color.out" >&2; fail "$n: meshlabserver (colorize) status $rc"; }
  "$ES_CLI" "$in" "$n.cli_color.ply" --colorize >"$n.cli_color.txt" 2>&1 ||
    { cat "$n.cli_color.txt" >&2; fail "$n: CLI --colorize failed"; }
  "$ES_TEST_TOOL" info "$n.plugin_color.ply" >"$n.plugin_color.info"
  grep -qx 'face_color=1' "$n.plugin_color.info" || fail "$n: no face colour in the PLY written with -m fc"
  grep -qx 'vertex_color=1' "$n.plugin_color.info" || fail "$n: no vertex colour in the PLY written with -m vc"
  colours=$(sed -n 's/^face_colors=//p' "$n.plugin_color.info")
  ((colours >= 2)) || fail "$n: only $colours face colour(s): verdicts not painted"
  "$ES_TEST_TOOL" compare "$n.plugin_color.ply" "$n.cli_color.ply" --rel-tol 1e-5 --colors ||
    fail "$n: plugin and CLI differ with colours"

  run_server "$n.plugin_extended" -i "$in" -o "$n.plugin_extended.ply" -m vc fc ff \
    -s sharpen_extended.mlx -l "$n.plugin_extended.log"
  ((rc == 0)) || { cat "$n.plugin_extended.out" >&2; fail "$n: meshlabserver (extended) status $rc"; }
  "$ES_CLI" "$in" "$n.cli_extended.ply" --method extended >"$n.cli_extended.txt" 2>&1 ||
    { cat "$n.cli_extended.txt" >&2; fail "$n: CLI --method extended failed"; }
  "$ES_TEST_TOOL" compare "$n.plugin_extended.ply" "$n.cli_extended.ply" --rel-tol 1e-5 ||
    fail "$n: plugin and CLI differ with the extended method"
  # The parameter reaches the core: the extended method runs no evidence guard.
  grep -q '^  subdivision: ' "$n.plugin_extended.log" || fail "$n: no report in the extended log"
  ! grep -q '^  evidence: ' "$n.plugin_extended.log" || fail "$n: method=extended ran the auto method"
  log "$n: plugin == CLI ($in_faces -> $out_faces faces, $colours face colours; extended too)"
done
