// Planar regions (extended/planar_regions.h) and placement on their own
// planes (placement.h: detail::onRegionPlanes).
#include <gtest/gtest.h>

#include <cmath>

#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/extended/zone_labels.h"
#include "edge_sharpener/placement.h"
#include "hand_built_meshes.h"

namespace es = edge_sharpener;
using es::Vec3;

TEST(PlanarRegions, PrincipalAxesFollowTheLongerExtent) {
  const auto basis = es::detail::inPlaneBasis(Vec3(0, 0, 1));
  EXPECT_NEAR(basis[0] * basis[1], 0, 1e-12);
  EXPECT_NEAR(basis[0] * Vec3(0, 0, 1), 0, 1e-12);
  EXPECT_NEAR(basis[1].Norm(), 1, 1e-12);
  // Points along the line at 30 degrees to basis[0], spread 10:1 across it.
  const double a = 30 * M_PI / 180;
  const Vec3 along = basis[0] * std::cos(a) + basis[1] * std::sin(a);
  const Vec3 across = basis[0] * -std::sin(a) + basis[1] * std::cos(a);
  double xx = 0, xy = 0, yy = 0;
  for (int i = -10; i <= 10; ++i)
    for (int j = -1; j <= 1; ++j) {
      const Vec3 p = along * double(i) + across * double(j);
      const double x = p * basis[0], y = p * basis[1];
      xx += x * x, xy += x * y, yy += y * y;
    }
  const auto axes = es::detail::principalAxes(basis, xx, xy, yy);
  EXPECT_NEAR(std::abs(axes[0] * along), 1, 1e-9);
  EXPECT_NEAR(std::abs(axes[1] * across), 1, 1e-9);
}

namespace {

// A height field with a sharp edge at x = kEdgeX: flat (z = 0) before it
// and, after it, a slope of 45 degrees that `bend` curves (z'' = -bend).
// Region 0: faces with x <= kEdgeX - 0.35, region 1: x >= kEdgeX + 0.15;
// the zone between.
constexpr int kNx = 40, kNy = 16;
constexpr double kH = 0.1, kEdgeX = 2.03;

struct EdgeField {
  es::Mesh m;
  es::FeatureZones zones;
  es::ExtendedStats stats;

  explicit EdgeField(double bend) {
    es::hand_built::heightField(m, kNx, kNy, kH, [bend](double x, double) {
      const double t = x - kEdgeX;
      return t <= 0 ? 0.0 : -t - 0.5 * bend * t * t;
    });
    zones.faceRegion = es::hand_built::regionsAcrossX(m, kEdgeX - 0.35, kEdgeX + 0.15, es::kZone);
    const es::VertexFaceTable vf(m);
    es::SharpenOptions opt;
    opt.method = es::Method::Extended;
    zones.support.sampleSpacing = kH;
    es::labelZoneVertices(m, vf, opt, zones, stats);
  }
  bool planar(int r) const { return zones.support.regionPlanes.at(r).normal.SquaredNorm() > 0; }
};

}  // namespace

TEST(PlanarRegions, TwoFlatRegionsAreTheirOwnPlanes) {
  EdgeField t(0.0);
  ASSERT_EQ(t.zones.support.regionPlanes.size(), 2u);
  EXPECT_EQ(t.stats.planarRegions, 2u);
  const es::Plane &flat = t.zones.support.regionPlanes[0], &slope = t.zones.support.regionPlanes[1];
  EXPECT_LT(es::angleBetween(flat.normal, Vec3(0, 0, 1)), 1e-6);
  EXPECT_LT(es::angleBetween(slope.normal, Vec3(1, 0, 1) / std::sqrt(2.0)), 1e-6);
  EXPECT_NEAR(flat.normal * flat.point, 0, 1e-6);
  EXPECT_NEAR(slope.normal * (slope.point - Vec3(kEdgeX, 0, 0)), 0, 1e-6);
}

