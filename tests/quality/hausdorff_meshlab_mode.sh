#!/usr/bin/env bash
# mesh-distance --sampling meshlab against MeshLab's own "Hausdorff Distance" filter (issue 19).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
"$PYTHON" "$ES_SOURCE_DIR/tests/quality/hausdorff_meshlab_mode.py"
