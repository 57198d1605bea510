#!/usr/bin/env bash
# meshlabserver -d lists both filters of the plugin, with their parameters.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

run_server listing -d filters.txt
((rc == 0)) || { cat listing.out >&2; fail "meshlabserver -d exited with status $rc"; }
[[ -s filters.txt ]] || fail "meshlabserver -d wrote no dump"

# section NAME: the dump's section of filter NAME (up to the next \section).
section() { awk -v n="$1" '/^\\section f[0-9]+ /{on = (index($0, " " n " ") > 0)} on' filters.txt; }
# params NAME: "Type|Description" per parameter row.
params() { section "$1" | sed -n 's/^<TR><TD> \\c \([A-Za-z0-9]*\) *<\/TD> *<TD> \(.*\) <\/TD> <TD><i>.*/\1|\2/p'; }

check_filter() {
  local name=$1 expected=$2 got text
  # Read the section whole first: `section | grep -q` under pipefail fails
  # whenever grep stops reading before awk has written everything (SIGPIPE).
  text=$(section "$name")
  [[ -n $text ]] || fail "filter '$name' not listed"
  grep -q 'Edge-Sharpener: Recovering sharp features' <<<"$text" ||
    fail "'$name': description does not cite the paper"
  got=$(params "$name")
  [[ $got == "$expected" ]] || fail "'$name' parameters:"$'\n'"$got"$'\n'"expected:"$'\n'"$expected"
  log "'$name' listed with $(wc -l <<<"$got") parameter(s)"
}

check_filter "Edge-Sharpener: Sharpen Chamfered Edges" "Enum|Method
Float|Smooth-edge multiplier
Bool|Edge-length check
Bool|Colorize
Enum|Colours
Float|Degenerate angle (deg)
Bool|Affect only selected faces"
check_filter "Edge-Sharpener: Detect Chamfers" "Enum|Method
Float|Smooth-edge multiplier
Enum|Colours"

total=$(sed -n 's/^Total \([0-9]*\) filtering actions.*/\1/p' listing.out)
log "meshlabserver reports $total filtering actions"
