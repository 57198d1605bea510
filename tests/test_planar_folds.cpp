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
constexpr double kParallel = 1.0 * M_PI / 180.0;

/// The stage's settings with a fold's plane within `tolerance` and the
/// exact one within `exactTolerance`, vertices moving up to 3 rings out.
es::FoldSettings settings(double tolerance, double exactTolerance) {
  es::FoldSettings s;
  s.planeTolerance = tolerance;
  s.minAngleRad = kMinAngle;
  s.exactTolerance = exactTolerance;
  s.parallelAngleRad = kParallel;
  s.relaxRings = 3;
  return s;
}

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
  const es::PlanarFoldStats stats = es::unfoldPlanarPatches(t.m, moved, settings(1e-9, 1e-9));
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
  const es::PlanarFoldStats stats = es::unfoldPlanarPatches(t.m, moved, settings(1e-9, 1e-9));
  EXPECT_EQ(stats.folds, 0u);
  EXPECT_EQ(stats.patches, 0u);
  EXPECT_TRUE(hb::hasEdge(t.m, 1, 3));
}

TEST(PlanarFolds, LeavesAFoldOffThePlane) {
  FoldedTop t;
  t.m.vert[2].P()[2] = 0.01f;  // C above the top: not one flat patch
  const auto moved = [](std::size_t v) { return v == 2; };
  const es::PlanarFoldStats stats = es::unfoldPlanarPatches(t.m, moved, settings(1e-3, 1e-3));
  EXPECT_EQ(stats.patches, 0u);
  EXPECT_TRUE(hb::hasEdge(t.m, 1, 3));
  EXPECT_TRUE(hb::closedOrientedManifold(t.m));
}

namespace {

/// Whether every face of `m` faces away from `inside` (a convex solid).
::testing::AssertionResult facesOutwardFrom(const es::Mesh &m, const es::Vec3 &inside) {
  for (std::size_t i = 0; i < m.face.size(); ++i) {
    const auto &f = m.face[i];
    const es::Vec3 centre =
        (es::positionOf(f.cV(0)) + es::positionOf(f.cV(1)) + es::positionOf(f.cV(2))) / 3.0;
    if (!(hb::areaNormal(f) * (centre - inside) > 0))
      return ::testing::AssertionFailure() << "face " << i << " faces inwards";
  }
  return ::testing::AssertionSuccess();
}

/// The faces' vertex indices, to compare the connectivity before and after.
std::vector<std::array<std::size_t, 3>> faceVertices(const es::Mesh &m) {
  std::vector<std::array<std::size_t, 3>> out;
  for (const auto &f : m.face)
    out.push_back(
        {vcg::tri::Index(m, f.cV(0)), vcg::tri::Index(m, f.cV(1)), vcg::tri::Index(m, f.cV(2))});
  return out;
}

}  // namespace

namespace {

// A closed mesh whose flat top (z = 0) is the unit square A B C D with two
// vertices inside, E at (0.3, 0.5) and F at (0.7, 0.5); below, an apex
// closes it.
struct TwoInside {
  es::Mesh m;
  static constexpr std::size_t kE = 4, kF = 5;
  TwoInside() {
    hb::makeMesh(m,
                 {{0, 0, 0},
                  {1, 0, 0},
                  {1, 1, 0},
                  {0, 1, 0},  // A B C D
                  {0.3, 0.5, 0},
                  {0.7, 0.5, 0},  // E F
                  {0.5, 0.5, -1}},
                 {{0, 1, 5},
                  {1, 2, 5},
                  {5, 2, 3},
                  {4, 5, 3},
                  {0, 5, 4},
                  {0, 4, 3},  // the top
                  {1, 0, 6},
                  {2, 1, 6},
                  {3, 2, 6},
                  {0, 3, 6}});
  }
};

}  // namespace

