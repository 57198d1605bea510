# Test shapes (exact references and their marching-cubes meshes) and the distance tool
# (Metro distance, and the feature-fidelity measures in test_fidelity.cpp).
# Test names start with "Meshes", so `ctest -R Meshes` runs exactly these.
edge_sharpener_test(meshes_tests test_shapes.cpp test_distance.cpp test_fidelity.cpp)
target_link_libraries(meshes_tests PRIVATE test_meshes)

# Dual contouring with exact Hermite data on the marching-cubes grid
# (test_meshes/dual_contouring.h): `ctest -R DualContouring`.
edge_sharpener_test(dual_contouring_tests test_dual_contouring.cpp)
target_link_libraries(dual_contouring_tests PRIVATE test_meshes)
