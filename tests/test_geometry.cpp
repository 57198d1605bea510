// Pure-geometry functions: no mesh involved.
#include <gtest/gtest.h>

#include <random>

#include "edge_sharpener/util/curved_flank.h"
#include "edge_sharpener/util/fillet_fit.h"
#include "edge_sharpener/util/geometry.h"
#include "edge_sharpener/util/qef.h"

namespace es = edge_sharpener;
using es::Plane;
using es::Vec3;

namespace {

constexpr double kDeg = M_PI / 180.0;

Vec3 unit(Vec3 v) {
  return v / v.Norm();
}

double planeOffset(const Plane &p, const Vec3 &x) {
  return p.normal * (x - p.point);
}

/// Random points in [-1, 1]^3 and planes through them, from a fixed seed.
class RandomPlanes {
 public:
  explicit RandomPlanes(unsigned seed) : rng_(seed) {}
  Vec3 point() { return Vec3(u_(rng_), u_(rng_), u_(rng_)); }
  Plane plane() { return Plane{point(), unit(point())}; }

 private:
  std::mt19937 rng_;
  std::uniform_real_distribution<double> u_{-1, 1};
};

}  // namespace

TEST(PlanePairLine, PointLiesOnBothPlanesAndIsClosestToTarget) {
  const Plane top{Vec3(0.2, 0, 1), Vec3(0, 0, 1)};
  const Plane side{Vec3(1, 0.3, 0.5), Vec3(1, 0, 0)};
  const Vec3 target(0.6, 0.15, 0.75);
  const auto x = es::closestPointOnPlanePairLine(top, side, target, 1 * kDeg);
  ASSERT_TRUE(x.has_value());
  EXPECT_NEAR((*x - Vec3(1, 0.15, 1)).Norm(), 0, 1e-12);
}

TEST(PlanePairLine, RandomPlanesGiveExactClosestPoint) {
  RandomPlanes sample(7);
  for (int trial = 0; trial < 200; ++trial) {
    const Plane p = sample.plane();
    const Plane q = sample.plane();
    const Vec3 target = sample.point();
    const auto x = es::closestPointOnPlanePairLine(p, q, target, 1 * kDeg);
    if (!x) {
      EXPECT_LE((p.normal ^ q.normal).Norm(), std::sin(1 * kDeg) + 1e-15) << trial;
      continue;
    }
    EXPECT_NEAR(planeOffset(p, *x), 0, 1e-9);
    EXPECT_NEAR(planeOffset(q, *x), 0, 1e-9);
    // The correction is orthogonal to the line: target - x has no component along N x M.
    const Vec3 dir = unit(p.normal ^ q.normal);
    EXPECT_NEAR((target - *x) * dir, 0, 1e-9);
  }
}

TEST(PlanePairLine, ParallelPlanesWithinToleranceAreRejected) {
  const Plane p{Vec3(0, 0, 0), Vec3(0, 0, 1)};
  const Plane nearlyParallel{Vec3(1, 0, 0),
                             unit(Vec3(std::sin(0.5 * kDeg), 0, std::cos(0.5 * kDeg)))};
  const Plane tilted{Vec3(1, 0, 0), unit(Vec3(std::sin(2 * kDeg), 0, std::cos(2 * kDeg)))};
  EXPECT_FALSE(es::closestPointOnPlanePairLine(p, nearlyParallel, Vec3(0, 0, 0), 1 * kDeg));
  EXPECT_TRUE(es::closestPointOnPlanePairLine(p, tilted, Vec3(0, 0, 0), 1 * kDeg));
  const Plane antiParallel{Vec3(0, 0, 1), Vec3(0, 0, -1)};
  EXPECT_FALSE(es::closestPointOnPlanePairLine(p, antiParallel, Vec3(0, 0, 0), 1 * kDeg));
}

TEST(ThreePlanes, CubeCornerIsRecovered) {
  const Plane x{Vec3(1, 0.3, 0.2), Vec3(1, 0, 0)};
  const Plane y{Vec3(0.5, 1, 0.9), Vec3(0, 1, 0)};
  const Plane z{Vec3(0.1, 0.7, 1), Vec3(0, 0, 1)};
  const auto w = es::intersectThreePlanes(x, y, z, 1 * kDeg);
  ASSERT_TRUE(w.has_value());
  EXPECT_NEAR((*w - Vec3(1, 1, 1)).Norm(), 0, 1e-12);
}

TEST(ThreePlanes, RandomPlanesMeetAtTheirCommonPoint) {
  RandomPlanes sample(11);
  int solved = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Plane p = sample.plane();
    const Plane q = sample.plane();
    const Plane r = sample.plane();
    const auto w = es::intersectThreePlanes(p, q, r, 1 * kDeg);
    const double triple = std::abs(p.normal * (q.normal ^ r.normal));
    EXPECT_EQ(w.has_value(), triple > std::sin(1 * kDeg)) << trial;
    if (!w) continue;
    ++solved;
    const double scale = 1.0 / triple;  // conditioning of the system
    EXPECT_NEAR(planeOffset(p, *w), 0, 1e-12 * scale * 10);
    EXPECT_NEAR(planeOffset(q, *w), 0, 1e-12 * scale * 10);
    EXPECT_NEAR(planeOffset(r, *w), 0, 1e-12 * scale * 10);
  }
  EXPECT_GT(solved, 150);
}

// The sides x = 1 and y = 1 of the unit cube: their edge is the line x = y = 1.
const Plane kSideX{Vec3(1, 0.5, 0.5), Vec3(1, 0, 0)};
const Plane kSideY{Vec3(0.5, 1, 0.5), Vec3(0, 1, 0)};

