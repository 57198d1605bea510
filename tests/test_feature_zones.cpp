// The extended method's detection (feature_zones.h) on hand-built meshes:
// segmentRegions() gives one region per flat side of voxel solids (a cube, an
// L-block) and returns thin sides to the zone as corridors by
// minRegionDepth; openRegionContacts() opens the faces where regions touch,
// except on narrow facets long enough to be surfaces;
// labelZoneVertices() gives each zone vertex the region whose plane it lies
// on, among those within maxLabelHops; projectZoneVertices()'s helpers pick
// the planes a zone vertex may go onto.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include "edge_sharpener/extended/feature_zones.h"
#include "edge_sharpener/smooth_edges.h"
#include "hand_built_meshes.h"

namespace es = edge_sharpener;
using es::Vec3;

namespace {

/// The flat side of a voxel solid a face lies on: its outward axis direction
/// and the plane's coordinate along it (in refined grid units).
using Side = std::pair<int, long>;

Side sideOf(const es::Mesh::FaceType &f, int n) {
  const Vec3 normal = es::hand_built::areaNormal(f);
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(normal[k]) > std::abs(normal[axis])) axis = k;
  const int direction = 2 * axis + (normal[axis] > 0);
  return {direction, std::lround(f.cP(0)[axis] * n)};
}

/// Smooth-edge test and region segmentation, as detection runs them.
struct Segmented {
  es::MeshLabels<es::Mesh> labels;
  es::VertexFaceTable vf;
  es::FeatureZones zones;
  es::ExtendedStats stats;

  Segmented(es::Mesh &m, int minRegionDepth) : labels(m), vf(m) {
    es::computeFaceNormals(m, labels);
    const es::SmoothEdgeStats smooth = es::labelSmoothEdges(m, labels, 2.0);
    es::segmentRegions(m, labels, vf, minRegionDepth, zones, stats, smooth.boundaryEdges > 0);
  }
};

/// Every face of a side outside `zoneSides` carries one region id, the same
/// over the side and different from every other side's; the faces of
/// `zoneSides` are in the zone.
::testing::AssertionResult oneRegionPerSide(const es::Mesh &m, int n, const es::FeatureZones &zones,
                                            const std::function<bool(Side)> &inZone) {
  std::map<Side, int> regionOfSide;
  std::set<int> ids;
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    const Side side = sideOf(m.face[f], n);
    const int r = zones.faceRegion[f];
    if (inZone(side)) {
      if (r != es::kZone)
        return ::testing::AssertionFailure() << "face " << f << " not in the zone";
      continue;
    }
    if (r == es::kZone) return ::testing::AssertionFailure() << "face " << f << " in the zone";
    const auto [it, added] = regionOfSide.emplace(side, r);
    if (added && !ids.insert(r).second)
      return ::testing::AssertionFailure() << "region " << r << " spans two sides";
    if (it->second != r)
      return ::testing::AssertionFailure() << "a side holds regions " << it->second << ", " << r;
  }
  for (const int r : ids)
    if (r < 0 || r >= int(ids.size()))
      return ::testing::AssertionFailure() << "region ids are not 0.." << ids.size() - 1;
  return ::testing::AssertionSuccess();
}

const auto kNoZone = [](Side) { return false; };

}  // namespace

TEST(SegmentRegions, OneRegionPerSideOfACube) {
  es::Mesh m;
  es::hand_built::voxelSurface(m, {{0, 0, 0}}, 3);
  Segmented s(m, 1);
  EXPECT_EQ(s.stats.regions, 6u);
  EXPECT_EQ(s.stats.corridors, 0u);
  EXPECT_EQ(s.stats.zoneFaces, 0u);
  EXPECT_TRUE(oneRegionPerSide(m, 3, s.zones, kNoZone));
}

