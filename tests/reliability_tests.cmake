# Reliability (issue 6): bad inputs through the readers, the core and both CLIs;
# invariants over generated shapes x rigid motions x scales x multipliers x
# resolutions; noise (paper, Figure 12); replay of the fuzz corpus and of every
# fixed crash reproducer (tests/reliability/fuzz_corpus, tests/reliability/crashes).
# Test names: ctest -R 'Reliability|BadInput|SharpenInvariants|SharpenNoise'. The fuzzers
# themselves (clang + libFuzzer) are built by scripts/fuzz.sh from fuzz/. Also here, as they
# run the CLI: cli_tests (tests/test_cli.cpp), what the CLI prints (ctest -R '^Cli\.').
if(TARGET edge-sharpener AND TARGET mesh-distance)
  edge_sharpener_test(reliability_tests
    reliability/test_bad_input.cpp reliability/test_invariants.cpp reliability/test_noise.cpp
    reliability/test_non_manifold.cpp reliability/test_selection.cpp)
  target_link_libraries(reliability_tests PRIVATE test_meshes)
  target_include_directories(reliability_tests PRIVATE
    "${CMAKE_CURRENT_SOURCE_DIR}" "${PROJECT_SOURCE_DIR}/apps")
  target_compile_definitions(reliability_tests PRIVATE
    EDGE_SHARPENER_CLI="$<TARGET_FILE:edge-sharpener>"
    MESH_DISTANCE_CLI="$<TARGET_FILE:mesh-distance>")
  add_dependencies(reliability_tests edge-sharpener mesh-distance)

  # What the CLI says to a user: --help, --help-all, the default, quiet,
  # verbose and JSON outputs (test names: ctest -R '^Cli\.').
  find_package(nlohmann_json 3 REQUIRED)
  edge_sharpener_test(cli_tests test_cli.cpp)
  target_link_libraries(cli_tests PRIVATE nlohmann_json::nlohmann_json)
  target_compile_definitions(cli_tests PRIVATE EDGE_SHARPENER_CLI="$<TARGET_FILE:edge-sharpener>")
  add_dependencies(cli_tests edge-sharpener)
endif()

# The fuzz targets' entry points, compiled with the project's compiler and
# driven by a plain main over the saved inputs.
foreach(_target fuzz_read_mesh fuzz_core_soup fuzz_distance)
  add_executable(reliability_replay_${_target}
    "${PROJECT_SOURCE_DIR}/fuzz/${_target}.cpp" "${PROJECT_SOURCE_DIR}/fuzz/replay_main.cpp")
  target_link_libraries(reliability_replay_${_target} PRIVATE edge_sharpener_core vcglib_plylib)
  target_include_directories(reliability_replay_${_target} PRIVATE
    "${CMAKE_CURRENT_SOURCE_DIR}" "${PROJECT_SOURCE_DIR}/apps" "${PROJECT_SOURCE_DIR}/fuzz")
  set(_inputs "${CMAKE_CURRENT_SOURCE_DIR}/reliability/fuzz_corpus/${_target}")
  if(EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/reliability/crashes/${_target}")
    list(APPEND _inputs "${CMAKE_CURRENT_SOURCE_DIR}/reliability/crashes/${_target}")
  endif()
  add_test(NAME ReliabilityFuzzReplay.${_target}
           COMMAND reliability_replay_${_target} ${_inputs})
endforeach()