// The edge x = 1, y = 1 of the unit cube ends at its top face z = 1.
TEST(EndPlane, APointBeyondTheEndFaceMovesToTheCorner) {
  const Plane top{Vec3(0.5, 0.5, 1), Vec3(0, 0, 1)};
  const auto before = es::keepBeforeEndPlane(kSideX, kSideY, top, Vec3(1, 1, 0.7), 1 * kDeg);
  ASSERT_TRUE(before.has_value());
  EXPECT_NEAR((*before - Vec3(1, 1, 0.7)).Norm(), 0, 1e-12);
  const auto beyond = es::keepBeforeEndPlane(kSideX, kSideY, top, Vec3(1, 1, 1.3), 1 * kDeg);
  ASSERT_TRUE(beyond.has_value());
  EXPECT_NEAR((*beyond - Vec3(1, 1, 1)).Norm(), 0, 1e-12);
}

// A block standing on a plate: its vertical edge lies above the plate's top
// face (the flanks on the side the normal points to) and ends there too.
TEST(EndPlane, TheEdgeSideIsWhereTheFlanksLie) {
  const Plane plate{Vec3(3, 3, 0), Vec3(0, 0, 1)};
  const auto above = es::keepBeforeEndPlane(kSideX, kSideY, plate, Vec3(1, 1, 0.2), 1 * kDeg);
  ASSERT_TRUE(above.has_value());
  EXPECT_NEAR((*above - Vec3(1, 1, 0.2)).Norm(), 0, 1e-12);
  const auto below = es::keepBeforeEndPlane(kSideX, kSideY, plate, Vec3(1, 1, -0.2), 1 * kDeg);
  ASSERT_TRUE(below.has_value());
  EXPECT_NEAR((*below - Vec3(1, 1, 0)).Norm(), 0, 1e-12);
}

// A third plane with the flanks on both sides (or containing one, or
// parallel to the line) ends no edge of theirs.
TEST(EndPlane, OnlyWhereTheFlanksLieOnOneSide) {
  const Plane across{Vec3(0.5, 0.5, 0.5), unit(Vec3(1, -1, 0.2))};
  EXPECT_FALSE(es::keepBeforeEndPlane(kSideX, kSideY, across, Vec3(1, 1, 0), 1 * kDeg));
  const Plane throughY{kSideY.point, Vec3(0, 0, 1)};
  EXPECT_FALSE(es::keepBeforeEndPlane(kSideX, kSideY, throughY, Vec3(1, 1, 0), 1 * kDeg));
  const Plane alongLine{Vec3(0, 0, 0), unit(Vec3(-1, -1, 0))};
  const auto kept = es::keepBeforeEndPlane(kSideX, kSideY, alongLine, Vec3(1, 1, 5), 1 * kDeg);
  ASSERT_TRUE(kept.has_value());  // on the flanks' side: the line never crosses it
  EXPECT_NEAR((*kept - Vec3(1, 1, 5)).Norm(), 0, 1e-12);
}

TEST(ThreePlanes, CoplanarNormalsAreRejected) {
  const Plane a{Vec3(0, 0, 0), Vec3(1, 0, 0)};
  const Plane b{Vec3(0, 0, 0), Vec3(0, 1, 0)};
  const Plane c{Vec3(1, 1, 0), unit(Vec3(1, 1, 0))};  // in the xy-plane of normals
  EXPECT_FALSE(es::intersectThreePlanes(a, b, c, 1 * kDeg));
  const Plane twin{Vec3(2, 0, 0), Vec3(1, 0, 0)};  // two equal normals
  EXPECT_FALSE(es::intersectThreePlanes(a, b, twin, 1 * kDeg));
}

TEST(Convexity, CubeEdgeChamferIsConvex) {
  // A on the top face, B on the side face x = 1 of the unit cube.
  const Plane top{Vec3(0.8, 0, 1), Vec3(0, 0, 1)};
  const Plane side{Vec3(1, 0, 0.8), Vec3(1, 0, 0)};
  EXPECT_EQ(es::classifyChamferEdge(top, side, 1e-3), es::EdgeConvexity::Convex);
}

TEST(Convexity, InnerCornerChamferIsConcave) {
  // L-shaped profile: floor z = 0 (normal up) meets wall x = 1 (normal -x).
  const Plane floor{Vec3(0.8, 0, 0), Vec3(0, 0, 1)};
  const Plane wall{Vec3(1, 0, 0.2), Vec3(-1, 0, 0)};
  EXPECT_EQ(es::classifyChamferEdge(floor, wall, 1e-3), es::EdgeConvexity::Concave);
}

TEST(Convexity, StepBetweenConcaveAndConvexIsMixed) {
  // B lies above P, A below Q: a step, not a sharp edge.
  const Plane lowerTilted{Vec3(0, 0, 0), unit(Vec3(-0.3, 0, 1))};
  const Plane upperTilted{Vec3(1, 0, 2), unit(Vec3(0.3, 0, 1))};
  EXPECT_EQ(es::classifyChamferEdge(lowerTilted, upperTilted, 1e-3), es::EdgeConvexity::Mixed);
}

TEST(Convexity, SymmetricInSwappingTheEndpoints) {
  RandomPlanes sample(3);
  for (int trial = 0; trial < 100; ++trial) {
    const Plane p = sample.plane();
    const Plane q = sample.plane();
    EXPECT_EQ(es::classifyChamferEdge(p, q, 1e-3), es::classifyChamferEdge(q, p, 1e-3));
  }
}