// An L of three voxels: eight flat sides, one of the edges concave.
TEST(SegmentRegions, OneRegionPerSideOfAnLBlock) {
  es::Mesh m;
  es::hand_built::voxelSurface(m, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 2);
  ASSERT_TRUE(es::hand_built::closedOrientedManifold(m));
  Segmented s(m, 1);
  EXPECT_EQ(s.stats.regions, 8u);
  EXPECT_EQ(s.stats.corridors, 0u);
  EXPECT_TRUE(oneRegionPerSide(m, 2, s.zones, kNoZone));
}

// A plate of 4 x 4 x 1 voxels cut in 2 x 2: its rims are bands two
// triangles high (depth 1 from their border), top and bottom reach depth 4.
// minRegionDepth 2 turns the rims into corridors, which join the zone.
TEST(SegmentRegions, ThinBandsBecomeCorridorsBelowMinRegionDepth) {
  std::vector<std::array<int, 3>> cells;
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y) cells.push_back({x, y, 0});
  const auto isRim = [](Side side) { return side.first / 2 != 2; };  // normal not along z
  for (const int minDepth : {1, 2}) {
    SCOPED_TRACE(minDepth);
    es::Mesh m;
    es::hand_built::voxelSurface(m, cells, 2);
    Segmented s(m, minDepth);
    std::size_t rimFaces = 0;
    for (const auto &f : m.face) rimFaces += isRim(sideOf(f, 2));
    if (minDepth == 1) {
      EXPECT_EQ(s.stats.regions, 6u);
      EXPECT_EQ(s.stats.corridors, 0u);
      EXPECT_TRUE(oneRegionPerSide(m, 2, s.zones, kNoZone));
    } else {
      EXPECT_EQ(s.stats.regions, 2u);
      EXPECT_EQ(s.stats.corridors, 4u);
      EXPECT_EQ(s.stats.zoneFaces, rimFaces);
      EXPECT_TRUE(oneRegionPerSide(m, 2, s.zones, isRim));
    }
  }
}

// Where two sides of the cube meet, their regions touch without a zone
// between them: every face with a vertex on a cube edge returns to the zone.
TEST(OpenRegionContacts, OpensTheFacesAroundWhereRegionsTouch) {
  es::Mesh m;
  es::hand_built::voxelSurface(m, {{0, 0, 0}}, 3);
  Segmented s(m, 1);
  ASSERT_EQ(s.stats.regions, 6u);
  const std::vector<int> before = s.zones.faceRegion;
  const auto onCubeEdge = [](const vcg::Point3f &p) {
    int onBorder = 0;
    for (int k = 0; k < 3; ++k) onBorder += p[k] == 0 || p[k] == 1;
    return onBorder >= 2;
  };
  std::size_t touching = 0;
  std::vector<char> opens(m.face.size(), 0);
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    for (int k = 0; k < 3; ++k) opens[f] |= onCubeEdge(m.face[f].cP(k));
    touching += opens[f];
  }
  ASSERT_GT(touching, 0u);
  ASSERT_LT(touching, m.face.size());

  // Every side would be left without an interior vertex, and each spans
  // sqrt(2) < 1.5: none is long enough to be kept as a narrow facet.
  std::size_t kept = 99;
  EXPECT_EQ(es::openRegionContacts(m, s.vf, s.zones, 1.5, kept), touching);
  EXPECT_EQ(kept, 0u);
  for (std::size_t f = 0; f < m.face.size(); ++f)
    EXPECT_EQ(s.zones.faceRegion[f], opens[f] ? es::kZone : before[f]) << "face " << f;
}

