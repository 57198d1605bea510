#!/usr/bin/env bash
# In MeshLab 2022.02 a point cloud, an inconsistently oriented mesh and a negative smooth-edge
# multiplier end in a filter error (MLException: non-zero exit, reason in the log),
# never a crash, and the mesh is left as it was (saved with --save-on-error and
# compared with the input: same geometry, no colour layer added).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

"$ES_TEST_TOOL" make-pointcloud pointcloud.ply
"$ES_TEST_TOOL" make-misoriented misoriented.ply
"$ES_TEST_TOOL" make-lblock lblock.ply
sed 's/name="smoothMultiplier" type="RichFloat" value="2"/name="smoothMultiplier" type="RichFloat" value="-1"/' \
  "$SCRIPTS/sharpen.mlx" >negative_multiplier.mlx
grep -q 'value="-1"' negative_multiplier.mlx || fail "cannot derive negative_multiplier.mlx"

# refused NAME INPUT SCRIPT EXPECTED-REASON
refused() {
  local n=$1 in=$2 script=$3 reason=$4
  run_filter "$n" -i "$ES_WORK_DIR/$in" -o "$ES_WORK_DIR/$n.left.ply" --save-on-error --mask vc,fc,ff \
    -s "$script"
  is_crash $rc && { cat "$n.out" >&2; fail "$n: crashed (status $rc)"; }
  ((rc == 1)) || { cat "$n.out" >&2; fail "$n: status $rc, expected 1 (filter error)"; }
  grep -q "filter 'Edge-Sharpener: .*' failed: $reason" "$n.out" ||
    { cat "$n.out" >&2; fail "$n: no '$reason' filter error"; }
  "$ES_TEST_TOOL" compare "$in" "$n.left.ply" --rel-tol 0 >"$n.compare.txt" ||
    { cat "$n.compare.txt"; fail "$n: the refused mesh changed"; }
  "$ES_TEST_TOOL" info "$n.left.ply" >"$n.info"
  grep -qx 'face_color=0' "$n.info" && grep -qx 'vertex_color=0' "$n.info" ||
    fail "$n: the refused mesh got colour layers"
  log "$n: refused, mesh unchanged: $(grep -o "failed: .*" "$n.out" | head -1)"
}

for script in sharpen detect; do
  refused "pointcloud.$script" pointcloud.ply "$SCRIPTS/$script.mlx" "Edge-Sharpener cannot process this mesh"
  refused "misoriented.$script" misoriented.ply "$SCRIPTS/$script.mlx" "Edge-Sharpener cannot process this mesh"
done
refused negative_multiplier lblock.ply "$ES_WORK_DIR/negative_multiplier.mlx" "Edge-Sharpener cannot run"

# A parameter the filter does not have is an error too (runner, before any filter).
run_filter unknown_parameter -i "$ES_WORK_DIR/lblock.ply" -f "Edge-Sharpener: Sharpen Chamfered Edges" \
  -p noSuchParameter=1
((rc == 2)) && grep -q "has no parameter 'noSuchParameter'" unknown_parameter.out ||
  { cat unknown_parameter.out >&2; fail "unknown parameter: status $rc"; }
# -f with -p sets a parameter by name: the negative multiplier again.
run_filter negative_by_name -i "$ES_WORK_DIR/lblock.ply" -f "Edge-Sharpener: Sharpen Chamfered Edges" \
  -p smoothMultiplier=-1
((rc == 1)) && grep -q "Edge-Sharpener cannot run" negative_by_name.out ||
  { cat negative_by_name.out >&2; fail "-p smoothMultiplier=-1: status $rc"; }
log "unknown and bad parameters given with -f/-p are refused"
