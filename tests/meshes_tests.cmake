# Test shapes (exact references and their marching-cubes meshes) and the distance tool.
# Test names start with "Meshes", so `ctest -R Meshes` runs exactly these.
edge_sharpener_test(meshes_tests test_shapes.cpp test_distance.cpp)
target_link_libraries(meshes_tests PRIVATE test_meshes)