// The slope turns by about 20 degrees over its 1.9 units: its core's halves
// turn by far more than the bound, and it is no plane; the flat side is one.
TEST(PlanarRegions, ACurvedRegionIsNotAPlane) {
  EdgeField t(0.2);
  EXPECT_TRUE(t.planar(0));
  EXPECT_FALSE(t.planar(1));
  EXPECT_EQ(t.stats.planarRegions, 1u);
}

// A sharp cube of 12 x 12 quads a side: each side's core holds the faces
// 3 hops inside it.
TEST(PlanarRegions, ACubesSidesArePlanesUnlessTheOptionIsOff) {
  for (const bool on : {true, false}) {
    SCOPED_TRACE(on);
    es::Mesh m;
    es::hand_built::voxelSurface(m, {{0, 0, 0}}, 12);
    es::SharpenOptions opt;
    opt.extended.regionPlanes = on;
    const es::SharpenReport r = es::sharpen(m, opt);
    EXPECT_EQ(r.extended.planarRegions, on ? 6u : 0u);
  }
}

namespace {

// Two sources on the planes z = 0 (region 0) and x = 0 (region 1), whose
// fits next to the feature tilt by `tilt` radians towards each other.
struct TwoSources {
  es::SupportPlanes support;
  es::InsertedVertexSource src;
  es::SharpenOptions opt;

  TwoSources(double tilt, double spacing) {
    support.reset(3);
    support.sampleSpacing = spacing;
    support.region = {0, 1, 2};
    support.nearby.assign(3, {es::SupportPlanes::kNoVertex, es::SupportPlanes::kNoVertex,
                              es::SupportPlanes::kNoVertex});
    support.setFit(0,
                   es::SupportFit::of({Vec3(0.05, 0, 0), Vec3(std::sin(tilt), 0, std::cos(tilt))}));
    support.setFit(1,
                   es::SupportFit::of({Vec3(0, 0, 0.05), Vec3(std::cos(tilt), 0, std::sin(tilt))}));
    support.setFit(2, es::SupportFit::of({Vec3(0, 0, 0.5), Vec3(0, 0, 1)}));
    support.regionPlanes = {es::Plane{Vec3(1, 0, 0), Vec3(0, 0, 1)},
                            es::Plane{Vec3(0, 0, 1), Vec3(1, 0, 0)},
                            es::Plane{Vec3(0, 0, 0.5), Vec3(0, 0, 1)}};
    src.original = {0, 1, 0};
    src.originalCount = 2;
    src.rest = Vec3(0.03, 0.2, 0.03);
    opt.method = es::Method::Auto;
  }
  /// Region 2, of plane `own`, lies near source `source`.
  TwoSources &nearThirdRegion(const es::Plane &own, int source) {
    support.regionPlanes[2] = own;
    support.nearby[source][0] = 2;
    return *this;
  }
  /// Where placement puts the vertex: between the fits, then onRegionPlanes
  /// (with its edge's typical turn, OwnPlaneTurns; negative: not known).
  Vec3 placed(double typicalTurnDeg = -1) const {
    const es::Plane fits[2] = {support.plane(0), support.plane(1)};
    Vec3 target;
    EXPECT_EQ(es::paperPlacement(src, fits, es::PlacementPolicy::autoMethod(opt).paper, target),
              es::Placement::Moved);
    const double typical = typicalTurnDeg < 0 ? -1 : typicalTurnDeg * M_PI / 180.0;
    es::detail::onRegionPlanes(src, support, es::PlacementPolicy::autoMethod(opt).paper, target,
                               typical);
    return target;
  }
};

const Vec3 kOnOwnPlanes(0, 0.2, 0);

}  // namespace

// The fits meet about 0.0034 from the own planes' line.
TEST(OnRegionPlanes, TheTargetMovesOntoTheRegionsOwnPlanes) {
  EXPECT_LT((TwoSources(0.05, 0.02).placed() - kOnOwnPlanes).Norm(), 1e-9);
}

