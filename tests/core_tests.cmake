# Core algorithm tests: pure geometry, the six filters on hand-built meshes,
# the split, cleanup and feature-zone stages on hand-built meshes
# (hand_built_meshes.h), end-to-end sharpening of the generated shapes.
edge_sharpener_test(core_tests test_geometry.cpp test_filters.cpp test_subdivision.cpp
                    test_cleanup.cpp test_feature_zones.cpp test_planar_regions.cpp test_plane_patches.cpp
                    test_feature_evidence.cpp test_surface_measures.cpp test_planar_folds.cpp
                    test_rulebook.cpp)
target_link_libraries(core_tests PRIVATE test_meshes)  # IntersectionGuard.BoxOverlapMatchesEveryPairTest
if(TARGET test_meshes AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/test_sharpen_shapes.cpp)
  edge_sharpener_test(sharpen_shapes_tests test_sharpen_shapes.cpp test_restored_edges.cpp)
  target_link_libraries(sharpen_shapes_tests PRIVATE test_meshes)
endif()
edge_sharpener_test(determinism_tests test_determinism.cpp)
target_link_libraries(determinism_tests PRIVATE test_meshes)