// Where the top (z = 1) meets the side x = 1 of the unit cube, the top's
// face is the part of its plane on the side's inner side; where a floor
// (z = 0) meets a wall rising from x = 1, the floor's face is the part on
// the wall's outer side. Either way the top's or floor's own samples tell.
// One plane per region; a zero normal where the region is no plane.
TEST(RegionPlaneOf, OnlyARegionThatIsAPlane) {
  const std::vector<es::Plane> planes = {{Vec3(0, 0, 0), Vec3(0, 0, 1)},
                                         {Vec3(0, 0, 0), Vec3(0, 0, 0)}};
  ASSERT_NE(es::regionPlaneOf(planes, 0), nullptr);
  EXPECT_EQ(es::regionPlaneOf(planes, 0), &planes[0]);
  EXPECT_EQ(es::regionPlaneOf(planes, 1), nullptr);
  EXPECT_EQ(es::regionPlaneOf(planes, 2), nullptr);
  EXPECT_EQ(es::regionPlaneOf(planes, -1), nullptr);
}

TEST(OnSideOf, ThePartOfAPlaneThatIsTheFaceIsWhereItsSamplesLie) {
  const Plane side{Vec3(1, 0, 0.5), Vec3(1, 0, 0)};
  const Vec3 topSample(0.7, 0.2, 1);
  EXPECT_TRUE(es::onSideOf(side, Vec3(0.95, 0, 1), topSample));
  EXPECT_FALSE(es::onSideOf(side, Vec3(1.05, 0, 1), topSample));
  const Plane wall{Vec3(1, 0, 0.5), Vec3(-1, 0, 0)};
  const Vec3 floorSample(1.4, 0.2, 0);
  EXPECT_TRUE(es::onSideOf(wall, Vec3(1.05, 0, 0), floorSample));
  EXPECT_FALSE(es::onSideOf(wall, Vec3(0.95, 0, 0), floorSample));
  EXPECT_TRUE(es::onSideOf(wall, Vec3(1, 0.3, 0), floorSample));      // on the plane
  EXPECT_FALSE(es::onSideOf(wall, Vec3(1.05, 0, 0), Vec3(1, 0, 0)));  // no side to follow
}

TEST(TriangleAngles, EquilateralAndDegenerate) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0.5, std::sqrt(3.0) / 2, 0);
  EXPECT_NEAR(es::minTriangleAngle(a, b, c), 60 * kDeg, 1e-12);
  EXPECT_NEAR(es::maxTriangleAngle(a, b, c), 60 * kDeg, 1e-12);
  EXPECT_EQ(es::minTriangleAngle(a, b, Vec3(2, 0, 0)), 0.0);  // collinear
  EXPECT_EQ(es::minTriangleAngle(a, a, c), 0.0);              // repeated vertex
  EXPECT_NEAR(es::maxTriangleAngle(a, Vec3(2, 0, 0), b), M_PI, 1e-12);
  EXPECT_NEAR(es::cornerAngle(a, b, Vec3(0, 1, 0)), 90 * kDeg, 1e-12);
}

TEST(IntermediatePlane, NormalOnTheArcBetweenFlanksIsBetween) {
  const Vec3 top(0, 0, 1), side(1, 0, 0);
  EXPECT_TRUE(es::normalBetween(top, side, unit(Vec3(1, 0, 1)), 1 * kDeg));
  EXPECT_TRUE(es::normalBetween(top, side, unit(Vec3(1, 0, 3)), 1 * kDeg));
  // Off the arc: the third face of a cube corner, or a facet turned sideways.
  EXPECT_FALSE(es::normalBetween(top, side, Vec3(0, 1, 0), 10 * kDeg));
  EXPECT_FALSE(es::normalBetween(top, side, unit(Vec3(1, 0.8, 1)), 10 * kDeg));
  EXPECT_TRUE(es::normalBetween(top, side, unit(Vec3(1, 0.1, 1)), 10 * kDeg));
}

TEST(IntermediatePlane, PassageIsMeasuredOnTheOuterSide) {
  // Convex edge of top z = 1 and side x = 1; a 45-degree facet through
  // (1, 0, 0.9) and (0.9, 0, 1) lies between them.
  const Vec3 sum(1, 0, 1);
  const Plane facet{Vec3(0.95, 0, 0.95), unit(Vec3(1, 0, 1))};
  const Vec3 rest(0.95, 0, 0.95), apex(1, 0, 1);
  EXPECT_NEAR(es::passageBeyondPlane(sum, facet, rest, apex), std::sqrt(2.0) * 0.05, 1e-12);
  // A point moved outward that stays on the inner side does not pass.
  EXPECT_LT(es::passageBeyondPlane(sum, facet, Vec3(0.95, 0, 0.9), Vec3(0.97, 0, 0.92)), 0);
  // Concave: the same geometry seen from inside (normals flipped), the
  // apex moves inward and passes the facet on its inner side.
  const Plane inner{facet.point, -facet.normal};
  EXPECT_NEAR(es::passageBeyondPlane(-sum, inner, rest, apex), std::sqrt(2.0) * 0.05, 1e-12);
}

