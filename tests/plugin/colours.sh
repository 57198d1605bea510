#!/usr/bin/env bash
# A coloured mesh through sharpen.mlx (the default method): MeshLab's vertex
# colours come out with every new vertex coloured from the vertices it was made
# between (no white vertex: vcglib's default), the same colours as the CLI
# gives, and unmoved vertices keep theirs.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

mapfile -t inputs < <(chamfered_inputs)
for in in "${inputs[@]}"; do
  n=$(basename "$in" .ply)
  "$ES_TEST_TOOL" paint-gradient "$in" "$n.coloured.ply" || fail "$n: cannot paint the input"
  run_server "$n.sharpen" -i "$n.coloured.ply" -o "$n.sharpened.ply" -m vc \
    -s "$SCRIPTS/sharpen.mlx" -l "$n.sharpen.log"
  ((rc == 0)) && [[ -f $n.sharpened.ply ]] || { cat "$n.sharpen.out" >&2; fail "$n: meshlabserver status $rc"; }
  "$ES_TEST_TOOL" info "$n.coloured.ply" >"$n.coloured.info"
  "$ES_TEST_TOOL" info "$n.sharpened.ply" >"$n.sharpened.info"
  grep -qx 'vertex_color=1' "$n.sharpened.info" || fail "$n: no vertex colour in the output"
  grep -qx 'white_vertices=0' "$n.sharpened.info" || fail "$n: white vertices in the output: $(grep white "$n.sharpened.info")"
  before=$(sed -n 's/^vertices=//p' "$n.coloured.info")
  after=$(sed -n 's/^vertices=//p' "$n.sharpened.info")
  ((after > before)) || fail "$n: nothing was added ($before -> $after vertices)"
  if [[ -n ${ES_CLI:-} && -x ${ES_CLI:-} ]]; then
    "$ES_CLI" "$n.coloured.ply" "$n.cli.ply" >"$n.cli.txt" 2>&1 || { cat "$n.cli.txt" >&2; fail "$n: CLI failed"; }
    "$ES_TEST_TOOL" compare "$n.sharpened.ply" "$n.cli.ply" --vertex-colors ||
      fail "$n: plugin and CLI colour the vertices differently"
  fi
  log "$n: $before -> $after vertices, every one coloured as the CLI colours it"
done
