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
  "ES_BUILD_DIR=${CMAKE_BINARY_DIR};ES_SOURCE_DIR=${PROJECT_SOURCE_DIR};ES_TEST_TOOL=$<TARGET_FILE:plugin_test_tool>;ES_CLI=$<$<TARGET_EXISTS:edge-sharpener>:$<TARGET_FILE:edge-sharpener>>")

# edge_sharpener_plugin_modern_test(NAME SCRIPT TIMEOUT_SECONDS [RESOURCE_LOCK...]).
# All of them lock the trixie root: the .deb test installs into its plugin folder.
function(edge_sharpener_plugin_modern_test name script timeout)
  add_test(NAME plugin_modern.${name} COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/plugin_modern/${script}")
  set_tests_properties(plugin_modern.${name} PROPERTIES
    TIMEOUT ${timeout}
    LABELS plugin_modern
    RESOURCE_LOCK "trixie_root;${ARGN}"
    ENVIRONMENT "${_es_modern_env};ES_WORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/plugin_modern/${name}")
  if(name STREQUAL "prepare")
    set_tests_properties(plugin_modern.${name} PROPERTIES FIXTURES_SETUP plugin_modern)
  else()
    set_tests_properties(plugin_modern.${name} PROPERTIES FIXTURES_REQUIRED plugin_modern)
  endif()
endfunction()

edge_sharpener_plugin_modern_test(prepare prepare.sh 1800)
edge_sharpener_plugin_modern_test(releases releases.sh 120)
edge_sharpener_plugin_modern_test(scripts scripts.sh 600)
edge_sharpener_plugin_modern_test(matches_cli matches_cli.sh 900)
edge_sharpener_plugin_modern_test(bad_input bad_input.sh 300)
# xvfb-run -a in the root shares /tmp/.X11-unix with the host's MeshLab tests.
edge_sharpener_plugin_modern_test(gui gui.sh 600 meshlab_xvfb)
edge_sharpener_plugin_modern_test(deb_trixie deb_trixie.sh 300)
edge_sharpener_plugin_modern_test(deb_bookworm deb_bookworm.sh 300 meshlab_xvfb)