TEST(Bend, CylinderCurvatureAcrossItsAxisOnly) {
  // Faces of a cylinder of radius R around the y axis, near its top (normal
  // +z): normals turn with x, not with y.
  const double radius = 2.0;
  es::CrossScatter3 turn, extent;
  const Vec3 point(0, 0, radius), normal(0, 0, 1);
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j) {
      const double angle = 0.02 * i;
      const Vec3 n(std::sin(angle), 0, std::cos(angle));
      const Vec3 c = n * radius + Vec3(0, 0.04 * j, 0);
      turn.add(n - normal, c - point, 1.0);
      extent.add(c - point, c - point, 1.0);
    }
  const double d = 0.3;
  // A circle of curvature 1/R leaves its tangent by about d^2 / (2R).
  EXPECT_NEAR(es::extrapolationBend(turn, extent, Vec3(1, 0, 0), d), d * d / (2 * radius),
              0.02 * d * d / (2 * radius));
  EXPECT_NEAR(es::extrapolationBend(turn, extent, Vec3(0, 1, 0), d), 0.0, 1e-6);
}

TEST(Bend, UncorrelatedNormalNoiseIsNotCurvature) {
  // A flat patch whose face normals alternate +-5 degrees (marching-cubes
  // staircase): the noise does not grow with position.
  es::CrossScatter3 turn, extent;
  for (int i = -4; i <= 4; ++i) {
    const double tilt = (i % 2 == 0 ? 1 : -1) * 5 * kDeg;
    const Vec3 n(std::sin(tilt), 0, std::cos(tilt));
    const Vec3 c(0.05 * i, 0, 0);
    turn.add(n - Vec3(0, 0, 1), c, 1.0);
    extent.add(c, c, 1.0);
  }
  EXPECT_LT(es::extrapolationBend(turn, extent, Vec3(1, 0, 0), 0.3), 0.002);
}

TEST(Bend, FitQualityTellsACurveFromStaircaseNoise) {
  // A cylinder's normals follow position exactly; alternating +-5 degree
  // tilts on a flat patch do not follow it at all.
  const double radius = 2.0;
  es::CrossScatter3 turn, extent, self;
  const Vec3 normal(0, 0, 1);
  for (int i = -3; i <= 3; ++i) {
    const double angle = 0.02 * i;
    const Vec3 n(std::sin(angle), 0, std::cos(angle));
    const Vec3 c = n * radius - Vec3(0, 0, radius);
    turn.add(n - normal, c, 1.0);
    extent.add(c, c, 1.0);
    self.add(n - normal, n - normal, 1.0);
  }
  EXPECT_GT(es::curveFitQuality(turn, extent, self, Vec3(1, 0, 0)), 0.99);

  es::CrossScatter3 noiseTurn, noiseExtent, noiseSelf;
  for (int i = -4; i <= 4; ++i) {
    const double tilt = (i % 2 == 0 ? 1 : -1) * 5 * kDeg;
    const Vec3 n(std::sin(tilt), 0, std::cos(tilt));
    const Vec3 c(0.05 * i, 0, 0);
    noiseTurn.add(n - normal, c, 1.0);
    noiseExtent.add(c, c, 1.0);
    noiseSelf.add(n - normal, n - normal, 1.0);
  }
  EXPECT_LT(es::curveFitQuality(noiseTurn, noiseExtent, noiseSelf, Vec3(1, 0, 0)), 0.1);
  // Nothing measured: no quality.
  EXPECT_EQ(es::curveFitQuality(es::CrossScatter3{}, es::CrossScatter3{}, es::CrossScatter3{},
                                Vec3(1, 0, 0)),
            0.0);
}

TEST(TrianglesApart, CoplanarNeighboursATenthApartAreApart) {
  // Two faces of one sharpened flank (z = 0.5 - 0.5 (x - 1.03)); vcglib's
  // Moeller test reports them as intersecting in double precision.
  const std::array<Vec3, 3> a{Vec3(1.03, 0.55, 0.5), Vec3(1.1, 0.6, 0.465), Vec3(1.03, 0.6, 0.5)};
  const std::array<Vec3, 3> b{Vec3(1.1, 0.5, 0.465), Vec3(1.2, 0.5, 0.415), Vec3(1.2, 0.6, 0.415)};
  EXPECT_TRUE(es::trianglesApart(a, b));
  EXPECT_TRUE(es::trianglesApart(b, a));
}

TEST(TrianglesApart, CrossingOverlappingAndTouchingAreNotApart) {
  const std::array<Vec3, 3> flat{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)};
  // Pierces the flat triangle.
  const std::array<Vec3, 3> crossing{Vec3(0.5, 0.5, -1), Vec3(0.5, 0.5, 1), Vec3(0.6, 0.4, 1)};
  // Coplanar, overlapping.
  const std::array<Vec3, 3> overlapping{Vec3(0.5, 0.5, 0), Vec3(3, 0.5, 0), Vec3(0.5, 3, 0)};
  // A vertex resting on the flat triangle's hypotenuse.
  const std::array<Vec3, 3> touching{Vec3(1, 1, 0), Vec3(2, 2, 1), Vec3(2, 1, 1)};
  // Parallel, 0.01 above.
  const std::array<Vec3, 3> above{Vec3(0, 0, 0.01), Vec3(2, 0, 0.01), Vec3(0, 2, 0.01)};
  EXPECT_FALSE(es::trianglesApart(flat, crossing));
  EXPECT_FALSE(es::trianglesApart(flat, overlapping));
  EXPECT_FALSE(es::trianglesApart(flat, touching));
  EXPECT_FALSE(es::trianglesApart(touching, flat));
  EXPECT_TRUE(es::trianglesApart(flat, above));
}