// Region 2's plane (z = 0.5) lies between the flanks' (z = 0 and x = 0 at
// z = 1): no edge of theirs ends at it.
TEST(OnRegionPlanes, NotNearAThirdPlaneBetweenTheFlanks) {
  TwoSources t(0.05, 0.1);
  t.support.nearby[0][0] = 2;  // its own plane, z = 0.5, as set up
  EXPECT_GT((t.placed() - kOnOwnPlanes).Norm(), 1e-3);
}

TEST(OnRegionPlanes, NotNearAThirdRegionThatIsNoPlane) {
  const TwoSources t = TwoSources(0.05, 0.02).nearThirdRegion({Vec3(0, 0.5, 0), Vec3(0, 0, 0)}, 0);
  EXPECT_GT((t.placed() - kOnOwnPlanes).Norm(), 1e-3);
}

// An end face y = 0.5 beyond the vertex: the line runs on to it.
TEST(OnRegionPlanes, NearACornerBeforeTheEndFace) {
  const TwoSources t = TwoSources(0.05, 0.02).nearThirdRegion({Vec3(0, 0.5, 0), Vec3(0, 1, 0)}, 1);
  EXPECT_LT((t.placed() - kOnOwnPlanes).Norm(), 1e-9);
}

// An end face y = 0.15 short of the point nearest the vertex: the line
// stops at the corner where the three planes meet.
TEST(OnRegionPlanes, NearACornerTheLineStopsAtTheEndFace) {
  const TwoSources t = TwoSources(0.05, 0.1).nearThirdRegion({Vec3(0, 0.15, 0), Vec3(0, 1, 0)}, 1);
  EXPECT_LT((t.placed() - Vec3(0, 0.15, 0)).Norm(), 1e-9);
}

TEST(OnRegionPlanes, NotWhereARegionIsNoPlane) {
  TwoSources t(0.05, 0.1);
  t.support.regionPlanes[1] = es::Plane{Vec3(0, 0, 0), Vec3(0, 0, 0)};
  EXPECT_GT((t.placed() - kOnOwnPlanes).Norm(), 1e-3);
}

// A vertex whose flank bends away (a curved face beside a plane: a
// cylinder's rim) takes its planar flank's own plane; the curved flank keeps
// its fit (bent by its curvature where the fits measured one).
TEST(OnRegionPlanes, ABentVertexBesideACurvedRegionTakesThePlanarFlanksOwnPlane) {
  TwoSources t(0.05, 0.02);
  t.support.regionPlanes[1] = es::Plane{Vec3(0, 0, 0), Vec3(0, 0, 0)};
  const es::Plane fits[2] = {t.support.plane(0), t.support.plane(1)};
  const es::PaperSettings paper = es::PlacementPolicy::autoMethod(t.opt).paper;
  Vec3 target;
  es::paperPlacement(t.src, fits, paper, target);
  es::detail::onRegionPlanes(t.src, t.support, paper, target, -1, /*bent=*/true);
  EXPECT_NEAR(target.Z(), 0.0, 1e-9);
  EXPECT_NEAR(fits[1].normal * (target - fits[1].point), 0.0, 1e-9);
  EXPECT_GT((target - kOnOwnPlanes).Norm(), 1e-3);
}

// A region's plane passing a sample spacing from the samples fitted next to
// the feature (a large, slightly curved face taken for a plane) does not
// model that flank there: it keeps its fit, and the other flank its own plane.
TEST(OnRegionPlanes, NotWhereTheRegionsPlanePassesFarFromTheFlanksSamples) {
  TwoSources t(0.05, 0.03);
  t.support.regionPlanes[0] = es::Plane{Vec3(0, 0, -0.02), Vec3(0, 0, 1)};  // 0.67 spacings off
  t.support.regionPlanes[1] = es::Plane{Vec3(-0.01, 0, 0), Vec3(1, 0, 0)};  // 0.33 spacings off
  const es::Plane fits[2] = {t.support.plane(0), t.support.plane(1)};
  const es::PaperSettings paper = es::PlacementPolicy::autoMethod(t.opt).paper;
  for (const double bound : {-1.0, t.opt.rules.feature.maxFeatureOffPlaneSpacings}) {
    SCOPED_TRACE(bound);
    Vec3 target;
    es::paperPlacement(t.src, fits, paper, target);
    es::detail::onRegionPlanes(t.src, t.support, paper, target, -1, false, bound);
    EXPECT_NEAR(target.X(), -0.01, 1e-9);
    if (bound < 0)
      EXPECT_NEAR(target.Z(), -0.02, 1e-9);
    else
      EXPECT_NEAR(fits[0].normal * (target - fits[0].point), 0.0, 1e-9);
  }
}

