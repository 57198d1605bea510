#!/usr/bin/env bash
# mesh-distance against MeshLab's own "Hausdorff Distance" filter on the same pairs.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
"$PYTHON" "$ES_SOURCE_DIR/tests/quality/hausdorff_crosscheck.py"