TEST(SegmentThroughTriangle, SameAnswerAtEveryScale) {
  // A segment crossing a triangle 2 degrees off its plane, one beside it,
  // one short of it, one ending on it, one in it and one grazing it: at the size of a part in
  // metres, millimetres and of a building. (vcglib's test called every
  // segment of the smallest parallel.)
  for (const double scale : {1e-5, 1e-2, 1.0, 1e3}) {
    const std::array<Vec3, 3> t{Vec3(0, 0, 0) * scale, Vec3(1, 0, 0) * scale,
                                Vec3(0, 1, 0) * scale};
    const double rise = std::tan(2 * M_PI / 180);
    const auto crossing = es::segmentThroughTriangle(Vec3(-0.5, 0.25, -0.75 * rise) * scale,
                                                     Vec3(1.0, 0.25, 0.75 * rise) * scale, t);
    ASSERT_TRUE(crossing.has_value()) << scale;
    EXPECT_NEAR((*crossing)[0], 0.25, 1e-9) << scale;
    EXPECT_NEAR((*crossing)[1], 0.25, 1e-9) << scale;
    EXPECT_FALSE(
        es::segmentThroughTriangle(Vec3(0.6, 0.6, -1) * scale, Vec3(0.6, 0.6, 1) * scale, t))
        << scale;  // passes the plane beyond the hypotenuse
    EXPECT_FALSE(es::segmentThroughTriangle(Vec3(0.2, 0.2, 0.5) * scale, Vec3(0.2, 0.2, 1) * scale,
                                            t))
        << scale;  // stops short of the plane
    EXPECT_FALSE(es::segmentThroughTriangle(Vec3(0.2, 0.2, 0) * scale, Vec3(0.2, 0.2, 1) * scale,
                                            t))
        << scale;  // ends on it
    EXPECT_FALSE(es::segmentThroughTriangle(Vec3(-1, 0.2, 0) * scale, Vec3(1, 0.2, 0) * scale, t))
        << scale;  // in the plane
    const double graze = std::tan(0.2 * M_PI / 180);
    EXPECT_FALSE(es::segmentThroughTriangle(Vec3(-0.5, 0.25, -0.75 * graze) * scale,
                                            Vec3(1.0, 0.25, 0.75 * graze) * scale, t))
        << scale;  // grazing: 0.2 degrees off the plane
  }
}

TEST(LiesOnSegment, OnItUpToFloatRoundingOnly) {
  const Vec3 a(100, 0, 0), b(101, 1, 0);
  EXPECT_TRUE(es::liesOnSegment(Vec3(100.5, 0.5, 0), a, b));
  EXPECT_TRUE(es::liesOnSegment(a, a, b));
  // A float's rounding off the segment, at coordinates near 100.
  const Vec3 rounded(Vec3::Construct(vcg::Point3f(100.3f, 0.3f, 0.f)));
  EXPECT_TRUE(es::liesOnSegment(rounded, a, b));
  EXPECT_FALSE(es::liesOnSegment(Vec3(100.5, 0.5, 0.001), a, b));  // off it
  EXPECT_FALSE(es::liesOnSegment(Vec3(101.5, 1.5, 0), a, b));      // on the line, beyond b
  EXPECT_FALSE(es::liesOnSegment(a, a, a));                        // no segment
}

// The line two planes meet on lies along a surface (0), pierces it (pi/2) or
// crosses it at the angle between them; parallel planes or no surface: pi/2.
TEST(LineAngleToSurface, AngleBetweenThePlanesLineAndTheSurface) {
  using es::Vec3;
  const double deg = M_PI / 180;
  const Vec3 side(1, 0, 0), top(0, 0, 1);   // meet on the y axis
  const auto turnedFromY = [&](double a) {  // a unit normal at `a` from the y axis
    return Vec3(0, std::cos(a * deg), std::sin(a * deg));
  };
  const Vec3 chamfer = Vec3(1, 0, 1) / std::sqrt(2.0);
  EXPECT_NEAR(es::lineAngleToSurface(side, top, chamfer), 0.0, 1e-12);  // along its chamfer
  EXPECT_NEAR(es::lineAngleToSurface(side, top, Vec3(0, 1, 0)), 90 * deg, 1e-9);
  EXPECT_NEAR(es::lineAngleToSurface(side, top, turnedFromY(60)), 30 * deg, 1e-9);
  EXPECT_NEAR(es::lineAngleToSurface(top, side, -turnedFromY(60)), 30 * deg, 1e-9);  // signs
  EXPECT_NEAR(es::lineAngleToSurface(side, side, chamfer), 90 * deg, 1e-12);         // parallel
  EXPECT_NEAR(es::lineAngleToSurface(side, top, Vec3(0, 0, 0)), 90 * deg, 1e-12);
}

TEST(CoincidentCorners, OnlyAnEdgeAtFloatRoundingOfTheLongestCounts) {
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  EXPECT_TRUE(es::hasCoincidentCorners(a, b, b));                      // two corners at b
  EXPECT_TRUE(es::hasCoincidentCorners(a, b, b + Vec3(0, 5e-6, 0)));   // within rounding
  EXPECT_FALSE(es::hasCoincidentCorners(a, b, b + Vec3(0, 1e-3, 0)));  // a needle, not one point
  EXPECT_FALSE(es::hasCoincidentCorners(a, b, Vec3(0.5, 0.001, 0)));   // a cap
}

