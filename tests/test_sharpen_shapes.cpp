// End to end: marching-cubes meshes of the exact test shapes, sharpened with
// the paper's method; distances to the exact shapes before and after, and the
// invariants every output must keep.
#include <gtest/gtest.h>

#include <cstdio>

#include <vcg/complex/algorithms/clean.h>

#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/mesh_distance.h"
#include "edge_sharpener/mesh_types.h"
#include "test_meshes/shapes.h"

namespace es = edge_sharpener;
namespace shapes = edge_sharpener::test_meshes;

namespace {

struct Case {
  std::string shape;
  double cellFraction;  // of the bounding-box diagonal
  double minMaxReduction;  // required max-error ratio before/after
  double minRmsReduction;  // required RMS ratio before/after
};

std::ostream &operator<<(std::ostream &os, const Case &c) {
  return os << c.shape << "@" << c.cellFraction * 100 << "%";
}

/// Checks the output is a closed, consistently oriented 2-manifold without
/// NaN; returns a description of the first problem, or "".
std::string topologyProblem(es::Mesh &m) {
  for (auto &v : m.vert)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(v.P()[k])) return "non-finite coordinate";
  vcg::tri::UpdateTopology<es::Mesh>::FaceFace(m);
  int edges = 0, boundary = 0, nonManifold = 0;
  vcg::tri::Clean<es::Mesh>::CountEdgeNum(m, edges, boundary, nonManifold);
  if (nonManifold > 0) return "non-manifold edge";
  if (vcg::tri::Clean<es::Mesh>::CountNonManifoldVertexFF(m, false) > 0)
    return "non-manifold vertex";
  if (boundary > 0) return "boundary edges in a closed input";
  if (!vcg::tri::Clean<es::Mesh>::IsCoherentlyOrientedMesh(m)) return "inconsistent orientation";
  return "";
}

class SharpenShapes : public ::testing::TestWithParam<Case> {};

}  // namespace

TEST_P(SharpenShapes, ReducesErrorAndKeepsInvariants) {
  const Case c = GetParam();
  const shapes::Shape &shape = shapes::shapeByName(c.shape);
  es::Mesh reference, input, output;
  shapes::buildReference(shape, reference);
  shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, c.cellFraction), input);
  vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(output, input);
  vcg::tri::UpdateTopology<es::Mesh>::FaceFace(output);

  const es::SharpenReport r = es::sharpen(output, {});
  EXPECT_EQ(topologyProblem(output), "");

  // Original vertices keep their index and bit-identical position.
  ASSERT_GE(output.vert.size(), input.vert.size());
  for (std::size_t i = 0; i < input.vert.size(); ++i)
    ASSERT_EQ(output.vert[i].P(), input.vert[i].P()) << "vertex " << i;
  // Counts follow the report's arithmetic.
  EXPECT_EQ(r.outputVertices, r.inputVertices + r.subdivision.insertedVertices - r.cleanup.collapses);
  EXPECT_EQ(r.outputFaces, r.inputFaces + r.subdivision.addedFaces - 2 * r.cleanup.collapses);
  EXPECT_EQ(r.cleanup.remaining, 0u);

  const es::DistanceReport before = es::measureDistance(input, reference);
  const es::DistanceReport after = es::measureDistance(output, reference);
  std::printf("%-14s cell %.1f%%: faces %zu -> %zu, chamfer edges %zu, corners %zu, moved %zu, "
              "fallbacks %zu | max %.4f%% -> %.4f%% (x%.2f), rms %.5f%% -> %.5f%% (x%.2f)\n",
              c.shape.c_str(), c.cellFraction * 100, r.inputFaces, r.outputFaces,
              r.filters.chamferEdges, r.filters.cornerFaces, r.placement.moved(),
              r.placement.fallbacks(), before.maxPercent(), after.maxPercent(),
              before.max() / after.max(), before.rmsPercent(), after.rmsPercent(),
              before.rms() / after.rms());
  // Never farther from the exact shape than the input.
  EXPECT_LE(after.max(), before.max() * 1.0001);
  EXPECT_LE(after.rms(), before.rms() * 1.0001);
  EXPECT_GE(before.max() / after.max(), c.minMaxReduction);
  EXPECT_GE(before.rms() / after.rms(), c.minRmsReduction);
}

INSTANTIATE_TEST_SUITE_P(
    MarchingCubes, SharpenShapes,
    ::testing::Values(Case{"cube", 0.02, 1.0, 1.0}, Case{"cube", 0.01, 1.0, 1.0},
                      Case{"lblock", 0.02, 1.0, 1.0}, Case{"lblock", 0.01, 1.0, 1.0},
                      Case{"lblock_tilted", 0.02, 1.0, 1.0}, Case{"wedge", 0.02, 1.0, 1.0},
                      Case{"pyramid", 0.02, 1.0, 1.0}, Case{"cross_prism", 0.02, 1.0, 1.0},
                      Case{"cylinder_block", 0.02, 1.0, 1.0}),
    [](const ::testing::TestParamInfo<Case> &info) {
      return info.param.shape + "_" + std::to_string(int(info.param.cellFraction * 1000)) + "permille";
    });

TEST(SharpenShapes, SphereWithoutFeaturesIsEssentiallyUnchanged) {
  const shapes::Shape &shape = shapes::shapeByName("sphere");
  es::Mesh reference, input, output;
  shapes::buildReference(shape, reference);
  shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, 0.02), input);
  vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(output, input);
  vcg::tri::UpdateTopology<es::Mesh>::FaceFace(output);
  const es::SharpenReport r = es::sharpen(output, {});
  const es::DistanceReport before = es::measureDistance(input, reference);
  const es::DistanceReport after = es::measureDistance(output, reference);
  std::printf("sphere: chamfer edges %zu, moved %zu | max %.4f%% -> %.4f%%, rms %.5f%% -> %.5f%%\n",
              r.filters.chamferEdges, r.placement.moved(), before.maxPercent(), after.maxPercent(),
              before.rmsPercent(), after.rmsPercent());
  EXPECT_LE(after.max(), before.max() * 1.05);
  EXPECT_LE(after.rms(), before.rms() * 1.05);
}