TEST(OnRegionPlanes, NotWhereNoRegionIsAPlane) {
  TwoSources t(0.05, 0.02);
  t.support.regionPlanes[0] = t.support.regionPlanes[1] = es::Plane{Vec3(0, 0, 0), Vec3(0, 0, 0)};
  const es::Plane fits[2] = {t.support.plane(0), t.support.plane(1)};
  Vec3 between;
  es::paperPlacement(t.src, fits, es::PlacementPolicy::autoMethod(t.opt).paper, between);
  EXPECT_LT((t.placed() - between).Norm(), 1e-12);
}

// The fits meet 0.0034 from the own planes' line: under a tenth of a
// sample spacing of 0.1, they are as good.
TEST(OnRegionPlanes, NotForAShiftUnderATenthOfASpacing) {
  TwoSources t(0.05, 0.1);
  EXPECT_GT((t.placed() - kOnOwnPlanes).Norm(), 1e-3);
}

// With a sample spacing of 0.002 the fits meet farther than one spacing
// from the own planes' line: the vetoes judged the move from there, so it
// stays.
TEST(OnRegionPlanes, NotFartherThanOneSampleSpacing) {
  TwoSources t(0.05, 0.002);
  EXPECT_GT((t.placed() - kOnOwnPlanes).Norm(), t.support.sampleSpacing);
}

namespace {

/// Source 0's fit turned by `turnDeg` about the edge's direction, through a
/// point beside its region's plane z = 0: the fits meet 0.013-0.02 from the
/// own planes' line, within a sample spacing of 0.1.
TwoSources withSource0FitTurned(double turnDeg) {
  TwoSources t(0.05, 0.1);
  const double turn = turnDeg * M_PI / 180.0;
  t.support.setFit(0,
                   es::SupportFit::of({Vec3(0.03, 0, 0), Vec3(std::sin(turn), 0, std::cos(turn))}));
  return t;
}

}  // namespace

// A fit turned 35 degrees from its region's plane lies on another surface
// the region took in (a conical chamfer beside a flat top): the fits place
// the vertex, not the region's core.
TEST(OnRegionPlanes, NotWhereAFitTurnsFarFromItsRegionsPlane) {
  const Vec3 placed = withSource0FitTurned(35).placed();
  EXPECT_GT((placed - kOnOwnPlanes).Norm(), 0.01);
}

TEST(OnRegionPlanes, WhereAFitTurnsLessFromItsRegionsPlane) {
  const Vec3 placed = withSource0FitTurned(25).placed();
  EXPECT_LT((placed - kOnOwnPlanes).Norm(), 1e-9);
}

// Along an edge whose fits turn 2 degrees from the own planes, a fit turned
// 25 degrees sees where the flank runs on into another surface (a fillet at
// the edge's end): the own planes' line would run on straight past it.
TEST(OnRegionPlanes, NotWhereAFitTurnsFarBeyondItsEdgesTypicalTurn) {
  const Vec3 placed = withSource0FitTurned(25).placed(/*typicalTurnDeg=*/2);
  EXPECT_GT((placed - kOnOwnPlanes).Norm(), 0.01);
}

// A reconstruction rounds the whole edge alike: its fits all turn about as
// far, and the own planes correct them.
TEST(OnRegionPlanes, WhereTheEdgesFitsTurnAlike) {
  const Vec3 placed = withSource0FitTurned(25).placed(/*typicalTurnDeg=*/10);
  EXPECT_LT((placed - kOnOwnPlanes).Norm(), 1e-9);
}

