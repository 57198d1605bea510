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

# `pip install .` from the checkout into a virtual environment that sees
# Debian's numpy, pybind11 and setuptools (PEP 668: never the system Python),
# then the package used from there.
add_test(NAME python.pip_install
  COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/tests/pip_install.sh" "${Python_EXECUTABLE}"
          "${CMAKE_CURRENT_SOURCE_DIR}" "${CMAKE_CURRENT_BINARY_DIR}/pip-venv")
set_tests_properties(python.pip_install PROPERTIES LABELS python TIMEOUT 900)

# The Blender add-on in Debian's Blender, headless: the zip (package inside),
# and the source folder using the package from PYTHONPATH (--python-use-system-env).
find_program(BLENDER_EXECUTABLE blender)
set(blender_test_script "${PROJECT_SOURCE_DIR}/blender/tests/test_addon.py")
if(BLENDER_EXECUTABLE)
  add_test(NAME blender.addon_zip
    COMMAND "${BLENDER_EXECUTABLE}" -b --factory-startup --python-exit-code 1
            --python "${blender_test_script}" --
            --addon "${CMAKE_BINARY_DIR}/blender/edge_sharpener_addon.zip" --source "${PROJECT_SOURCE_DIR}")
  add_test(NAME blender.addon_folder
    COMMAND "${BLENDER_EXECUTABLE}" -b --factory-startup --python-use-system-env --python-exit-code 1
            --python "${blender_test_script}" --
            --addon "${PROJECT_SOURCE_DIR}/blender/edge_sharpener_addon" --source "${PROJECT_SOURCE_DIR}")
  set_tests_properties(blender.addon_zip PROPERTIES LABELS blender TIMEOUT 300
    ENVIRONMENT "BLENDER_USER_SCRIPTS=${CMAKE_BINARY_DIR}/blender/user-scripts-zip")
  set_tests_properties(blender.addon_folder PROPERTIES LABELS blender TIMEOUT 300
    ENVIRONMENT "BLENDER_USER_SCRIPTS=${CMAKE_BINARY_DIR}/blender/user-scripts-folder;PYTHONPATH=${CMAKE_CURRENT_BINARY_DIR}")
else()
  # Not a silent skip: scripts/bootstrap.sh installs Debian's blender.
  add_test(NAME blender.missing COMMAND sh -c "echo 'blender not found: run scripts/bootstrap.sh'; exit 1")
  set_tests_properties(blender.missing PROPERTIES LABELS blender)
endif()
