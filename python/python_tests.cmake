# Tests of the Python package (label python) and of the Blender add-on
# (label blender). The package is found on PYTHONPATH (this build) and the
# CLI results it is compared with come from this build's programs.
set(python_test_env
  "PYTHONPATH=${CMAKE_CURRENT_BINARY_DIR}"
  "ES_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
  "ES_CLI=$<TARGET_FILE:edge-sharpener>"
  "ES_DISTANCE_CLI=$<TARGET_FILE:mesh-distance>"
  # pytest's cache stays out of the source tree.
  "PYTHONDONTWRITEBYTECODE=1")

add_test(NAME python.pytest
  COMMAND "${Python_EXECUTABLE}" -m pytest -q -p no:cacheprovider "${CMAKE_CURRENT_SOURCE_DIR}/tests")
set_tests_properties(python.pytest PROPERTIES LABELS python TIMEOUT 600
  ENVIRONMENT "${python_test_env}")