// The typical turn of an edge is the median over its vertices of the
// largest turn of their sources' fits from their regions' own planes.
TEST(OwnPlaneTurns, TheMedianTurnOfAnEdgesVertices) {
  es::SupportPlanes support;
  support.reset(5);
  support.sampleSpacing = 0.1;
  support.region = {0, 1, 0, 0, 2};
  const auto turned = [](double deg) {
    const double a = deg * M_PI / 180.0;
    return Vec3(std::sin(a), 0, std::cos(a));
  };
  support.setFit(0, es::SupportFit::of({Vec3(0, 0, 0), turned(0)}));
  support.setFit(1, es::SupportFit::of({Vec3(0, 0, 0), Vec3(1, 0, 0)}));
  support.setFit(2, es::SupportFit::of({Vec3(0, 0, 0), turned(4)}));
  support.setFit(3, es::SupportFit::of({Vec3(0, 0, 0), turned(25)}));
  support.setFit(4, es::SupportFit::of({Vec3(0, 0, 0), Vec3(0, 1, 0)}));
  support.regionPlanes = {es::Plane{Vec3(0, 0, 0), Vec3(0, 0, 1)},
                          es::Plane{Vec3(0, 0, 0), Vec3(1, 0, 0)},
                          es::Plane{Vec3(0, 0, 0), Vec3(0, 0, 0)}};  // region 2: no plane
  const auto source = [](std::size_t a, std::size_t b, std::size_t c = 0, int count = 2) {
    es::InsertedVertexSource src;
    src.original = {a, b, c};
    src.originalCount = count;
    return src;
  };
  es::SplitPlan plan;
  plan.originalVertexCount = 5;
  plan.inserted = {source(0, 1), source(2, 1), source(1, 3), source(0, 4)};
  const es::OwnPlaneTurns turns(plan, support);
  // Edge (0, 1): turns 0, 4 and 25 degrees; the fit beside region 1 is exact.
  EXPECT_NEAR(turns.typicalRad(source(3, 1), support) * 180 / M_PI, 4, 1e-9);
  // Edge (0, 2): region 2 is no plane; the turn is its planar flank's.
  EXPECT_NEAR(turns.typicalRad(source(0, 4), support), 0, 1e-12);
  EXPECT_LT(turns.typicalRad(source(0, 1, 2, 3), support), 0);          // a corner
  EXPECT_LT(es::OwnPlaneTurns().typicalRad(source(0, 1), support), 0);  // none measured
}

TEST(PlanarRegions, OutwardSignFollowsTheFacesOrientation) {
  es::Mesh m;
  es::hand_built::voxelSurface(m, {{0, 0, 0}}, 4);
  EXPECT_EQ(es::outwardSign(m), 1);
  for (auto &f : m.face) std::swap(f.V(1), f.V(2));
  EXPECT_EQ(es::outwardSign(m), -1);
}