// The unit cube's three faces at its corner (1, 1, 1), normals outwards.
TEST(NearestPointBehindPlanes, OntoTheFaceEdgeOrCornerOfABox) {
  const std::vector<Plane> faces = {Plane{Vec3(1, 0, 0), Vec3(1, 0, 0)},
                                    Plane{Vec3(0, 1, 0), Vec3(0, 1, 0)},
                                    Plane{Vec3(0, 0, 1), Vec3(0, 0, 1)}};
  const auto nearest = [&](const Vec3 &p) {
    return es::nearestPointBehindPlanes(p, faces, 1e-9, 1 * kDeg).value();
  };
  EXPECT_LT((nearest(Vec3(0.5, 0.5, 0.5)) - Vec3(0.5, 0.5, 0.5)).Norm(), 1e-12);  // behind all
  EXPECT_LT((nearest(Vec3(1.2, 0.5, 0.5)) - Vec3(1, 0.5, 0.5)).Norm(), 1e-12);    // a face
  EXPECT_LT((nearest(Vec3(1.2, 1.1, 0.5)) - Vec3(1, 1, 0.5)).Norm(), 1e-12);      // an edge
  EXPECT_LT((nearest(Vec3(1.2, 1.1, 1.3)) - Vec3(1, 1, 1)).Norm(), 1e-12);        // the corner
  // Beyond one face but in front of the edge's other face only by less than
  // the projection would cross: the face, not the edge.
  EXPECT_LT((nearest(Vec3(1.2, 0.9, 0.5)) - Vec3(1, 0.9, 0.5)).Norm(), 1e-12);
}

// The nearest point behind random planes: behind every one, and no random
// point behind them all lies nearer.
TEST(NearestPointBehindPlanes, NoPointBehindThemAllIsNearer) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g(0, 1);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Plane> planes;
    for (int k = 0; k < 3; ++k)
      planes.push_back(
          Plane{Vec3(g(rng), g(rng), g(rng)) * 0.3, unit(Vec3(g(rng), g(rng), g(rng)))});
    const Vec3 p(g(rng), g(rng), g(rng));
    const auto nearest = es::nearestPointBehindPlanes(p, planes, 1e-9, 1 * kDeg);
    ASSERT_TRUE(nearest.has_value());
    for (const Plane &plane : planes) EXPECT_LE(planeOffset(plane, *nearest), 1e-9);
    const double d = (*nearest - p).Norm();
    for (int s = 0; s < 2000; ++s) {
      const Vec3 q = *nearest + Vec3(g(rng), g(rng), g(rng)) * 0.05;
      bool behind = true;
      for (const Plane &plane : planes) behind = behind && planeOffset(plane, q) <= 0;
      if (behind) {
        EXPECT_GE((q - p).Norm(), d - 1e-9);
      }
    }
  }
}

// Two parallel planes facing each other (a slab) have no edge; a point
// beyond one goes onto it. Facing away from each other nothing lies behind
// both.
TEST(NearestPointBehindPlanes, ParallelPlanes) {
  const std::vector<Plane> slab = {Plane{Vec3(0, 0, 1), Vec3(0, 0, 1)},
                                   Plane{Vec3(0, 0, -1), Vec3(0, 0, -1)}};
  EXPECT_LT((es::nearestPointBehindPlanes(Vec3(0.3, 0, 1.5), slab, 1e-9, 1 * kDeg).value() -
             Vec3(0.3, 0, 1))
                .Norm(),
            1e-12);
  const std::vector<Plane> apart = {Plane{Vec3(0, 0, 1), Vec3(0, 0, -1)},
                                    Plane{Vec3(0, 0, -1), Vec3(0, 0, 1)}};
  EXPECT_FALSE(es::nearestPointBehindPlanes(Vec3(0, 0, 0), apart, 1e-9, 1 * kDeg).has_value());
}

TEST(ProjectOntoPlane, TheFootOfThePerpendicular) {
  const Plane tilted{Vec3(1, 2, 3), unit(Vec3(1, -2, 2))};
  const Vec3 p(4, -1, 0.5);
  const Vec3 foot = es::projectOntoPlane(tilted, p);
  EXPECT_NEAR(planeOffset(tilted, foot), 0, 1e-12);
  EXPECT_LT(((p - foot) ^ tilted.normal).Norm(), 1e-12);  // along the normal
}

TEST(FitPlaneLeastSquares, RecoversATiltedPlaneThroughTheWeightedCentroid) {
  const Plane tilted{Vec3(1, 2, 3), unit(Vec3(1, -2, 2))};
  const Vec3 u = unit(tilted.normal ^ Vec3(0, 0, 1)), w = tilted.normal ^ u;
  std::vector<Vec3> points;
  std::vector<double> weights;
  Vec3 centre(0, 0, 0);
  double total = 0;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 5; ++j) {
      points.push_back(tilted.point + u * (0.3 * i) + w * (0.7 * j - 0.2 * i));
      weights.push_back(1 + (i * 5 + j) % 3);
      centre += points.back() * weights.back(), total += weights.back();
    }
  const Plane fitted = es::fitPlaneLeastSquares(points, weights, -tilted.normal);
  EXPECT_NEAR((fitted.normal + tilted.normal).Norm(), 0, 1e-9);  // turned towards -normal
  EXPECT_NEAR((fitted.point - centre / total).Norm(), 0, 1e-12);
  const std::vector<double> none(points.size(), 0.0);
  EXPECT_EQ(es::fitPlaneLeastSquares(points, none, tilted.normal).normal.SquaredNorm(), 0);
}

