# MeshLab plugin tests: the real Debian meshlabserver / meshlab, under Xvfb, on the
# private prefix of filter_edge_sharpener (target meshlab_private_prefix, built by
# `all`). Each test is a bash script in tests/plugin/; it exits 77 (skipped) only
# when MeshLab is not installed. Run them with: ctest -L plugin
add_executable(plugin_test_tool plugin/plugin_test_tool.cpp)
target_link_libraries(plugin_test_tool PRIVATE edge_sharpener_core vcglib_plylib)
set(_es_menu_tool "")
if(TARGET meshlab_common)  # defined by filter_edge_sharpener/ when MeshLab is installed
  add_executable(list_filter_menu plugin/list_filter_menu.cpp)
  target_link_libraries(list_filter_menu PRIVATE meshlab_common)
  set(_es_menu_tool "$<TARGET_FILE:list_filter_menu>")
endif()

set(_es_cli "")
if(TARGET edge-sharpener)
  set(_es_cli "$<TARGET_FILE:edge-sharpener>")
endif()

# edge_sharpener_plugin_test(NAME SCRIPT TIMEOUT_SECONDS). Without filter_edge_sharpener/
# (no MeshLab) the scripts skip if MeshLab is really absent, and fail otherwise.
function(edge_sharpener_plugin_test name script timeout)
  edge_sharpener_meshlab_script_test(plugin ${name} ${script} ${timeout}
    "ES_TEST_TOOL=$<TARGET_FILE:plugin_test_tool>;ES_CLI=${_es_cli};ES_MENU_TOOL=${_es_menu_tool}")
endfunction()

edge_sharpener_plugin_test(listing listing.sh 120)
edge_sharpener_plugin_test(sharpen_matches_cli sharpen_matches_cli.sh 900)
edge_sharpener_plugin_test(detect detect.sh 600)
edge_sharpener_plugin_test(pipeline_hausdorff pipeline_hausdorff.sh 900)
edge_sharpener_plugin_test(bad_input bad_input.sh 300)
edge_sharpener_plugin_test(gui gui.sh 600)