// A bar of 1 x 1 x 8 voxels, two cells to a voxel: its four long sides are
// facets two cells wide, whose every face touches another side, so opening
// the contacts would leave them no interior vertex. Spanning 8, they keep
// their faces; the square ends (span sqrt(2)) open. With no length given,
// every side opens; on a finer bar (four cells a voxel) every side keeps an
// interior vertex and opens at its contacts whatever the length.
TEST(OpenRegionContacts, NarrowFacetsLongerThanTheLengthKeepTheirFaces) {
  std::vector<std::array<int, 3>> cells;
  for (int z = 0; z < 8; ++z) cells.push_back({0, 0, z});
  const auto isEnd = [](Side side) { return side.first / 2 == 2; };  // normal along z
  for (const int n : {2, 4})
    for (const double minLength : {0.0, 4.0}) {
      SCOPED_TRACE(testing::Message() << "cells a voxel " << n << ", length " << minLength);
      es::Mesh m;
      es::hand_built::voxelSurface(m, cells, n);
      Segmented s(m, 1);
      ASSERT_EQ(s.stats.regions, 6u);
      const std::vector<int> before = s.zones.faceRegion;
      std::size_t kept = 99;
      const std::size_t opened = es::openRegionContacts(m, s.vf, s.zones, minLength, kept);
      const bool keepsLongSides = n == 2 && minLength > 0;
      EXPECT_EQ(kept, keepsLongSides ? 4u : 0u);
      std::size_t endFaces = 0, openedOnLongSides = 0;
      for (std::size_t f = 0; f < m.face.size(); ++f) {
        const bool end = isEnd(sideOf(m.face[f], n));
        endFaces += end;
        if (!end) openedOnLongSides += s.zones.faceRegion[f] == es::kZone;
        if (end || !keepsLongSides) continue;
        EXPECT_EQ(s.zones.faceRegion[f], before[f]) << "face " << f;
      }
      if (n == 2) {  // every face of an end touches another side
        EXPECT_EQ(opened - openedOnLongSides, endFaces);
      }
      EXPECT_EQ(openedOnLongSides > 0, !keepsLongSides);
    }
}

namespace {

// A height field, flat (z = 0) up to the sharp edge at x = 1.13 and falling
// at 45 degrees after it. Region 0: faces with x <= 0.8, region 1: x >= 1.3;
// the zone's vertex columns x = 0.9 .. 1.2 lie on the flat plane up to 1.1
// and on the slope at 1.2.
constexpr int kNx = 20, kNy = 6;
constexpr double kH = 0.1, kEdgeX = 1.13;

struct TwoPlanes {
  es::Mesh m;
  es::FeatureZones zones;

  TwoPlanes() {
    es::hand_built::heightField(m, kNx, kNy, kH,
                                [](double x, double) { return x <= kEdgeX ? 0.0 : kEdgeX - x; });
    zones.faceRegion = es::hand_built::regionsAcrossX(m, 0.8, 1.3, es::kZone);
  }
  static int column(std::size_t v) { return int(v % (kNx + 1)); }
};

const Vec3 kNormalOf[2] = {Vec3(0, 0, 1), Vec3(1, 0, 1) / std::sqrt(2.0)};

}  // namespace

// Column 1.1 is 2 hops from region 1 and 3 from region 0, yet lies on
// region 0's plane: it samples the flat side and takes its label.
TEST(LabelZoneVertices, ZoneVerticesTakeTheRegionWhosePlaneTheyLieOn) {
  TwoPlanes t;
  const es::VertexFaceTable vf(t.m);
  es::SharpenOptions opt;
  opt.method = es::Method::Extended;
  ASSERT_EQ(opt.extended.maxLabelHops, 3);
  es::ExtendedStats stats;
  es::labelZoneVertices(t.m, vf, opt, t.zones, stats);
  EXPECT_EQ(stats.zoneVertices, std::size_t(4 * (kNy + 1)));
  EXPECT_EQ(stats.labelledZoneVertices, stats.zoneVertices);
  for (std::size_t v = 0; v < t.m.vert.size(); ++v) {
    const int col = TwoPlanes::column(v);
    const int expected = col <= 11 ? 0 : 1;  // x = 1.1 still lies on the flat side
    EXPECT_EQ(t.zones.vertexLabel[v], expected) << "vertex " << v << " column " << col;
    EXPECT_EQ(bool(t.zones.inRegion[v]), col <= 8 || col >= 13) << "vertex " << v;
    if (col < 8 || col > 13) continue;  // fitted planes: the region border and the zone
    const es::Plane &plane = t.zones.support.plane(v);
    EXPECT_LT(es::angleBetween(plane.normal, kNormalOf[expected]), 1e-6) << "vertex " << v;
    EXPECT_LT(std::abs(plane.normal * (es::positionOf(&t.m.vert[v]) - plane.point)), 1e-6)
        << "vertex " << v << " off its plane";
  }
}