TEST(PlanarFolds, VerticesInsideAFlatPatchMoveOnItsPlane) {
  // E and F in each other's places: two faces of the top turn over. Their
  // faces all lie on the top, so they move on it (each to the mean of its
  // neighbours) and the top faces up again, the same flat square, with the
  // same faces.
  TwoInside t;
  EXPECT_TRUE(facesOutwardFrom(t.m, {0.5, 0.5, -0.5})) << "the set-up";
  std::swap(t.m.vert[TwoInside::kE].P(), t.m.vert[TwoInside::kF].P());
  EXPECT_FALSE(facesOutwardFrom(t.m, {0.5, 0.5, -0.5})) << "the set-up: folded";
  const auto before = faceVertices(t.m);
  // The stage would tile this small patch again; the relaxation on its own:
  std::size_t relaxed = 0;
  std::vector<char> settled(t.m.vert.size(), 0);
  for (auto &f : t.m.face)
    for (int j = 0; j < 3 && relaxed == 0; ++j)
      if (es::detail::foldedOnPlane(f, j, 1e-9))
        relaxed = es::detail::relaxFlatFold<es::Mesh>(&f, j, settings(1e-9, 1e-9), settled,
                                                      t.m.vert.data());
  EXPECT_EQ(relaxed, 2u);
  EXPECT_EQ(faceVertices(t.m), before) << "no face tiled again";
  EXPECT_LT(t.m.vert[TwoInside::kE].cP()[0], t.m.vert[TwoInside::kF].cP()[0]);
  for (std::size_t v : {TwoInside::kE, TwoInside::kF}) EXPECT_EQ(t.m.vert[v].cP()[2], 0);
  EXPECT_TRUE(facesOutwardFrom(t.m, {0.5, 0.5, -0.5}));
  EXPECT_TRUE(hb::closedOrientedManifold(t.m));
}

TEST(PlanarFolds, LeavesAVertexMovedOutOfItsOutline) {
  // The top's centre E moved past side A-B: its faces lie on the top, but
  // taking it back would take away the flap it makes beyond the top's
  // outline, a change of the surface; the fold is the intersection guard's.
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
  const auto before = faceVertices(m);
  const es::Vec3 e = es::positionOf(&m.vert[4]);
  const auto moved = [](std::size_t v) { return v == 4; };
  const es::PlanarFoldStats stats = es::unfoldPlanarPatches(m, moved, settings(1e-9, 1e-9));
  EXPECT_GE(stats.folds, 1u);
  EXPECT_EQ(stats.patches, 0u);
  EXPECT_EQ(stats.relaxedVertices, 0u);
  EXPECT_EQ(faceVertices(m), before);
  EXPECT_EQ(es::positionOf(&m.vert[4]), e);
  EXPECT_TRUE(hb::closedOrientedManifold(m));
}

TEST(PlanarFolds, VerticesWhoseFacesAreOnlyNearlyFlatStay) {
  // As above, but the top twisted by a hair (C up, D down): within 1e-3 it
  // is one plane, but not within 1e-6 (a curved face is a plane only
  // nearby), so with the exact tolerance E and F stay.
  const auto relaxWithin = [](double exactTolerance, std::vector<es::Vec3> &positions) {
    TwoInside t;
    t.m.vert[2].P()[2] = 1e-4f;
    t.m.vert[3].P()[2] = -1e-4f;
    std::swap(t.m.vert[TwoInside::kE].P(), t.m.vert[TwoInside::kF].P());
    std::size_t relaxed = 0;
    std::vector<char> settled(t.m.vert.size(), 0);
    for (auto &f : t.m.face)
      for (int j = 0; j < 3 && relaxed == 0; ++j)
        if (es::detail::foldedOnPlane(f, j, 1e-3))
          relaxed = es::detail::relaxFlatFold<es::Mesh>(
              &f, j, settings(exactTolerance, exactTolerance), settled, t.m.vert.data());
    for (const auto &v : t.m.vert) positions.push_back(es::positionOf(&v));
    return relaxed;
  };
  std::vector<es::Vec3> exact, loose;
  EXPECT_EQ(relaxWithin(1e-6, exact), 0u);
  EXPECT_FLOAT_EQ(float(exact[TwoInside::kE][0]), 0.7f) << "E stays (in F's place)";
  EXPECT_FLOAT_EQ(float(exact[TwoInside::kF][0]), 0.3f) << "F stays (in E's place)";
  EXPECT_EQ(relaxWithin(1e-3, loose), 2u) << "the control: nearly flat is flat enough";
}

namespace {

// A closed roof: two planes meeting along a ridge (y = 0.5, z = 0.5) over a
// unit square, with ridge vertices R0 R1 R2 R3 at x = 0, 0.4, 0.6, 1.
struct Roof {
  es::Mesh m;
  static constexpr std::size_t kR1 = 5, kR2 = 6;
  Roof() {
    hb::makeMesh(m,
                 {{0, 0, 0},
                  {1, 0, 0},
                  {0, 1, 0},
                  {1, 1, 0},  // B0 B1 C0 C1
                  {0, 0.5, 0.5},
                  {0.4, 0.5, 0.5},
                  {0.6, 0.5, 0.5},
                  {1, 0.5, 0.5}},  // R0 R1 R2 R3
                 {{0, 1, 5},
                  {0, 5, 4},
                  {1, 6, 5},
                  {1, 7, 6},  // the side y < 0.5
                  {2, 4, 5},
                  {2, 5, 3},
                  {3, 5, 6},
                  {3, 6, 7},  // the side y > 0.5
                  {0, 4, 2},
                  {1, 3, 7},
                  {0, 2, 3},
                  {0, 3, 1}});
  }
};

}  // namespace

