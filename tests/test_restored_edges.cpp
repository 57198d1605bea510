// The restored sharp edges sharpen() reports to a caller that asks for them
// (kRestoredVertexAttribute, restoredEdges): on a marching-cubes cube they
// are the cube's twelve edges, on a sphere there are none, and a caller that
// does not ask gets no attribute.
#include <gtest/gtest.h>

#include <cmath>

#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/restored_edges.h"
#include "edge_sharpener/util/mesh_types.h"
#include "test_meshes/shapes.h"

namespace es = edge_sharpener;
namespace shapes = edge_sharpener::test_meshes;

namespace {

/// The shape's marching-cubes mesh at `cellFraction` of its diagonal,
/// sharpened by the default method with the restored-vertex attribute.
/// \return the attribute's values per output vertex.
std::vector<std::uint8_t> sharpenRecordingRestored(const std::string &name, double cellFraction,
                                                   es::Mesh &m) {
  const shapes::Shape &shape = shapes::shapeByName(name);
  shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, cellFraction), m);
  vcg::tri::UpdateTopology<es::Mesh>::FaceFace(m);
  vcg::tri::Allocator<es::Mesh>::AddPerVertexAttribute<std::uint8_t>(m,
                                                                     es::kRestoredVertexAttribute);
  const es::SharpenReport report = es::sharpen(m, es::SharpenOptions{});
  auto h = vcg::tri::Allocator<es::Mesh>::FindPerVertexAttribute<std::uint8_t>(
      m, es::kRestoredVertexAttribute);
  EXPECT_TRUE(vcg::tri::Allocator<es::Mesh>::IsValidHandle(m, h));
  std::vector<std::uint8_t> restored(m.vert.size());
  std::size_t count = 0;
  for (std::size_t v = 0; v < m.vert.size(); ++v) count += restored[v] = h[v];
  EXPECT_EQ(count, report.placement.moved());  // every vertex the report counts as moved
  // A persistent attribute is the caller's to delete (vcglib's mesh does not).
  vcg::tri::Allocator<es::Mesh>::DeletePerVertexAttribute(m, h);
  return restored;
}

/// Which of the unit cube's coordinates lie on its faces (|c| = 0.5) within `tolerance`.
std::array<bool, 3> onCubeFaces(const es::Mesh::CoordType &p, double tolerance) {
  std::array<bool, 3> on{};
  for (int c = 0; c < 3; ++c) on[c] = std::abs(std::abs(double(p[c])) - 0.5) <= tolerance;
  return on;
}

}  // namespace

TEST(RestoredEdges, AreTheCubesTwelveEdges) {
  es::Mesh m;
  const double cellFraction = 0.02;
  const std::vector<std::uint8_t> restored = sharpenRecordingRestored("cube", cellFraction, m);
  const double cell =
      shapes::cellSizeForDiagonalFraction(shapes::shapeByName("cube"), cellFraction);
  const double tolerance = 0.05 * cell;

  std::size_t restoredCount = 0;
  for (std::size_t v = 0; v < m.vert.size(); ++v) {
    if (!restored[v]) continue;
    ++restoredCount;
    const auto on = onCubeFaces(m.vert[v].cP(), tolerance);
    EXPECT_GE(on[0] + on[1] + on[2], 2) << "restored vertex " << v << " off the cube's edges";
  }
  EXPECT_GT(restoredCount, 0u);

  // Every restored edge runs along one edge of the cube (both ends on the
  // same two faces), and together they cover the twelve unit edges.
  double length = 0;
  for (const auto &[a, b] : es::restoredEdges(m, restored)) {
    ASSERT_TRUE(restored[a] && restored[b]);
    const auto onA = onCubeFaces(m.vert[a].cP(), tolerance);
    const auto onB = onCubeFaces(m.vert[b].cP(), tolerance);
    EXPECT_GE((onA[0] && onB[0]) + (onA[1] && onB[1]) + (onA[2] && onB[2]), 2)
        << "edge " << a << "-" << b << " leaves the cube's edges";
    length += vcg::Distance(m.vert[a].cP(), m.vert[b].cP());
  }
  EXPECT_GT(length, 0.9 * 12.0);
  EXPECT_LT(length, 1.001 * 12.0);
}

TEST(RestoredEdges, NoneOnASphere) {
  es::Mesh m;
  const std::vector<std::uint8_t> restored = sharpenRecordingRestored("sphere", 0.02, m);
  for (std::uint8_t r : restored) EXPECT_EQ(r, 0);
  EXPECT_TRUE(es::restoredEdges(m, restored).empty());
}

TEST(RestoredEdges, NoAttributeUnlessAsked) {
  const shapes::Shape &shape = shapes::shapeByName("cube");
  es::Mesh m;
  shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, 0.02), m);
  vcg::tri::UpdateTopology<es::Mesh>::FaceFace(m);
  const es::SharpenReport report = es::sharpen(m, es::SharpenOptions{});
  EXPECT_GT(report.placement.moved(), 0u);
  EXPECT_FALSE(vcg::tri::HasPerVertexAttribute(m, es::kRestoredVertexAttribute));
}