// A rough input's planar regions (flattenPlanarRegions): of the vertices
// labelled with the flat region, one of its own raised above its plane
// (outside: the height field's faces face +z) within the bound goes back onto
// it, and so does a zone vertex raised as much; one lowered (inside, as a
// convex blend lies) and one raised beyond the bound stay. A vertex given the
// flat region's label past the edge does not go onto the flat plane (that
// place lies beyond the slope's plane, off the flat face): it lies outside
// the slope's plane too, and goes to the nearest point behind both, on the
// slope.
TEST(PlanarRegions, FlatteningMovesOnlyVerticesJustOutsideTheirPlaneOntoItsFace) {
  EdgeField t(0.0);
  ASSERT_TRUE(t.planar(0) && t.planar(1));
  const auto at = [](int i, int j) { return std::size_t(j * (kNx + 1) + i); };
  const std::size_t raised = at(5, 8), lowered = at(8, 8), far = at(11, 8), zone = at(19, 8),
                    pastEdge = at(21, 8);
  ASSERT_TRUE(t.zones.inRegion[raised] && t.zones.inRegion[lowered] && t.zones.inRegion[far]);
  ASSERT_FALSE(t.zones.inRegion[zone] || t.zones.inRegion[pastEdge]);
  ASSERT_EQ(t.zones.vertexLabel[zone], 0);
  t.zones.vertexLabel[pastEdge] = 0;
  t.m.vert[raised].P()[2] += 0.05;
  t.m.vert[lowered].P()[2] -= 0.05;
  t.m.vert[far].P()[2] += 0.15;
  t.m.vert[zone].P()[2] += 0.05;
  t.m.vert[pastEdge].P()[2] = 0.05;
  const double maxMove = kH;  // one sample spacing
  const Vec3 pastEdgeAt = es::positionOf(&t.m.vert[pastEdge]);
  EXPECT_EQ(es::flattenPlanarRegions(t.m, es::VertexFaceTable(t.m), t.zones,
                                     t.zones.support.regionPlanes, 1e-6, maxMove, 1),
            3u);
  EXPECT_NEAR(t.m.vert[raised].P()[2], 0, 1e-6);
  EXPECT_NEAR(t.m.vert[zone].P()[2], 0, 1e-6);
  EXPECT_NEAR(t.m.vert[lowered].P()[2], -0.05, 1e-6);
  EXPECT_NEAR(t.m.vert[far].P()[2], 0.15, 1e-6);
  const es::Plane &slope = t.zones.support.regionPlanes[1];
  const Vec3 onSlope = pastEdgeAt - slope.normal * (slope.normal * (pastEdgeAt - slope.point));
  EXPECT_LT((es::positionOf(&t.m.vert[pastEdge]) - onSlope).Norm(), 1e-6);
  EXPECT_LT(onSlope[2], 0);
  // Facing the other way, the lowered vertex is the one outside.
  t.m.vert[raised].P()[2] += 0.05;
  EXPECT_EQ(es::flattenPlanarRegions(t.m, es::VertexFaceTable(t.m), t.zones,
                                     t.zones.support.regionPlanes, 1e-6, maxMove, -1),
            1u);
  EXPECT_NEAR(t.m.vert[raised].P()[2], 0.05, 1e-6);
  EXPECT_NEAR(t.m.vert[lowered].P()[2], 0, 1e-6);
}

namespace {

/// Vertex (i, j) of EdgeField's grid.
std::size_t gridVertex(int i, int j) {
  return std::size_t(j * (kNx + 1) + i);
}

}  // namespace

// A vertex a fused scan bulged beyond a convex edge, outside both faces'
// planes, where its nearest point behind both is on the edge: it goes there,
// labelled with the flat region (its place on the flat plane lies off the
// face) or with none. Faced the other way the edge is concave: the solid
// reaches beyond each plane there, and it stays.
TEST(PlanarRegions, FlatteningMovesAVertexBulgedBeyondAConvexEdgeOntoTheEdge) {
  for (const int label : {0, es::kZone}) {
    EdgeField t(0.0);
    const std::size_t v = gridVertex(21, 8);
    t.zones.vertexLabel[v] = label;
    t.m.vert[v].P()[2] = 0.1;
    const double maxMove = 2 * kH;
    EXPECT_EQ(es::flattenPlanarRegions(t.m, es::VertexFaceTable(t.m), t.zones,
                                       t.zones.support.regionPlanes, 1e-6, maxMove, -1),
              0u);
    EXPECT_EQ(es::flattenPlanarRegions(t.m, es::VertexFaceTable(t.m), t.zones,
                                       t.zones.support.regionPlanes, 1e-6, maxMove, 1),
              1u);
    EXPECT_LT((es::positionOf(&t.m.vert[v]) - Vec3(kEdgeX, 8 * kH, 0)).Norm(), 1e-6)
        << "label " << label;
  }
}

