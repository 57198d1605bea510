#!/usr/bin/env bash
# A point cloud and an inconsistently oriented mesh end in a filter error
# (non-zero exit, reason in the log, no output), not in a crash; so does a bad
# parameter value. (A non-manifold mesh is processed: non_manifold.sh.)
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

"$ES_TEST_TOOL" make-pointcloud pointcloud.ply
"$ES_TEST_TOOL" make-misoriented misoriented.ply

for in in pointcloud misoriented; do
  for script in sharpen detect; do
    n=$in.$script
    run_server "$n" -i "$in.ply" -o "$n.out.ply" -m vc fc ff -s "$SCRIPTS/$script.mlx" -l "$n.log"
    cat "$n.out" >>"$n.log"
    is_crash $rc && { cat "$n.log" >&2; fail "$n: meshlabserver crashed (status $rc)"; }
    ((rc != 0)) || fail "$n: meshlabserver succeeded on bad input"
    [[ ! -e $n.out.ply ]] || fail "$n: an output mesh was written"
    reason=$(grep -m1 'Edge-Sharpener cannot process this mesh' "$n.log") ||
      { cat "$n.log" >&2; fail "$n: the log does not say why"; }
    log "$n: refused (status $rc): ${reason#*: }"
  done
done

# Out-of-range parameter on a good mesh: refused by the core before any change.
"$ES_TEST_TOOL" make-lblock lblock.ply
sed 's/name="smoothMultiplier" type="RichFloat" value="2"/name="smoothMultiplier" type="RichFloat" value="-1"/' \
  "$SCRIPTS/sharpen.mlx" >negative_multiplier.mlx
grep -q 'value="-1"' negative_multiplier.mlx || fail "cannot derive negative_multiplier.mlx"
run_server negative_multiplier -i lblock.ply -o negative_multiplier.out.ply -s negative_multiplier.mlx \
  -l negative_multiplier.log
is_crash $rc && fail "negative multiplier: meshlabserver crashed (status $rc)"
((rc != 0)) && [[ ! -e negative_multiplier.out.ply ]] || fail "negative multiplier: accepted"
reason=$(grep -m1 'Edge-Sharpener cannot run' negative_multiplier.log) ||
  { cat negative_multiplier.log negative_multiplier.out >&2; fail "negative multiplier: the log does not say why"; }
log "negative multiplier: refused (status $rc): ${reason#*: }"
