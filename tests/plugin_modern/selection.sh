#!/usr/bin/env bash
# "Affect only selected faces" in MeshLab 2022.02 (issue 61): check_selection_run
# (tests/lib/common.sh) through the runner in the trixie root.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[[ -x ${ES_CLI:-} ]] || fail "the edge-sharpener CLI is not built (ES_CLI='${ES_CLI:-}')"
check_selection_run run_filter
