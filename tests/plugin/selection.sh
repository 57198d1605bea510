#!/usr/bin/env bash
# "Affect only selected faces" in MeshLab 2020.09 (issue 61): check_selection_run
# (tests/lib/common.sh) through meshlabserver.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
[[ -n ${ES_CLI:-} && -x ${ES_CLI:-} ]] || fail "the edge-sharpener CLI is not built (ES_CLI='${ES_CLI:-}')"
check_selection_run run_server
