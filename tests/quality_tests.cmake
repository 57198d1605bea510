# Quality area: the measured accuracy of the sharpener (issue 4).
#   quality.fast_subset         the generated shapes, resampled by the real meshlabserver
#                               ("Uniform Mesh Resampling", 1%) and by the project's own
#                               marching cubes, sharpened by both methods, measured with
#                               mesh-distance: never worse than the input, sphere and exact
#                               shapes unchanged, the paper method's reduction factors.
#   quality.hausdorff_crosscheck  mesh-distance agrees with MeshLab's "Hausdorff Distance".
# The full benchmark (docs/results.md) is scripts/bench-quality.sh, not a test.
# Both exit 77 (skipped) only when MeshLab or python3 is not installed. Run: ctest -L quality
get_property(_es_q_prefix GLOBAL PROPERTY EDGE_SHARPENER_MESHLAB_PREFIX)
if(NOT _es_q_prefix)
  set(_es_q_prefix "${CMAKE_BINARY_DIR}/meshlab-prefix")
endif()

function(edge_sharpener_quality_test name script timeout)
  add_test(NAME quality.${name} COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/quality/${script}")
  set_tests_properties(quality.${name} PROPERTIES
    SKIP_RETURN_CODE 77
    TIMEOUT ${timeout}
    LABELS "quality"
    # meshlabserver under xvfb-run -a: one at a time (see plugin_tests.cmake).
    RESOURCE_LOCK meshlab_xvfb
    ENVIRONMENT "ES_BUILD_DIR=${CMAKE_BINARY_DIR};ES_MESHLAB_PREFIX=${_es_q_prefix};ES_SOURCE_DIR=${PROJECT_SOURCE_DIR};ES_WORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/quality/${name}")
endfunction()

edge_sharpener_quality_test(fast_subset fast_subset.sh 900)
edge_sharpener_quality_test(hausdorff_crosscheck hausdorff_crosscheck.sh 600)
