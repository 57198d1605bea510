# Test shapes (exact references and their marching-cubes meshes) and the distance tool
# (Metro distance, and the feature-fidelity measures in test_fidelity.cpp).
# Test names start with "Meshes", so `ctest -R Meshes` runs exactly these.
edge_sharpener_test(meshes_tests test_shapes.cpp test_distance.cpp test_fidelity.cpp)
target_link_libraries(meshes_tests PRIVATE test_meshes)
