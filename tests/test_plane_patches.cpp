// Planes grown face by face on a rough input (extended/plane_patches.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/extended/plane_patches.h"
#include "hand_built_meshes.h"
#include "test_meshes/shapes.h"

namespace es = edge_sharpener;
using es::Vec3;

namespace {

constexpr double kDeg = M_PI / 180.0;

/// A unit cube, each face cut into n x n squares, every vertex moved by up
/// to `jitter` (in squares) along each axis: a rough box.
void roughBox(es::Mesh &m, int n, double jitter, unsigned seed) {
  es::hand_built::voxelSurface(m, {{0, 0, 0}}, n);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-jitter / n, jitter / n);
  for (auto &v : m.vert)
    v.P() += es::Mesh::CoordType(offset(random), offset(random), offset(random));
}

/// A sphere of radius 1 tessellated in rings x segments.
void sphere(es::Mesh &m, int rings, int segments) {
  const es::test_meshes::TriangleList s = es::test_meshes::detail::uvSphere(1.0, rings, segments);
  std::vector<Vec3> points;
  for (const auto &p : s.vertices) points.push_back(Vec3(p.X(), p.Y(), p.Z()));
  es::hand_built::makeMesh(m, points, s.triangles);
}

/// The axis (0, 1, 2) a unit normal lies along, or -1 when none within `tolerance`.
int axisOf(const Vec3 &n, double tolerance) {
  for (int axis = 0; axis < 3; ++axis)
    if (std::abs(n[axis]) >= std::cos(tolerance)) return axis;
  return -1;
}

}  // namespace

// Each face of a rough box is one patch, its plane along the face's axis, and
// a vertex inside a face (off the box's edges) carries that face's patch.
TEST(PlanePatches, ARoughBoxsSixFacesAreSixPlanes) {
  es::Mesh m;
  const int n = 12;
  roughBox(m, n, 0.05, 7);
  const es::VertexFaceTable vf(m);
  const es::PlanePatches patches = es::growPlanePatches(m, vf, 1.0 / n, es::PlanePatchSettings{});
  EXPECT_EQ(patches.count(), 6u);
  int axes[3] = {0, 0, 0};
  for (const es::Plane &p : patches.planes)
    if (p.normal.SquaredNorm() > 0) {
      const int axis = axisOf(p.normal, 2 * kDeg);
      ASSERT_GE(axis, 0);
      ++axes[axis];
    }
  EXPECT_EQ(axes[0], 2);
  EXPECT_EQ(axes[1], 2);
  EXPECT_EQ(axes[2], 2);
  int inside = 0;
  for (std::size_t v = 0; v < m.vert.size(); ++v) {
    const auto &p = m.vert[v].cP();
    int onSides = 0, side = -1;
    for (int axis = 0; axis < 3; ++axis)
      if (p[axis] < 0.5 / n || p[axis] > 1 - 0.5 / n) ++onSides, side = axis;
    if (onSides != 1) continue;  // on an edge, or an inner vertex of no face
    const int label = patches.labels.vertexLabel[v];
    ASSERT_GE(label, 0) << "vertex " << v;
    EXPECT_TRUE(patches.labels.inRegion[v]);
    EXPECT_EQ(axisOf(patches.planes[label].normal, 2 * kDeg), side);
    ++inside;
  }
  EXPECT_GT(inside, 6 * (n - 2) * (n - 2) / 2);
}

// A sphere has no plane: each piece the growth takes bends (the regions'
// planarity tests), and none is kept.
TEST(PlanePatches, ASphereHasNoPlanes) {
  es::Mesh m;
  sphere(m, 24, 48);
  const es::VertexFaceTable vf(m);
  const es::PlanePatches patches =
      es::growPlanePatches(m, vf, 2 * M_PI / 48, es::PlanePatchSettings{});
  EXPECT_EQ(patches.count(), 0u);
  for (std::size_t v = 0; v < m.vert.size(); ++v) {
    EXPECT_EQ(patches.labels.vertexLabel[v], es::kZone);
    EXPECT_FALSE(patches.labels.inRegion[v]);
  }
}

// With the planarity tests loosened, small pieces of a sphere pass them; each
// meets its neighbours at a small angle, so without a partner at an edge's
// angle they are dropped. Allowed a partner at a small angle, they stay.
TEST(PlanePatches, PiecesOfACurvedSurfaceNeedAPartnerAtAnEdge) {
  es::Mesh m;
  sphere(m, 48, 96);
  const es::VertexFaceTable vf(m);
  const double spacing = 2 * M_PI / 96;
  es::PlanePatchSettings loose;
  loose.maxDistanceSpacings = 0.08;
  loose.maxTurnRad = 30 * kDeg;
  loose.minAreaSpacings2 = 1;
  loose.planarity.maxRmsSpacings = 10;
  loose.planarity.maxBendRad = M_PI;
  loose.pairRings = 1;
  loose.pairAngleRad = 20 * kDeg;
  EXPECT_EQ(es::growPlanePatches(m, vf, spacing, loose).count(), 0u);
  loose.pairAngleRad = 2 * kDeg;
  EXPECT_GT(es::growPlanePatches(m, vf, spacing, loose).count(), 10u);
}

// An exact box: the patches' planes are its faces' planes.
TEST(PlanePatches, AnExactBoxsPatchesLieOnItsFaces) {
  es::Mesh m;
  es::hand_built::voxelSurface(m, {{0, 0, 0}}, 10);
  const es::VertexFaceTable vf(m);
  const es::PlanePatches patches = es::growPlanePatches(m, vf, 0.1, es::PlanePatchSettings{});
  ASSERT_EQ(patches.count(), 6u);
  for (const es::Plane &p : patches.planes) {
    if (p.normal.SquaredNorm() == 0) continue;
    const int axis = axisOf(p.normal, 1e-9);
    ASSERT_GE(axis, 0);
    EXPECT_TRUE(std::abs(p.point[axis]) < 1e-12 || std::abs(p.point[axis] - 1) < 1e-12);
  }
}
