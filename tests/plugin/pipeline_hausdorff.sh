#!/usr/bin/env bash
# The shipped pipeline example resample_sharpen_hausdorff.mlx runs end to end on
# a sharp L-shaped block, and the Hausdorff distances it logs drop after sharpening.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

"$ES_TEST_TOOL" make-lblock lblock.ply
run_server pipeline -i lblock.ply -o sharpened.ply -m vc fc ff \
  -s "$SCRIPTS/resample_sharpen_hausdorff.mlx" -l log.txt
((rc == 0)) && [[ -f sharpened.ply ]] || { cat pipeline.out >&2; fail "meshlabserver status $rc"; }
grep -q '^  subdivision: ' log.txt || fail "no Edge-Sharpener report in the log"

# meshlabserver prints the whole log so far after every filter: read the last copy
# (after the last "filter: " line). Each "Hausdorff Distance" logs
# "min : A   max B   mean : C   RMS : D" in absolute units, then the same relative
# to the bbox diagonal. Keep the absolute lines: the 1st and 3rd (resampled ->
# original, original -> resampled) are before sharpening, the 5th and 7th after.
mapfile -t rows < <(awk '/^filter: /{n = 0; next} {l[++n] = $0} END {for (i = 1; i <= n; ++i) print l[i]}' log.txt |
  grep -E '^ +min : ' | awk 'NR % 2 == 1 {print $5, $11}')
((${#rows[@]} == 4)) || { cat log.txt >&2; fail "expected 4 Hausdorff results in the log, got ${#rows[@]}"; }
read -r max_b rms_b max_a rms_a < <(printf '%s\n' "${rows[@]}" | awk '
  NR <= 2 { mb = ($1 > mb ? $1 : mb); rb += $2 * $2 }
  NR > 2  { ma = ($1 > ma ? $1 : ma); ra += $2 * $2 }
  END { printf "%.6f %.6f %.6f %.6f\n", mb, sqrt(rb / 2), ma, sqrt(ra / 2) }')
log "two-sided Hausdorff (unit bbox): max $max_b -> $max_a, RMS $rms_b -> $rms_a"
for i in 0 1 2 3; do log "  one-sided #$((i + 1)) (max RMS): ${rows[$i]}"; done
awk -v b="$rms_b" -v a="$rms_a" 'BEGIN { exit !(a < 0.9 * b) }' ||
  fail "RMS distance did not drop by 10% after sharpening ($rms_b -> $rms_a)"
awk -v b="$max_b" -v a="$max_a" 'BEGIN { exit !(a < b) }' ||
  fail "max distance did not drop after sharpening ($max_b -> $max_a)"
