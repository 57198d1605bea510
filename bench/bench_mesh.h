// Shared by the benchmark programs: the benchmark meshes (marching cubes of
// a test shape with sharp features, sized by face count) and timing helpers.
#pragma once

#include <chrono>
#include <cmath>
#include <string>

#include "edge_sharpener/util/mesh_types.h"
#include "test_meshes/shapes.h"

namespace edge_sharpener::bench {

/// The shape every benchmark mesh is made of: the L-block tilted so that no
/// face, edge or corner is aligned with the grid (convex and concave edges,
/// corners mixing both) - the chamfers a real marching-cubes output has.
inline const char *kShape = "lblock_tilted";

/// Marching-cubes cell size giving about `faces` faces: the face count of a
/// marching-cubes surface grows as 1/cell^2, calibrated on a coarse grid.
inline double cellSizeForFaces(const test_meshes::Shape &shape, double faces) {
  const double h0 = test_meshes::cellSizeForDiagonalFraction(shape, 0.02);
  Mesh coarse;
  test_meshes::marchingCubes(shape, h0, coarse);
  return h0 * std::sqrt(double(coarse.fn) / faces);
}

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace edge_sharpener::bench
