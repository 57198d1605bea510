# MeshLab 2022.02 plugin tests: the real MeshLab 2022.02 of Debian trixie, in the
# root made by scripts/trixie-root.sh (outside the clone, reused across clones),
# on the builds of scripts/build-plugins.sh. The fixture plugin_modern.prepare
# makes both (idempotent; a few minutes the first time on a machine). Each test
# is a bash script in tests/plugin_modern/. Run them with: ctest -L plugin_modern
if(NOT TARGET plugin_test_tool)
  add_executable(plugin_test_tool plugin/plugin_test_tool.cpp)
  target_link_libraries(plugin_test_tool PRIVATE edge_sharpener_core vcglib_plylib)
endif()

set(_es_modern_env
  "ES_BUILD_DIR=${CMAKE_BINARY_DIR}" "ES_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
  "ES_TEST_TOOL=$<TARGET_FILE:plugin_test_tool>"
  "ES_CLI=$<$<TARGET_EXISTS:edge-sharpener>:$<TARGET_FILE:edge-sharpener>>")

# All of them lock the trixie root: the .deb test installs into its plugin folder. The
# fixture plugin_modern.prepare comes before the others; its COST makes CTest start it
# first (a clean clone has no timings), so that its downloads and three builds run
# beside the rest of the suite instead of after most of it.
edge_sharpener_script_tests(plugin_modern prepare 2700 ENVIRONMENT ${_es_modern_env}
  PROPERTIES RESOURCE_LOCK trixie_root FIXTURES_SETUP plugin_modern COST 100000)
edge_sharpener_script_tests(plugin_modern
  releases 120  scripts 600  matches_cli 900  bad_input 300  non_manifold 300  selection 300
  gui 600  deb_trixie 300
  deb_bookworm 300
  ENVIRONMENT ${_es_modern_env}
  PROPERTIES RESOURCE_LOCK trixie_root FIXTURES_REQUIRED plugin_modern)
# xvfb-run -a in the root shares /tmp/.X11-unix with the host's MeshLab tests.
set_property(TEST plugin_modern.gui plugin_modern.deb_bookworm APPEND PROPERTY RESOURCE_LOCK meshlab_xvfb)
