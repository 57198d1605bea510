#!/usr/bin/env bash
# detect.mlx paints and selects the chamfer and corner faces without moving
# anything; colours and selection come out in the PLY with -m vc fc ff.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

mapfile -t inputs < <(chamfered_inputs)
for in in "${inputs[@]}"; do
  n=$(basename "$in" .ply)
  run_server "$n.detect" -i "$in" -o "$n.detect.ply" -m vc fc ff -s "$SCRIPTS/detect.mlx" -l "$n.detect.log"
  ((rc == 0)) && [[ -f $n.detect.ply ]] || { cat "$n.detect.out" >&2; fail "$n: meshlabserver status $rc"; }
  grep -q '^  filters: ' "$n.detect.log" || fail "$n: no Edge-Sharpener report in the log"
  ! grep -q '^  subdivision: ' "$n.detect.log" || fail "$n: detection reports a subdivision"
  "$ES_TEST_TOOL" compare "$in" "$n.detect.ply" --rel-tol 0 || fail "$n: detection changed the geometry"
  "$ES_TEST_TOOL" info "$n.detect.ply" >"$n.detect.info"
  grep -qx 'face_color=1' "$n.detect.info" || fail "$n: no face colour in the output"
  grep -qx 'face_flags=1' "$n.detect.info" || fail "$n: no face flags in the output"
  selected=$(sed -n 's/^selected_faces=//p' "$n.detect.info")
  colours=$(sed -n 's/^face_colors=//p' "$n.detect.info")
  ((selected > 0)) || fail "$n: no chamfer/corner face selected"
  ((colours >= 2)) || fail "$n: only $colours face colour(s)"
  reported=$(sed -n 's/.* \([0-9]*\) faces selected, those Sharpen.*/\1/p' "$n.detect.log" | head -1)
  [[ -n $reported ]] && ((reported == selected)) ||
    fail "$n: $selected faces selected, the report says ${reported:-?}"
  if [[ -n ${ES_CLI:-} && -x ${ES_CLI:-} ]]; then
    "$ES_CLI" "$in" "$n.cli_detect.ply" --detect-only --colorize >"$n.cli_detect.txt" 2>&1 ||
      { cat "$n.cli_detect.txt" >&2; fail "$n: CLI --detect-only failed"; }
    "$ES_TEST_TOOL" compare "$n.detect.ply" "$n.cli_detect.ply" --rel-tol 0 --colors ||
      fail "$n: plugin and CLI paint differently"
  fi
  log "$n: $selected faces selected, $colours face colours, geometry unchanged"
done