TEST(PlanarFolds, VerticesOutOfOrderAlongASharpEdgeSlideAlongIt) {
  // Placement put R1 and R2 on the ridge in each other's places (as samples
  // a hair from a corner project onto its edge out of order): a face on
  // either side folds over its neighbour. Each has its faces on the two
  // planes, so each moves along the ridge only.
  Roof roof;
  EXPECT_TRUE(facesOutwardFrom(roof.m, {0.5, 0.5, 0.2})) << "the set-up";
  std::swap(roof.m.vert[Roof::kR1].P(), roof.m.vert[Roof::kR2].P());
  EXPECT_FALSE(facesOutwardFrom(roof.m, {0.5, 0.5, 0.2})) << "the set-up: folded";
  const auto before = faceVertices(roof.m);
  std::vector<es::Vec3> positions;
  for (const auto &v : roof.m.vert) positions.push_back(es::positionOf(&v));
  const auto moved = [](std::size_t v) { return v == Roof::kR1 || v == Roof::kR2; };
  const es::PlanarFoldStats stats = es::unfoldPlanarPatches(roof.m, moved, settings(1e-6, 1e-6));
  EXPECT_GE(stats.folds, 1u);
  EXPECT_EQ(stats.relaxedVertices, 2u);
  EXPECT_EQ(faceVertices(roof.m), before);
  const auto &r1 = roof.m.vert[Roof::kR1].cP(), &r2 = roof.m.vert[Roof::kR2].cP();
  EXPECT_LT(r1[0], r2[0]);
  for (const auto *p : {&r1, &r2}) {
    EXPECT_NEAR((*p)[1], 0.5, 1e-6) << "on the ridge";
    EXPECT_NEAR((*p)[2], 0.5, 1e-6) << "on the ridge";
  }
  for (std::size_t v = 0; v < positions.size(); ++v)
    if (v != Roof::kR1 && v != Roof::kR2) {
      EXPECT_EQ(es::positionOf(&roof.m.vert[v]), positions[v])
          << "vertex " << v << " (its faces on three planes, or on one plane not folded)";
    }
  EXPECT_TRUE(facesOutwardFrom(roof.m, {0.5, 0.5, 0.2}));
  EXPECT_TRUE(hb::closedOrientedManifold(roof.m));
}

namespace {

/// The roof with R1 and R2 out of order in the input itself: a fold the
/// input has.
struct InputFoldedRoof : Roof {
  InputFoldedRoof() { std::swap(m.vert[kR1].P(), m.vert[kR2].P()); }
};

}  // namespace

TEST(PlanarFolds, AFoldTheInputHasBesideAMovedFaceSlidesAlongItsEdge) {
  // As above, but R1 and R2 came out of order in the input, and sharpening
  // moved R0, whose faces touch the fold's: the input's fold is undone like
  // one sharpening made (a remesher casting its samples onto a sharp edge
  // out of order leaves it; the surface does not change).
  InputFoldedRoof roof;
  const es::PlanarFoldStats stats = es::unfoldPlanarPatches(
      roof.m, [](std::size_t v) { return v == 4; }, settings(1e-6, 1e-6));
  EXPECT_GE(stats.folds, 1u);
  EXPECT_EQ(stats.relaxedVertices, 2u);
  const auto &r1 = roof.m.vert[Roof::kR1].cP(), &r2 = roof.m.vert[Roof::kR2].cP();
  EXPECT_LT(r1[0], r2[0]);
  for (const auto *p : {&r1, &r2}) {
    EXPECT_NEAR((*p)[1], 0.5, 1e-6) << "on the ridge";
    EXPECT_NEAR((*p)[2], 0.5, 1e-6) << "on the ridge";
  }
  EXPECT_TRUE(facesOutwardFrom(roof.m, {0.5, 0.5, 0.2}));
  EXPECT_TRUE(hb::closedOrientedManifold(roof.m));
}

