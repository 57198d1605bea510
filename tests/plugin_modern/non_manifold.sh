#!/usr/bin/env bash
# Meshes with non-manifold spots are processed in MeshLab 2022.02 (issue 59): the
# marching-cubes L-block with a non-manifold vertex and edge
# (test_meshes/generated/lblock_mc2_spots.ply) and a tetrahedron with a fin. Sharpen and
# Detect succeed; the faces at the spots come out as they came (plugin_test_tool
# spot-faces); the log says where they are; Sharpen gives the CLI's mesh.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[[ -x ${ES_CLI:-} ]] || fail "the edge-sharpener CLI is not built (ES_CLI='${ES_CLI:-}')"

cp "$ES_SOURCE_DIR/test_meshes/generated/lblock_mc2_spots.ply" spots.ply
"$ES_TEST_TOOL" make-nonmanifold fin.ply
for n in spots fin; do
  for script in sharpen detect; do
    run_filter "$n.$script" -i "$ES_WORK_DIR/$n.ply" -o "$ES_WORK_DIR/$n.$script.ply" --mask vc,fc,ff \
      -s "$SCRIPTS/$script.mlx" -l "$ES_WORK_DIR/$n.$script.log"
    ((rc == 0)) && [[ -f $n.$script.ply ]] || { cat "$n.$script.out" >&2; fail "$n.$script: runner status $rc"; }
    check_spots_kept "$n.ply" "$n.$script.ply" "$n.$script.log"
  done
  "$ES_CLI" "$n.ply" "$n.cli.ply" >"$n.cli.txt" 2>&1 || { cat "$n.cli.txt" >&2; fail "$n: CLI failed"; }
  "$ES_TEST_TOOL" compare "$n.sharpen.ply" "$n.cli.ply" --rel-tol 1e-5 >"$n.compare.txt" ||
    { cat "$n.compare.txt"; fail "$n: MeshLab 2022.02 and the CLI differ"; }
done
in_faces=$("$ES_TEST_TOOL" info spots.ply | sed -n 's/^faces=//p')
out_faces=$("$ES_TEST_TOOL" info spots.sharpen.ply | sed -n 's/^faces=//p')
((out_faces > in_faces)) || fail "spots: nothing was sharpened ($in_faces -> $out_faces faces)"
log "spots: $in_faces -> $out_faces faces, MeshLab 2022.02 == CLI"
