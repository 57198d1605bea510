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

# Without filter_edge_sharpener/ (no MeshLab) the scripts skip if MeshLab is really absent,
# and fail otherwise.
edge_sharpener_meshlab_script_tests(plugin
  listing 120  sharpen_matches_cli 900  detect 600  colours 600  pipeline_hausdorff 900  bad_input 300
  non_manifold 300  selection 300
  gui 600
  ENVIRONMENT "ES_TEST_TOOL=$<TARGET_FILE:plugin_test_tool>" "ES_CLI=${_es_cli}" "ES_MENU_TOOL=${_es_menu_tool}")
