#!/usr/bin/env bash
# Every mesh of ../shared/meshes sharpened as it is (exact CAD meshes, a scan: nothing is
# chamfered) by the auto method (the default) and by the extended method. Auto: the mesh comes
# back unchanged, at most 0.1% of the diagonal away (issue 20; measured below 1e-4% on every
# mesh: octa-flower17k, already sharp with curved faces, is left whole by the median-lift
# gate). Extended: no vertex is thrown far away (a CAD mesh's long slivers once let twirl move
# by 31% of its diagonal), the change stays below 1.5% (measured at most 1.36%: fandisk's
# facetted blends). Skipped without ../shared.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
shared="$ES_SOURCE_DIR/../shared/meshes"
[[ -d $shared ]] || { echo "$shared not found: skipped"; exit $SKIP; }
cli="$ES_BUILD_DIR/apps/edge-sharpener"
distance="$ES_BUILD_DIR/apps/mesh-distance"
extended_limit=1.5
auto_limit=0.1  # issue 20: a CAD mesh passed through as it is changes by at most 0.1%
failures=0
checked=0
for mesh in "$shared"/*; do
  case "${mesh,,}" in *.off | *.stl | *.obj | *.ply) ;; *) continue ;; esac
  name=$(basename "$mesh")
  [[ $name == chamfer-cube.off ]] && continue  # polygonal: not a triangle mesh
  for variant in auto extended; do
    out="$ES_WORK_DIR/${name%.*}-${variant}.ply"
    args=(--method "$variant")
    limit=$extended_limit
    [[ $variant == auto ]] && limit=$auto_limit
    if ! "$cli" "$mesh" "$out" "${args[@]}" -q 2>"$out.err"; then
      echo "FAIL: $name $variant: $(cat "$out.err")" >&2
      failures=$((failures + 1))
      continue
    fi
    change=$("$distance" "$out" "$mesh" --json | "$PYTHON" -c 'import json,sys; print(json.load(sys.stdin)["symmetric"]["max_percent"])')
    printf '  %-22s %-16s change max %.4f%% of the diagonal\n' "$name" "$variant" "$change"
    if ! "$PYTHON" -c "import sys; sys.exit(0 if $change < $limit else 1)"; then
      echo "FAIL: $name $variant: moved by $change% of the diagonal (limit $limit%)" >&2
      failures=$((failures + 1))
    fi
    checked=$((checked + 1))
  done
done
((checked > 0)) || { echo "FAIL: no mesh checked in $shared" >&2; exit 1; }
((failures == 0)) || exit 1
echo "cad as is: $checked runs, every change below its limit ($auto_limit% auto, $extended_limit% extended)"
