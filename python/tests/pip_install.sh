#!/usr/bin/env bash
# `pip install .` from the checkout into a fresh virtual environment that sees
# Debian's numpy, pybind11 and setuptools (--system-site-packages; PEP 668:
# never the system Python; --no-index: nothing is downloaded), then uses the
# installed package from outside the checkout.
# Usage: pip_install.sh PYTHON SOURCE_DIR/python VENV_DIR
set -euo pipefail
python=$1 package=$2 venv=$3
rm -rf "$venv"
"$python" -m venv --system-site-packages "$venv"
export EDGE_SHARPENER_BUILD_BASE="$venv/build"
mkdir -p "$EDGE_SHARPENER_BUILD_BASE"
"$venv/bin/python" -m pip install --no-build-isolation --no-index --quiet "$package"
cd "$venv"
"$venv/bin/python" - "$package" <<'PY'
import pathlib, sys
import numpy as np
import edge_sharpener as es

installed = pathlib.Path(es.__file__).resolve()
assert "site-packages" in installed.parts, installed  # the venv's copy, not the checkout
# An octahedron: every edge sharp, nothing to do but a clean run.
v = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], np.float64)
f = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
out_v, out_f, report = es.sharpen(v, f, method="extended")
assert out_v.dtype == np.float64 and report["input"]["faces"] == 8, report
assert "multiplier" in es.sharpen.__doc__
try:
    es.sharpen(v, f[:, ::-1][:1].tolist() + f[1:].tolist())  # one face flipped
except es.InputError as error:
    assert "oriented" in str(error), error
else:
    raise AssertionError("a misoriented mesh was accepted")
print("pip-installed edge_sharpener:", installed)
PY
