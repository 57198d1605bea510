#!/usr/bin/env bash
# The shipped .mlx scripts run unchanged in MeshLab 2022.02: sharpen.mlx,
# detect.mlx, and resample_sharpen_hausdorff.mlx (stock Transform, Uniform Mesh
# Resampling and Hausdorff Distance around ours: the RMS distance to the
# original drops, the max does not grow).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

make_lblock
for script in sharpen detect; do
  run_filter "$script" -i "$ES_WORK_DIR/lblock_umr.ply" -o "$ES_WORK_DIR/$script.ply" \
    -s "$SCRIPTS/$script.mlx" -l "$ES_WORK_DIR/$script.log"
  ((rc == 0)) && [[ -f $script.ply ]] || { cat "$script.out" >&2; fail "$script.mlx: runner status $rc"; }
  grep -q '^  filters: ' "$script.log" || fail "$script.mlx: no Edge-Sharpener report in the log"
  log "$script.mlx ran"
done

run_filter pipeline -i "$ES_WORK_DIR/lblock.ply" -o "$ES_WORK_DIR/pipeline.ply" \
  -s "$SCRIPTS/resample_sharpen_hausdorff.mlx" -l "$ES_WORK_DIR/pipeline.log"
((rc == 0)) && [[ -f pipeline.ply ]] || { cat pipeline.out >&2; fail "resample_sharpen_hausdorff.mlx: status $rc"; }
grep -q '^  subdivision: ' pipeline.log || fail "pipeline: no Edge-Sharpener report"
# Hausdorff Distance logs "min : A   max B   mean : C   RMS : D" in absolute units,
# then relative to the bbox: 4 one-sided runs, 2 before and 2 after sharpening.
mapfile -t rows < <(grep -E '^ +min : ' pipeline.log | awk 'NR % 2 == 1 {print $5, $11}')
((${#rows[@]} == 4)) || { cat pipeline.log >&2; fail "pipeline: ${#rows[@]} Hausdorff results, expected 4"; }
read -r max_b rms_b max_a rms_a < <(printf '%s\n' "${rows[@]}" | awk '
  { m[NR] = $1; r[NR] = $2 }
  END { print (m[1] > m[2] ? m[1] : m[2]), (r[1] > r[2] ? r[1] : r[2]),
              (m[3] > m[4] ? m[3] : m[4]), (r[3] > r[4] ? r[3] : r[4]) }')
awk -v b="$rms_b" -v a="$rms_a" 'BEGIN { exit !(a < b) }' ||
  fail "pipeline: sharpening did not reduce the two-sided RMS distance ($rms_b -> $rms_a)"
awk -v b="$max_b" -v a="$max_a" 'BEGIN { exit !(a <= b) }' ||
  fail "pipeline: sharpening increased the two-sided max distance ($max_b -> $max_a)"
log "resample_sharpen_hausdorff.mlx: two-sided Hausdorff max $max_b -> $max_a, RMS $rms_b -> $rms_a"
