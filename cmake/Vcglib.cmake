# Locates the vcglib tree that ships inside Debian's `meshlab` source package
# (unpacked by scripts/bootstrap.sh) and defines:
#   vcglib          INTERFACE target: include dirs + Eigen (vcglib is header-only)
#   vcglib_plylib   static library with vcglib's PLY parser (wrap/ply/plylib.cpp)
# MESHLAB_SOURCE_DIR may be set to use another unpacked tree.
set(MESHLAB_SOURCE_DIR "${PROJECT_SOURCE_DIR}/.cache/meshlab-src"
    CACHE PATH "Unpacked Debian meshlab 2020.09 source tree (holds vcglib/)")
set(EXPECTED_MESHLAB_VERSION "2020.09")

if(NOT EXISTS "${MESHLAB_SOURCE_DIR}/vcglib/vcg/complex/complex.h")
  message(FATAL_ERROR
    "vcglib not found under MESHLAB_SOURCE_DIR=${MESHLAB_SOURCE_DIR}.\n"
    "Run `sudo scripts/bootstrap.sh` (it unpacks Debian's meshlab source package there).")
endif()
file(STRINGS "${MESHLAB_SOURCE_DIR}/ML_VERSION" _ml_version LIMIT_COUNT 1)
if(NOT _ml_version STREQUAL EXPECTED_MESHLAB_VERSION)
  message(FATAL_ERROR
    "MeshLab source tree is version '${_ml_version}', expected ${EXPECTED_MESHLAB_VERSION} "
    "(the version of Debian bookworm's meshlab binary). Delete ${MESHLAB_SOURCE_DIR} and rerun scripts/bootstrap.sh.")
endif()

find_package(Eigen3 3.3 REQUIRED NO_MODULE)

add_library(vcglib INTERFACE)
# SYSTEM: vcglib's own warnings (e.g. std::unary_function under C++17) are not ours.
target_include_directories(vcglib SYSTEM INTERFACE "${MESHLAB_SOURCE_DIR}/vcglib")
target_link_libraries(vcglib INTERFACE Eigen3::Eigen)

add_library(vcglib_plylib STATIC "${MESHLAB_SOURCE_DIR}/vcglib/wrap/ply/plylib.cpp")
target_link_libraries(vcglib_plylib PUBLIC vcglib)
set_target_properties(vcglib_plylib PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_compile_options(vcglib_plylib PRIVATE -w)
