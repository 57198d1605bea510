"""Builds the extension module edge_sharpener._edge_sharpener (pybind11) from
src/binding.cpp and the header-only core in ../vcg_ext. Metadata: pyproject.toml.

vcglib comes from Debian's meshlab source package, which scripts/bootstrap.sh
unpacks into .cache/meshlab-src (EDGE_SHARPENER_CACHE moves .cache;
EDGE_SHARPENER_VCGLIB names a vcglib tree directly).
"""
import os
import pathlib

from pybind11.setup_helpers import Pybind11Extension, build_ext
from setuptools import setup

here = pathlib.Path(__file__).resolve().parent
root = here.parent


def vcglib_dir():
    cache = pathlib.Path(os.environ.get("EDGE_SHARPENER_CACHE", root / ".cache"))
    for candidate in (os.environ.get("EDGE_SHARPENER_VCGLIB"), cache / "meshlab-src" / "vcglib"):
        if candidate and (pathlib.Path(candidate) / "vcg" / "complex" / "complex.h").exists():
            return str(candidate)
    raise SystemExit("edge-sharpener: vcglib not found; run scripts/bootstrap.sh (it unpacks "
                     "Debian's meshlab source package into .cache/) or set EDGE_SHARPENER_VCGLIB")


extension = Pybind11Extension(
    "edge_sharpener._edge_sharpener",
    ["src/binding.cpp"],
    include_dirs=[str(root / "vcg_ext"), str(root / "apps"), vcglib_dir(), "/usr/include/eigen3"],
    cxx_std=17,
    # The core's per-face loops run in parallel with OpenMP (serially without it).
    # -g0: no debug information (Debian's Python builds with -g: a larger, slower build).
    extra_compile_args=["-fopenmp", "-Wno-deprecated-declarations", "-g0"],
    extra_link_args=["-fopenmp"],
)

# pip builds in the checkout: EDGE_SHARPENER_BUILD_BASE keeps the build files
# out of it (the tests point it at CMake's build directory).
build_base = os.environ.get("EDGE_SHARPENER_BUILD_BASE")
options = {"build": {"build_base": build_base}, "egg_info": {"egg_base": build_base}} if build_base else {}

setup(ext_modules=[extension], cmdclass={"build_ext": build_ext}, options=options)