// Points on z = 0 and a strip along one rim lifted off it, as a fused scan
// bulges beside an edge: the plain fit tilts towards the strip, the trimmed
// one drops it and lies on the plane.
TEST(FitPlaneTrimmed, DropsTheBulgeAlongARim) {
  std::vector<Vec3> points;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) points.push_back(Vec3(0.05 * i, 0.05 * j, i >= 19 ? 0.04 : 0));
  const std::vector<double> weights(points.size(), 1.0);
  const Plane plain = es::fitPlaneLeastSquares(points, weights, Vec3(0, 0, 1));
  const Plane trimmed = es::fitPlaneTrimmed(points, weights, Vec3(0, 0, 1), 1.5);
  EXPECT_GT(es::angleBetween(plain.normal, Vec3(0, 0, 1)), 1 * kDeg);
  EXPECT_LT(es::angleBetween(trimmed.normal, Vec3(0, 0, 1)), 1e-9);
  EXPECT_NEAR(trimmed.point[2], 0, 1e-12);
}

// The QEF (Ju et al.): a plane of weight 3 pulls three times as hard as one
// of weight 1; what the planes do not fix stays at the centre; four planes
// through one point (a pyramid's apex) fix it, whatever the centre.
TEST(Qef, WeighsItsPlanesAndKeepsTheCentreWhereTheyFixNothing) {
  const Plane low{Vec3(0, 0, 0), Vec3(0, 0, 1)}, high{Vec3(5, 5, 1), Vec3(0, 0, 1)};
  es::QefSolution x = es::solveQef({low, high}, {1, 3}, Vec3(0.2, -0.3, 9));
  EXPECT_EQ(x.rank, 1);
  EXPECT_LT((x.point - Vec3(0.2, -0.3, 0.75)).Norm(), 1e-14);
  const Vec3 apex(0, 0, 0.6);
  std::vector<Plane> faces;
  for (const Vec3 &n :
       {Vec3(1.1, 0, 0.7), Vec3(-1.1, 0, 0.7), Vec3(0, 1.1, 0.7), Vec3(0, -1.1, 0.7)})
    faces.push_back(Plane{apex + (n ^ Vec3(0, 0, 1)) * 0.5, n / n.Norm()});  // a point off the apex
  x = es::solveQef(faces, {}, Vec3(0.3, -0.2, 0.1));
  EXPECT_EQ(x.rank, 3);
  EXPECT_LT((x.point - apex).Norm(), 1e-12);
  // Two of them, opposite faces: their line through the apex, at the point nearest the centre.
  x = es::solveQef({faces[0], faces[1]}, {}, Vec3(0.3, -0.2, 0.1));
  EXPECT_EQ(x.rank, 2);
  EXPECT_LT((x.point - Vec3(0, -0.2, 0.6)).Norm(), 1e-12);
}

// A flank fitted as placement fits it (the faces' area-weighted normal and
// centroid, the scatters of their deviations), here of a cylinder's side
// next to its flat top: the bent flank meets the top on the rim, a circle,
// where the fitted plane meets it on a straight line inside.
TEST(CurvedFlank, MeetsAFlatCapOnACylindersRim) {
  using es::closestPointOnPlanePairLine;
  using es::CrossScatter3;
  using es::CurvedFlank;
  using es::curvedFlank;
  using es::onBothFlanks;
  const double radius = 1.0;
  std::vector<Vec3> normal, centroid;
  for (double t = -0.2; t <= 0.2001; t += 0.05)
    for (double z = -0.3; z <= -0.0499; z += 0.05) {
      normal.emplace_back(std::cos(t), std::sin(t), 0);
      centroid.emplace_back(radius * std::cos(t), radius * std::sin(t), z);
    }
  Vec3 n(0, 0, 0), c(0, 0, 0);
  for (std::size_t i = 0; i < normal.size(); ++i) n += normal[i], c += centroid[i];
  const Plane side{c / double(centroid.size()), n.Normalize()};
  CrossScatter3 normalPosition, positionScatter;
  for (std::size_t i = 0; i < normal.size(); ++i) {
    normalPosition.add(normal[i] - side.normal, centroid[i] - side.point, 1.0 / normal.size());
    positionScatter.add(centroid[i] - side.point, centroid[i] - side.point, 1.0 / normal.size());
  }
  const CurvedFlank bent = curvedFlank(side, normalPosition, positionScatter);
  EXPECT_NEAR(bent.kuu + bent.kvv, 1.0 / radius, 1e-3);  // one principal curvature: 1/R
  const CurvedFlank top = curvedFlank({Vec3(0, 0, 0), Vec3(0, 0, 1)}, {}, {});
  EXPECT_FALSE(top.curved());

  const Vec3 rest(0.97, 0.2, -0.02);
  const auto onPlanes = closestPointOnPlanePairLine(side, top.plane, rest, 1.0 * M_PI / 180.0);
  ASSERT_TRUE(onPlanes);
  const auto radialError = [&](const Vec3 &x) { return std::abs(std::hypot(x[0], x[1]) - radius); };
  EXPECT_GT(radialError(*onPlanes), 0.01);
  const auto onFlanks = onBothFlanks(bent, top, *onPlanes, 1e-12);
  ASSERT_TRUE(onFlanks);
  EXPECT_NEAR((*onFlanks)[2], 0.0, 1e-12);
  EXPECT_LT(radialError(*onFlanks), 1e-3);
  // Two flat flanks meet where their planes do.
  const CurvedFlank flatSide = curvedFlank(side, {}, {});
  const auto onFlat = onBothFlanks(flatSide, top, rest, 1e-12);
  ASSERT_TRUE(onFlat);
  EXPECT_LT(((*onFlat) - *closestPointOnPlanePairLine(side, top.plane, *onFlat, 0.01)).Norm(),
            1e-12);
  // Flanks that never meet: two parallel planes.
  EXPECT_FALSE(onBothFlanks(top, curvedFlank({Vec3(0, 0, 1), Vec3(0, 0, 1)}, {}, {}), rest, 1e-9));
}