// With maxLabelHops 1 only the zone columns next to a region are labelled.
TEST(LabelZoneVertices, VerticesBeyondMaxLabelHopsStayUnlabelled) {
  TwoPlanes t;
  const es::VertexFaceTable vf(t.m);
  es::SharpenOptions opt;
  opt.method = es::Method::Extended;
  opt.extended.maxLabelHops = 1;
  es::ExtendedStats stats;
  es::labelZoneVertices(t.m, vf, opt, t.zones, stats);
  EXPECT_EQ(stats.zoneVertices, std::size_t(4 * (kNy + 1)));
  EXPECT_EQ(stats.labelledZoneVertices, std::size_t(2 * (kNy + 1)));
  for (std::size_t v = 0; v < t.m.vert.size(); ++v) {
    const int col = TwoPlanes::column(v);
    const int expected = col <= 9 ? 0 : col >= 12 ? 1 : es::kZone;
    EXPECT_EQ(t.zones.vertexLabel[v], expected) << "vertex " << v << " column " << col;
  }
}

// Where two regions meet with no zone between them, their shared vertices
// are creases (already sharp), not labelled with either region.
TEST(LabelZoneVertices, VerticesSharedByTwoRegionsAreCreases) {
  TwoPlanes t;
  for (std::size_t f = 0; f < t.m.face.size(); ++f) {
    double cx = 0;
    for (int k = 0; k < 3; ++k) cx += t.m.face[f].cP(k)[0] / 3.0;
    t.zones.faceRegion[f] = cx < 1.0 ? 0 : 1;
  }
  const es::VertexFaceTable vf(t.m);
  es::SharpenOptions opt;
  es::ExtendedStats stats;
  es::labelZoneVertices(t.m, vf, opt, t.zones, stats);
  EXPECT_EQ(stats.zoneVertices, 0u);
  for (std::size_t v = 0; v < t.m.vert.size(); ++v) {
    const int col = TwoPlanes::column(v);
    EXPECT_EQ(t.zones.vertexLabel[v], col < 10 ? 0 : col > 10 ? 1 : es::kCrease) << "vertex " << v;
    EXPECT_TRUE(t.zones.inRegion[v]);
  }
}

// A zone vertex inside a convex corner's cell, (0.4, 0.4, 0.4) off the faces
// x = 0, y = 0, z = 0: projected onto z = 0 it stays as far from the other
// two, so that plane may take it; a move that takes it farther from one of
// its planes (onto a plane turned towards another) may not.
TEST(ProjectZoneVertices, ANeighboursPlaneTakesAVertexOnlyNoFartherFromItsOtherPlanes) {
  const es::Plane x{Vec3(0, 0, 0), Vec3(1, 0, 0)}, y{Vec3(0, 0, 0), Vec3(0, 1, 0)},
      z{Vec3(0, 0, 0), Vec3(0, 0, 1)};
  const std::array<const es::Plane *, 4> corner{&x, &y, &z, &z};
  const Vec3 p(0.4, 0.4, 0.4);
  EXPECT_TRUE(es::detail::noFartherFromPlanes(corner, 3, p, es::projectOntoPlane(z, p), 1e-12));
  EXPECT_TRUE(es::detail::noFartherFromPlanes(corner, 3, p, es::projectOntoPlane(y, p), 1e-12));
  const es::Plane tilted{Vec3(0, 0, 0), Vec3(1, 0, 1) / std::sqrt(2.0)};
  const Vec3 onTilted = es::projectOntoPlane(tilted, Vec3(0.4, 0.4, 0.1));
  EXPECT_FALSE(es::detail::noFartherFromPlanes(corner, 3, Vec3(0.4, 0.4, 0.1), onTilted, 1e-12))
      << "moved along (1, 0, 1): farther from z = 0";
  // Zero normals (no plane) are skipped.
  const es::Plane none{Vec3(0, 0, 0), Vec3(0, 0, 0)};
  const std::array<const es::Plane *, 4> withNone{&none, &z, &none, &none};
  EXPECT_TRUE(es::detail::noFartherFromPlanes(withNone, 2, p, es::projectOntoPlane(z, p), 0));
}