// Beside one plane alone nothing shows that the solid lies behind it: the
// slope curves (no plane), and a zone vertex raised above the flat plane
// whose place there lies off the flat face stays.
TEST(PlanarRegions, FlatteningNeedsTwoPlanesAroundAVertexOffItsFace) {
  EdgeField t(0.2);
  ASSERT_TRUE(t.planar(0));
  ASSERT_FALSE(t.planar(1));
  const std::size_t v = gridVertex(21, 8);
  t.zones.vertexLabel[v] = es::kZone;
  t.m.vert[v].P()[2] = 0.05;
  EXPECT_EQ(es::flattenPlanarRegions(t.m, es::VertexFaceTable(t.m), t.zones,
                                     t.zones.support.regionPlanes, 1e-6, 2 * kH, 1),
            0u);
  EXPECT_NEAR(t.m.vert[v].P()[2], 0.05, 1e-9);
}

// A region that is no plane between the flat and the slope (a boss on the
// edge): its vertex just outside the planes stays while another of its own
// rises beyond the bound (the region's own shape), and goes behind them once
// none does.
TEST(PlanarRegions, FlatteningLeavesARegionThatRisesBeyondThePlanes) {
  EdgeField t(0.0);
  const int boss = 2;  // no plane: regionPlanes has two entries
  for (int i = 19; i <= 22; ++i)
    for (int j = 6; j <= 10; ++j) {
      t.zones.vertexLabel[gridVertex(i, j)] = boss;
      t.zones.inRegion[gridVertex(i, j)] = 1;
    }
  const std::size_t low = gridVertex(20, 8), top = gridVertex(20, 10);
  const double maxMove = 2 * kH;
  t.m.vert[low].P()[2] = 0.05;
  t.m.vert[top].P()[2] = 0.5;
  EXPECT_EQ(es::flattenPlanarRegions(t.m, es::VertexFaceTable(t.m), t.zones,
                                     t.zones.support.regionPlanes, 1e-6, maxMove, 1),
            0u);
  EXPECT_NEAR(t.m.vert[low].P()[2], 0.05, 1e-9);
  t.m.vert[top].P()[2] = 0;
  EXPECT_EQ(es::flattenPlanarRegions(t.m, es::VertexFaceTable(t.m), t.zones,
                                     t.zones.support.regionPlanes, 1e-6, maxMove, 1),
            1u);
  EXPECT_NEAR(t.m.vert[low].P()[2], 0, 1e-6);
}

// The grown planes' pass (flattenRoughPlanes): a vertex a better estimate of
// its face's plane has placed (its region's core fit) is not moved onto the
// plane it is labelled with now, while an unmarked one raised as much is; a
// marked vertex bulged beyond a convex edge still goes behind both planes.
TEST(PlanarRegions, FlatteningLeavesAVertexOnABetterPlaneOffItsLabelsPlane) {
  EdgeField t(0.0);
  const std::size_t marked = gridVertex(5, 8), unmarked = gridVertex(8, 8),
                    bulged = gridVertex(21, 8);
  ASSERT_TRUE(t.zones.inRegion[marked] && t.zones.inRegion[unmarked]);
  t.m.vert[marked].P()[2] += 0.05;
  t.m.vert[unmarked].P()[2] += 0.05;
  t.zones.vertexLabel[bulged] = 0;
  t.m.vert[bulged].P()[2] = 0.1;
  std::vector<char> onBetterPlane(t.m.vert.size(), 0);
  onBetterPlane[marked] = onBetterPlane[bulged] = 1;
  EXPECT_EQ(es::flattenPlanarRegions(t.m, es::VertexFaceTable(t.m), t.zones,
                                     t.zones.support.regionPlanes, 1e-6, 2 * kH, 1, onBetterPlane),
            2u);
  EXPECT_NEAR(t.m.vert[marked].P()[2], 0.05, 1e-9);
  EXPECT_NEAR(t.m.vert[unmarked].P()[2], 0, 1e-6);
  EXPECT_LT((es::positionOf(&t.m.vert[bulged]) - Vec3(kEdgeX, 8 * kH, 0)).Norm(), 1e-6);
}