// ----- util/fillet_fit.h: a feature's cross-section as a fillet

namespace {
/// `count` samples on a fillet of radius `r` between planes whose outward
/// normals turn by `turnRad` (distances inside each plane), with `flat`
/// samples on each plane beyond the arc's ends.
std::vector<es::CrossSectionSample> filletSamples(double r, double turnRad, int count, int flat) {
  // In the cross-section: plane A is y = 0 (solid below), plane B turned by
  // turnRad; the fillet's centre lies r inside both.
  const Vec3 nA(0, 1, 0), nB(std::sin(turnRad), std::cos(turnRad), 0);
  const Vec3 bisector = (nA + nB) * (-1 / (nA + nB).Norm());
  const Vec3 centre = bisector * (r / std::cos(turnRad / 2));
  std::vector<es::CrossSectionSample> out;
  for (int i = 0; i <= count; ++i) {
    const double t = double(i) / count;
    Vec3 n = nA * (1 - t) + nB * t;
    n /= n.Norm();
    const Vec3 p = centre + n * r;
    out.push_back({-(p * nA), -(p * nB)});
  }
  // On each plane, beyond the tangent points.
  const Vec3 alongA(1, 0, 0), alongB(std::cos(turnRad), -std::sin(turnRad), 0);
  for (int i = 1; i <= flat; ++i) {
    const Vec3 a = (centre + nA * r) - alongA * (0.5 * i),
               b = (centre + nB * r) + alongB * (0.5 * i);
    out.push_back({-(a * nA), -(a * nB)});
    out.push_back({-(b * nA), -(b * nB)});
  }
  return out;
}
}  // namespace

TEST(FilletFit, SamplesOnAFilletAreOnItsRoundedWedge) {
  for (double turnDeg : {60.0, 90.0, 120.0}) {
    const double turn = turnDeg * M_PI / 180, c = std::cos(turn);
    for (const es::CrossSectionSample &s : filletSamples(1.7, turn, 8, 3))
      EXPECT_NEAR(es::distanceToRoundedWedge(s, c, 1.7), 0.0, 1e-9) << turnDeg;
    // The sharp wedge: a sample inside lies min(a, b) below it.
    EXPECT_NEAR(es::distanceToRoundedWedge({0.3, 0.5}, c, 0.0), -0.3, 1e-12);
    EXPECT_NEAR(es::distanceToRoundedWedge({0.0, 2.0}, c, 0.0), 0.0, 1e-12);
  }
  // A right angle's fillet is r * sqrt(2) across.
  EXPECT_NEAR(es::filletWidth(1.0, 0.0), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(es::filletWidth(1.0, -1.0), 2.0, 1e-12);
}

TEST(FilletFit, TheFitFindsTheRadiusAndTheSharpWedgeWhereSamplesLieOnThePlanes) {
  for (double turnDeg : {50.0, 90.0, 130.0}) {
    const double turn = turnDeg * M_PI / 180, c = std::cos(turn);
    const es::FilletFit fit = es::fitFillet(filletSamples(1.7, turn, 6, 4), c, 8.0, 0.05);
    EXPECT_NEAR(fit.radius, 1.7, 0.01) << turnDeg;
    EXPECT_LT(fit.rms, 1e-3);
    EXPECT_GT(fit.wedgeRms, 0.04);  // the arc off the wedge by up to 0.3 r
    // Samples on the two planes only (a sampler that puts them on the surface
    // of a sharp edge): every fillet narrower than their distance from the
    // edge fits them alike, and the plainest, the sharp wedge, is taken.
    std::vector<es::CrossSectionSample> onPlanes;
    for (double d : {0.2, 0.9, 1.6, 2.3}) {
      onPlanes.push_back({0.0, d * std::sin(turn)});
      onPlanes.push_back({d * std::sin(turn), 0.0});
    }
    const es::FilletFit sharp = es::fitFillet(onPlanes, c, 8.0, 0.05);
    EXPECT_EQ(sharp.radius, 0.0) << turnDeg;
    EXPECT_LT(sharp.rms, 1e-9);
    EXPECT_EQ(sharp.wedgeRms, sharp.rms);
  }
  EXPECT_EQ(es::fitFillet({}, 0.0, 8.0, 0.05).radius, 0.0);
}

TEST(FilletFit, AGridMeetsEdgesAlikeUpToItsSymmetries) {
  const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const double minCos = std::cos(10 * M_PI / 180);
  // Every edge of two axis planes is alike, whichever axes and sides.
  EXPECT_TRUE(es::gridEquivalentEdges(x, z, -y, z, minCos));
  EXPECT_TRUE(es::gridEquivalentEdges(x, z, z * -1, y, minCos));
  // A plane at 30 degrees to an axis plane, against one at 45.
  const Vec3 at30(std::cos(M_PI / 6), std::sin(M_PI / 6), 0);
  const Vec3 at45(std::sqrt(0.5), std::sqrt(0.5), 0);
  EXPECT_TRUE(es::gridEquivalentEdges(at30, z, Vec3(at30[1], at30[0], 0), -z, minCos));
  EXPECT_FALSE(es::gridEquivalentEdges(at30, z, at45, z, minCos));
  EXPECT_FALSE(es::gridEquivalentEdges(x, z, at45, z, minCos));
}