// Moving vertex 0 across: a face of area that the move would fold refuses
// it; a face whose other two corners sit at one point (two new vertices
// placed on one target of a grid-aligned edge), exactly or up to a float's
// rounding, has no way to face, before or after, and does not.
TEST(ProjectZoneVertices, AFaceWithoutAreaDoesNotRefuseAMove) {
  es::Mesh m;
  es::hand_built::makeMesh(m,
                           {Vec3(0, 0, 0.3), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0),
                            Vec3(0, -1, 0), Vec3(-1, 0, 0), Vec3(-1, 1e-7, 0)},
                           {{0, 1, 2}, {0, 3, 5}, {0, 6, 3}});
  const double degenerate = 1.0 * M_PI / 180.0;
  const std::vector<std::uint32_t> areaFace{0}, noAreaFace{1};
  // Down onto z = 0, within the triangle: the face keeps facing +z.
  EXPECT_TRUE(es::detail::moveKeepsFaces(m, areaFace, 0, Vec3(0.3, 0.3, 0), degenerate));
  // Beyond the edge from 1 to 2: the face would face -z.
  EXPECT_FALSE(es::detail::moveKeepsFaces(m, areaFace, 0, Vec3(1, 1, 0), degenerate));
  // Corners 3 and 5 coincide: no area before, none after, wherever 0 goes.
  EXPECT_TRUE(es::detail::moveKeepsFaces(m, noAreaFace, 0, Vec3(0.3, 0.3, 0), degenerate));
  const std::vector<std::uint32_t> rounded{2};
  EXPECT_TRUE(es::detail::moveKeepsFaces(m, rounded, 0, Vec3(0.3, 0.3, 0), degenerate))
      << "corners 1e-7 apart: a float's rounding of one point";
  const std::vector<std::uint32_t> both{0, 1};
  EXPECT_TRUE(es::detail::moveKeepsFaces(m, both, 0, Vec3(0.3, 0.3, 0), degenerate));
  EXPECT_FALSE(es::detail::moveKeepsFaces(m, both, 0, Vec3(1, 1, 0), degenerate))
      << "the face with area still refuses";
}

namespace {

// Face 0: vertex 0 0.01 off the segment from 1 to 2 (angles near 1.1 and 0.6
// degrees); face 1: a fair triangle on vertex 3.
void makeSliverAndFairFace(es::Mesh &m) {
  es::hand_built::makeMesh(m,
                           {Vec3(0, 0.01, 0), Vec3(-0.5, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),
                            Vec3(1, 1, 0), Vec3(0, 2, 0)},
                           {{0, 1, 2}, {3, 4, 5}});
}

}  // namespace