TEST(PlanarFolds, AFoldTheInputHasFarFromAnyMovedVertexStays) {
  // The same input with nothing moved: a mesh the method leaves whole
  // passes as it came, its folds included.
  InputFoldedRoof roof;
  std::vector<es::Vec3> positions;
  for (const auto &v : roof.m.vert) positions.push_back(es::positionOf(&v));
  const es::PlanarFoldStats stats = es::unfoldPlanarPatches(
      roof.m, [](std::size_t) { return false; }, settings(1e-6, 1e-6));
  EXPECT_EQ(stats.folds, 0u);
  EXPECT_EQ(stats.relaxedVertices, 0u);
  for (std::size_t v = 0; v < positions.size(); ++v)
    EXPECT_EQ(es::positionOf(&roof.m.vert[v]), positions[v]) << "vertex " << v;
}

namespace {

/// A unit cube, six squares a side, with a vertex of its top (z = 1) moved
/// across the diagonal of a square beside it: that square's face turns over,
/// as it came (a fold the input has, as a cast onto a surface leaves).
struct FoldedCubeTop {
  es::Mesh m;
  FoldedCubeTop() {
    hb::voxelSurface(m, {{0, 0, 0}}, 6);
    m.vert[at(3, 2, 6)].P() = es::Mesh::CoordType(2.4f / 6, 2.6f / 6, 1);
  }
  /// The index of the vertex at grid point (i, j, k) / 6.
  std::size_t at(int i, int j, int k) const {
    for (std::size_t v = 0; v < m.vert.size(); ++v)
      if (m.vert[v].cP() == es::Mesh::CoordType(i / 6.f, j / 6.f, k / 6.f)) return v;
    ADD_FAILURE() << "no vertex at " << i << ", " << j << ", " << k;
    return 0;
  }
  /// The stage on this mesh as it came, with vertex `moved` the one moved.
  es::PlanarFoldStats unfoldWithMoved(std::size_t moved) {
    return es::unfoldPlanarPatches(
        m, [moved](std::size_t v) { return v == moved; }, settings(1e-6, 1e-6));
  }
  /// Whether every face of the top faces up (+z).
  bool topFacesUp() const {
    for (const auto &f : m.face)
      if (f.cP(0)[2] == 1 && f.cP(1)[2] == 1 && f.cP(2)[2] == 1 && hb::areaNormal(f)[2] <= 0)
        return false;
    return true;
  }
};

}  // namespace

TEST(PlanarFolds, AFoldTheInputHasNextToAMovedFaceIsTiledAgain) {
  // Sharpening moved a vertex of a face next to the input's fold: the flat
  // patch around it is tiled again, as if the fold were sharpening's own.
  FoldedCubeTop t;
  ASSERT_FALSE(t.topFacesUp()) << "the set-up: folded";
  // (3, 4) is in face ((2, 3), (3, 3), (3, 4)), next to the unfolded face
  // ((2, 2), (3, 3), (2, 3)) that the turned-over face ((2, 2), (3, 2)
  // moved, (3, 3)) is folded over.
  const es::PlanarFoldStats stats = t.unfoldWithMoved(t.at(3, 4, 6));
  EXPECT_GE(stats.folds, 1u);
  EXPECT_GE(stats.patches, 1u);
  EXPECT_EQ(stats.relaxedVertices, 0u);
  EXPECT_TRUE(t.topFacesUp());
  EXPECT_TRUE(hb::closedOrientedManifold(t.m));
}

TEST(PlanarFolds, AFoldTheInputHasFarFromAnyMovedFaceStays) {
  // The same fold, with only a vertex of the bottom moved: meshes the
  // method leaves whole pass as they came, their folds included.
  FoldedCubeTop t;
  const auto before = faceVertices(t.m);
  const es::PlanarFoldStats stats = t.unfoldWithMoved(t.at(3, 3, 0));
  EXPECT_EQ(stats.folds, 0u);
  EXPECT_EQ(stats.patches, 0u);
  EXPECT_EQ(faceVertices(t.m), before);
  EXPECT_FALSE(t.topFacesUp());
}

TEST(PlanarFolds, AFoldIsTiledAgainAcrossWhicheverOfItsEdgesAPatchIs) {
  // (2, 1) is in face ((2, 1), (3, 2) moved, (2, 2)), which the turned-over
  // face ((2, 2), (3, 2) moved, (3, 3)) is folded over across its first
  // edge: the patch of those two crosses itself. The turned-over face tiles
  // across another of its edges (that face beside it is not seeded here).
  FoldedCubeTop t;
  const es::PlanarFoldStats stats = t.unfoldWithMoved(t.at(2, 1, 6));
  EXPECT_GE(stats.patches, 1u);
  EXPECT_TRUE(t.topFacesUp());
  EXPECT_TRUE(hb::closedOrientedManifold(t.m));
}
