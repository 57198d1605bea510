// A flat patch folded over itself, tiled again (guards/planar_folds.h), and
// the polygon triangulation under it (util/polygon_triangulation.h).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "edge_sharpener/guards/planar_folds.h"
#include "edge_sharpener/util/mesh_types.h"
#include "edge_sharpener/util/polygon_triangulation.h"
#include "hand_built_meshes.h"

namespace es = edge_sharpener;
namespace hb = es::hand_built;

namespace {

double tiledArea(const std::vector<es::Vec2> &polygon,
                 const std::vector<std::array<int, 3>> &tiles) {
  double area = 0;
  for (const auto &t : tiles) {
    const double a = es::detail::cross2(polygon[t[0]], polygon[t[1]], polygon[t[2]]) / 2;
    EXPECT_GT(a, 0) << "a tile turns clockwise or is flat";
    area += a;
  }
  return area;
}

constexpr double kMinAngle = 1.0 * M_PI / 180.0;

}  // namespace

TEST(PolygonTriangulation, ASquareIsTwoTriangles) {
  const std::vector<es::Vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const auto tiles = es::triangulateSimplePolygon(square, kMinAngle);
  ASSERT_EQ(tiles.size(), 2u);
  EXPECT_NEAR(tiledArea(square, tiles), 1.0, 1e-12);
}

TEST(PolygonTriangulation, AReflexCornerIsTiledAroundNotAcross) {
  // An L: the reflex corner (1, 1) is where a saddle corner's flat side turns.
  const std::vector<es::Vec2> l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  const auto tiles = es::triangulateSimplePolygon(l, kMinAngle);
  ASSERT_EQ(tiles.size(), 4u);
  EXPECT_NEAR(tiledArea(l, tiles), es::signedArea(l), 1e-12);
  EXPECT_NEAR(es::signedArea(l), 3.0, 1e-12);
}

TEST(PolygonTriangulation, PointsOnAStraightSideMakeNoFlatTile) {
  // (1, 0) and (1.5, 0) lie on the side from (0, 0) to (2, 0).
  const std::vector<es::Vec2> p{{0, 0}, {1, 0}, {1.5, 0}, {2, 0}, {2, 1}, {0, 1}};
  const auto tiles = es::triangulateSimplePolygon(p, kMinAngle);
  ASSERT_EQ(tiles.size(), 4u);
  EXPECT_NEAR(tiledArea(p, tiles), 2.0, 1e-12);
}

TEST(PolygonTriangulation, RefusesACrossedOrClockwiseOutline) {
  const std::vector<es::Vec2> bowtie{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  EXPECT_FALSE(es::isSimplePolygon(bowtie));
  EXPECT_TRUE(es::triangulateSimplePolygon(bowtie, kMinAngle).empty());
  const std::vector<es::Vec2> clockwise{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  EXPECT_TRUE(es::isSimplePolygon(clockwise));
  EXPECT_TRUE(es::triangulateSimplePolygon(clockwise, kMinAngle).empty());
}

TEST(PolygonTriangulation, RefusesWhenEveryTilingHasASliver) {
  // A strip 1000 times longer than wide: both tilings have a tile with an
  // angle under a tenth of a degree.
  const std::vector<es::Vec2> p{{0, 0}, {10, 0}, {10, 0.01}, {0, 0.01}};
  EXPECT_TRUE(es::triangulateSimplePolygon(p, kMinAngle).empty());
  EXPECT_EQ(es::triangulateSimplePolygon(p, 0).size(), 2u);
}

namespace {

// A closed mesh whose flat top (z = 0) is the quad A B C D with C moved to a
// reflex corner, still split along B-D: face (B, C, D) is folded over
// (A, B, D). Below, an apex closes it.
struct FoldedTop {
  es::Mesh m;
  FoldedTop() {
    hb::makeMesh(m,
                 {{0, 0, 0},
                  {1, 0, 0},
                  {0.3, 0.3, 0},
                  {0, 1, 0},        // A B C D
                  {0.2, 0.2, -1}},  // apex
                 {{0, 1, 3},
                  {1, 2, 3},  // the top
                  {1, 0, 4},
                  {2, 1, 4},
                  {3, 2, 4},
                  {0, 3, 4}});
  }
};

}  // namespace

TEST(PlanarFolds, AFoldedFlatPatchIsTiledAgainOnItsPlane) {
  FoldedTop t;
  EXPECT_LT(hb::areaNormal(t.m.face[1])[2], 0) << "the set-up: (B, C, D) is folded";
  const auto moved = [](std::size_t v) { return v == 2; };  // C
  const es::PlanarFoldStats stats = es::unfoldPlanarPatches(t.m, moved, 1e-9, kMinAngle);
  EXPECT_GE(stats.folds, 1u);
  EXPECT_EQ(stats.patches, 1u);
  // The top is (A, B, C) and (A, C, D) now, both facing up, on z = 0.
  for (int i = 0; i < 2; ++i) {
    EXPECT_GT(hb::areaNormal(t.m.face[i])[2], 0);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(t.m.face[i].cV(k)->cP()[2], 0);
  }
  EXPECT_TRUE(hb::hasEdge(t.m, 0, 2));
  EXPECT_FALSE(hb::hasEdge(t.m, 1, 3));
  EXPECT_TRUE(hb::closedOrientedManifold(t.m));
}

TEST(PlanarFolds, LeavesAFoldWhoseVerticesAreAtRest) {
  FoldedTop t;
  const auto moved = [](std::size_t) { return false; };
  const es::PlanarFoldStats stats = es::unfoldPlanarPatches(t.m, moved, 1e-9, kMinAngle);
  EXPECT_EQ(stats.folds, 0u);
  EXPECT_EQ(stats.patches, 0u);
  EXPECT_TRUE(hb::hasEdge(t.m, 1, 3));
}

TEST(PlanarFolds, LeavesAFoldOffThePlane) {
  FoldedTop t;
  t.m.vert[2].P()[2] = 0.01f;  // C above the top: not one flat patch
  const auto moved = [](std::size_t v) { return v == 2; };
  const es::PlanarFoldStats stats = es::unfoldPlanarPatches(t.m, moved, 1e-3, kMinAngle);
  EXPECT_EQ(stats.patches, 0u);
  EXPECT_TRUE(hb::hasEdge(t.m, 1, 3));
  EXPECT_TRUE(hb::closedOrientedManifold(t.m));
}

TEST(PlanarFolds, LeavesAVertexMovedOutOfItsOutline) {
  // The top's centre E moved past side A-B: no tiling of the same vertices
  // covers the square, so the fold stays (the intersection guard's case).
  es::Mesh m;
  hb::makeMesh(m, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, -0.2, 0}, {0.5, 0.5, -1}},
               {{0, 1, 4},
                {1, 2, 4},
                {2, 3, 4},
                {3, 0, 4},  // the top, fanned from E
                {1, 0, 5},
                {2, 1, 5},
                {3, 2, 5},
                {0, 3, 5}});
  std::vector<std::array<const es::Mesh::VertexType *, 3>> before;
  for (const auto &f : m.face) before.push_back({f.cV(0), f.cV(1), f.cV(2)});
  const auto moved = [](std::size_t v) { return v == 4; };
  const es::PlanarFoldStats stats = es::unfoldPlanarPatches(m, moved, 1e-9, kMinAngle);
  EXPECT_GE(stats.folds, 1u);
  EXPECT_EQ(stats.patches, 0u);
  for (std::size_t i = 0; i < m.face.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(m.face[i].cV(k), before[i][k]);
  EXPECT_TRUE(hb::closedOrientedManifold(m));
}