// A face that was already a sliver (v beside two new vertices on the
// restored line, a marching-cubes vertex half a cell off an edge) may stay one:
// the cleanup removes it. A face with good angles may not become one, and no
// face may turn over.
TEST(ProjectZoneVertices, ASliverMayStayASliver) {
  es::Mesh m;
  makeSliverAndFairFace(m);
  const double degenerate = 1.0 * M_PI / 180.0;
  const std::vector<std::uint32_t> sliver{0}, fair{1};
  EXPECT_TRUE(es::detail::moveKeepsFaces(m, sliver, 0, Vec3(0, 0.005, 0), degenerate))
      << "thinner, still facing +z";
  EXPECT_FALSE(es::detail::moveKeepsFaces(m, sliver, 0, Vec3(0, -0.005, 0), degenerate))
      << "across the line: turned over";
  EXPECT_TRUE(es::detail::moveKeepsFaces(m, fair, 3, Vec3(0.1, 1, 0), degenerate));
  EXPECT_FALSE(es::detail::moveKeepsFaces(m, fair, 3, Vec3(0.5, 1.5 - 0.004, 0), degenerate))
      << "onto the segment from 4 to 5, less than a degree off it";
}

// Onto the restored line (a zone vertex on the edge itself, between new
// vertices placed on it): a face whose other two corners are new vertices
// and that is left with an angle below the degenerate one refuses nothing,
// whichever way it faces, since the cleanup removes it; the same face
// between input vertices still refuses a turn, and a fair face may never
// turn over.
TEST(ProjectZoneVertices, ASliverBetweenNewVerticesRefusesNothing) {
  es::Mesh m;
  makeSliverAndFairFace(m);
  const double degenerate = 1.0 * M_PI / 180.0;
  const std::vector<std::uint32_t> sliver{0}, fair{1};
  const std::size_t newFrom1 = 1;  // vertices 1 to 5 are new ones
  EXPECT_TRUE(es::detail::moveKeepsFaces(m, sliver, 0, Vec3(0, 0, 0), degenerate, newFrom1))
      << "onto the line through 1 and 2: no area left";
  EXPECT_TRUE(es::detail::moveKeepsFaces(m, sliver, 0, Vec3(0, -0.005, 0), degenerate, newFrom1))
      << "just across it: a sliver facing -z";
  EXPECT_FALSE(es::detail::moveKeepsFaces(m, sliver, 0, Vec3(0, -0.005, 0), degenerate))
      << "1 and 2 input vertices: turned over";
  EXPECT_FALSE(es::detail::moveKeepsFaces(m, sliver, 0, Vec3(0, -0.005, 0), degenerate, 2))
      << "only 2 new: turned over";
  EXPECT_FALSE(es::detail::moveKeepsFaces(m, fair, 3, Vec3(1, 2, 0), degenerate, newFrom1))
      << "a fair face turned over";
}

// The planes tried for a zone vertex: its own first, then those of the
// vertices listed nearby, closest first, up to the first padding entry;
// nearby vertices without a plane are skipped.
TEST(ProjectZoneVertices, OwnPlaneFirstThenTheNearbyRegionsPlanes) {
  es::SupportPlanes support;
  support.reset(5);
  const auto fitWithNormal = [](const Vec3 &n) {
    return es::SupportFit::of(es::Plane{Vec3(0, 0, 0), n});
  };
  support.setFit(0, fitWithNormal(Vec3(1, 0, 0)));
  support.setFit(1, fitWithNormal(Vec3(0, 1, 0)));
  support.setFit(3, fitWithNormal(Vec3(0, 0, 1)));
  constexpr std::uint32_t kNo = es::SupportPlanes::kNoVertex;
  support.nearby.assign(5, {kNo, kNo, kNo});
  support.nearby[0] = {1, 2, 3};  // vertex 2 has no plane
  std::array<const es::Plane *, 4> planes{};
  ASSERT_EQ(es::detail::projectionPlanes(support, 0, planes), 3);
  EXPECT_EQ(planes[0], &support.plane(0));
  EXPECT_EQ(planes[1], &support.plane(1));
  EXPECT_EQ(planes[2], &support.plane(3));
  EXPECT_EQ(es::detail::projectionPlanes(support, 4, planes), 1) << "nothing nearby: own only";
}
