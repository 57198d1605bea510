// The auto method's evidence guard (guards/feature_evidence.h) on hand-made
// split plans and triangles: which inserted vertices form one feature, when a
// feature's evidence is weak, how far a move lifts the surface, how a weak
// edge reaches its corners, and the mesh-wide gate; no mesh needed.
#include <gtest/gtest.h>

#include <algorithm>

#include "edge_sharpener/guards/feature_evidence.h"
#include "edge_sharpener/util/mesh_types.h"
#include "hand_built_meshes.h"

namespace es = edge_sharpener;

namespace {
/// A scan-like surface: the general refused bound applies (refusedBound).
const es::SurfaceMeasures kRoughSurface{/*noiseSpacings=*/1.0, /*planarFraction=*/0.0};

es::InsertedVertexSource edgeVertex(std::size_t a, std::size_t b) {
  es::InsertedVertexSource s;
  s.original = {a, b, 0};
  s.originalCount = 2;
  return s;
}

es::InsertedVertexSource cornerVertex(std::size_t a, std::size_t b, std::size_t c) {
  es::InsertedVertexSource s;
  s.original = {a, b, c};
  s.originalCount = 3;
  return s;
}

/// Two chamfer strips meeting at a corner triangle (2, 3, 10): strip A
/// between regions 0 and 1 over source vertices 0..4, strip B between
/// regions 1 and 2 over 10..13, and one corner vertex.
struct TwoStripsAndACorner {
  es::SplitPlan plan;
  std::vector<long> region;
  TwoStripsAndACorner() {
    plan.originalVertexCount = 20;
    region.assign(20, -1);
    for (std::size_t v : {0, 2, 4}) region[v] = 0;
    for (std::size_t v : {1, 3, 10, 12}) region[v] = 1;
    for (std::size_t v : {11, 13}) region[v] = 2;
    // strip A: 0-1, 1-2, 2-3, 3-4 (alternating regions 0 and 1)
    for (std::size_t v = 0; v < 4; ++v) plan.inserted.push_back(edgeVertex(v, v + 1));
    // strip B: 10-11, 11-12, 12-13 (regions 1 and 2)
    for (std::size_t v = 10; v < 13; ++v) plan.inserted.push_back(edgeVertex(v, v + 1));
    plan.inserted.push_back(cornerVertex(2, 3, 10));
  }
  std::vector<std::uint32_t> group(std::vector<es::Feature> &features) const {
    return es::groupFeatures(
        plan, [&](std::size_t v) { return region[v]; }, features);
  }
  /// Grouped, with every inserted vertex moved and on its planes.
  std::vector<std::uint32_t> groupAllMoved(std::vector<es::Feature> &features) const;
};

es::Feature feature(std::size_t vertices, std::size_t moved, double offPlane = 0,
                    bool corner = false) {
  es::Feature f;
  f.vertices = vertices;
  f.moved = moved;
  f.maxOffPlane = offPlane;
  f.offPlaneQ90 = f.offPlaneMedian = offPlane;  // every sample that far
  f.corner = corner;
  return f;
}

}  // namespace

std::vector<std::uint32_t> TwoStripsAndACorner::groupAllMoved(
    std::vector<es::Feature> &features) const {
  const auto featureOf = group(features);
  features[featureOf[0]] = feature(4, 4);
  features[featureOf[4]] = feature(3, 3);
  features[featureOf[7]] = feature(1, 1, 0, true);
  return featureOf;
}

TEST(FeatureEvidence, StripsBetweenDifferentRegionPairsAreSeparateFeatures) {
  TwoStripsAndACorner t;
  std::vector<es::Feature> features;
  const auto featureOf = t.group(features);
  ASSERT_EQ(features.size(), 3u);
  for (std::size_t k = 1; k < 4; ++k) EXPECT_EQ(featureOf[k], featureOf[0]);
  for (std::size_t k = 5; k < 7; ++k) EXPECT_EQ(featureOf[k], featureOf[4]);
  EXPECT_NE(featureOf[0], featureOf[4]);
  EXPECT_NE(featureOf[7], featureOf[0]);
  EXPECT_NE(featureOf[7], featureOf[4]);
  EXPECT_TRUE(features[featureOf[7]].corner);
  EXPECT_FALSE(features[featureOf[0]].corner);
}

TEST(FeatureEvidence, DisconnectedStripsBetweenTheSameRegionsAreSeparateFeatures) {
  es::SplitPlan plan;
  plan.originalVertexCount = 10;
  plan.inserted = {edgeVertex(0, 1), edgeVertex(1, 2), edgeVertex(5, 6), edgeVertex(6, 7)};
  const std::vector<long> region{0, 1, 0, -1, -1, 0, 1, 0, -1, -1};
  std::vector<es::Feature> features;
  const auto featureOf = es::groupFeatures(
      plan, [&](std::size_t v) { return region[v]; }, features);
  EXPECT_EQ(features.size(), 2u);
  EXPECT_EQ(featureOf[0], featureOf[1]);
  EXPECT_EQ(featureOf[2], featureOf[3]);
  EXPECT_NE(featureOf[0], featureOf[2]);
}

// A pyramid's apex: four regions meet, and the chamfered apex holds, beside
// its corner vertices, an edge between two opposite faces (regions 0 and 2,
// which touch only at the apex). Every vertex of that edge shares a source
// with the corner's: it lies inside the corner's chamfer and is part of it.
TEST(FeatureEvidence, AnEdgeInsideACornersChamferIsPartOfIt) {
  es::SplitPlan plan;
  plan.originalVertexCount = 12;
  const std::vector<long> region{0, 1, 2, 3, 0, 2, -1, -1, -1, -1, -1, -1};
  plan.inserted = {cornerVertex(0, 1, 2), cornerVertex(2, 3, 4), edgeVertex(4, 5),
                   edgeVertex(5, 0)};
  std::vector<es::Feature> features;
  const auto featureOf = es::groupFeatures(
      plan, [&](std::size_t v) { return region[v]; }, features);
  ASSERT_EQ(features.size(), 1u);
  for (std::size_t k = 1; k < 4; ++k) EXPECT_EQ(featureOf[k], featureOf[0]);
  EXPECT_TRUE(features[0].corner);
}

// An edge that runs on beyond the corner's chamfer (some vertex of it
// touches no corner vertex) stays an edge, however short.
TEST(FeatureEvidence, AnEdgeRunningOutOfTheCornerStaysAnEdge) {
  es::SplitPlan plan;
  plan.originalVertexCount = 12;
  const std::vector<long> region{0, 1, 2, 3, 0, 2, 0, -1, -1, -1, -1, -1};
  plan.inserted = {cornerVertex(0, 1, 2), cornerVertex(2, 3, 4), edgeVertex(4, 5),
                   edgeVertex(5, 6)};
  std::vector<es::Feature> features;
  const auto featureOf = es::groupFeatures(
      plan, [&](std::size_t v) { return region[v]; }, features);
  ASSERT_EQ(features.size(), 2u);
  EXPECT_EQ(featureOf[2], featureOf[3]);
  EXPECT_NE(featureOf[2], featureOf[0]);
  EXPECT_FALSE(features[featureOf[2]].corner);
}

TEST(FeatureEvidence, WeakWhenShortRefusedOrOffItsPlanes) {
  es::SharpenOptions opt;  // 3 vertices, half refused, 0.6 spacings off plane
  EXPECT_FALSE(es::isLeft(es::judgeFeature(feature(10, 10), opt)));
  EXPECT_FALSE(es::isLeft(es::judgeFeature(feature(10, 5), opt)));  // half: not most
  EXPECT_TRUE(es::isLeft(es::judgeFeature(feature(10, 4), opt)));
  EXPECT_TRUE(es::isLeft(es::judgeFeature(feature(2, 2), opt)));
  EXPECT_FALSE(es::isLeft(es::judgeFeature(feature(1, 1, 0, /*corner=*/true), opt)));
  EXPECT_FALSE(es::isLeft(es::judgeFeature(feature(10, 10, 0.6), opt)));
  EXPECT_TRUE(es::isLeft(es::judgeFeature(feature(10, 10, 0.7), opt)));
}

// Each feature gets the verdict of the first rule it fails, in the
// rulebook's order: on the surface, too short, shallow, across its chamfer,
// off its planes, mostly refused.
TEST(FeatureEvidence, TheVerdictNamesTheFirstRuleAFeatureFails) {
  const es::SharpenOptions opt;
  EXPECT_EQ(es::judgeFeature(feature(10, 10), opt), es::Verdict::Restored);
  EXPECT_EQ(es::judgeFeature(feature(2, 2), opt), es::Verdict::TooShort);
  EXPECT_EQ(es::judgeFeature(feature(2, 0, 1.0), opt), es::Verdict::TooShort);
  es::Feature shallow = feature(10, 10);
  shallow.flankAngleRad = 10 * M_PI / 180;
  EXPECT_EQ(es::judgeFeature(shallow, opt), es::Verdict::ShallowAngle);
  es::Feature across = feature(10, 10);
  across.lineChamferAngleRad = 60 * M_PI / 180;
  EXPECT_EQ(es::judgeFeature(across, opt), es::Verdict::LineAcrossChamfer);
  EXPECT_EQ(es::judgeFeature(feature(10, 10, 0.7), opt), es::Verdict::OffItsPlanes);
  EXPECT_EQ(es::judgeFeature(feature(10, 4, 0.7), opt), es::Verdict::OffItsPlanes);
  EXPECT_EQ(es::judgeFeature(feature(10, 4), opt), es::Verdict::MostlyRefused);
  es::Feature bevel = feature(10, 10, 0.2);
  bevel.offPlaneMedian = 0.2;
  EXPECT_EQ(es::judgeFeature(bevel, opt, /*exactSampling=*/true), es::Verdict::OnTheSurface);
  EXPECT_EQ(es::countVerdicts({es::Verdict::Restored, es::Verdict::TooShort,
                               es::Verdict::Restored})[static_cast<int>(es::Verdict::Restored)],
            2u);
}

// A vertex whose target crosses to another sheet of the input counts as one
// the other tests refused.
TEST(FeatureEvidence, AFewFarSamplesOfAnExactlySampledFeatureDoNotMakeItWeak) {
  const es::SharpenOptions opt;
  es::Feature f = feature(40, 40, /*offPlane=*/2.9);
  f.offPlaneQ90 = 0.0;  // the rest on their planes: a remesher that reprojects
  EXPECT_FALSE(es::isLeft(es::judgeFeature(f, opt)));
  f.offPlaneQ90 = 0.05;
  EXPECT_FALSE(es::isLeft(es::judgeFeature(f, opt)));
  f.offPlaneQ90 = 0.2;  // a blend along it
  EXPECT_TRUE(es::isLeft(es::judgeFeature(f, opt)));
  es::SharpenOptions everyFarSample;
  everyFarSample.rules.feature.onPlaneSpacings = 0;
  f.offPlaneQ90 = 0.0;
  EXPECT_TRUE(es::isLeft(es::judgeFeature(f, everyFarSample)));
}

// A sampler that rounds the samples nearest an edge (a reconstruction, a
// voxel remesher's corner cells) leaves half of them on their planes; a
// blend or a bevel along the feature moves most of them off.
TEST(FeatureEvidence, AFeatureMostlyOnItsPlanesIsNotWeak) {
  const es::SharpenOptions opt;  // median within 0.1 spacings, none beyond 1
  es::Feature f = feature(40, 40, /*offPlane=*/0.9);
  f.offPlaneMedian = 0.05;
  EXPECT_FALSE(es::isLeft(es::judgeFeature(f, opt)));
  f.offPlaneMedian = 0.1;
  EXPECT_FALSE(es::isLeft(es::judgeFeature(f, opt)));
  f.offPlaneMedian = 0.2;  // a blend along it
  EXPECT_TRUE(es::isLeft(es::judgeFeature(f, opt)));
  f.offPlaneMedian = 0.05;
  f.maxOffPlane = 1.2;  // a sample beyond a whole spacing
  EXPECT_TRUE(es::isLeft(es::judgeFeature(f, opt)));
  es::SharpenOptions off;
  off.rules.feature.medianOnPlaneSpacings = 0;
  f.maxOffPlane = 0.9;
  EXPECT_TRUE(es::isLeft(es::judgeFeature(f, off)));
}

// The line an acute edge's planes meet on moves farther with their errors
// (over the sine of their angle): its samples are allowed less.
TEST(FeatureEvidence, AnAcuteEdgeMostlyOnItsPlanesIsAllowedLess) {
  const es::SharpenOptions opt;
  const double deg = M_PI / 180;
  es::Feature f = feature(40, 40, /*offPlane=*/0.8);
  f.offPlaneMedian = 0.05;
  f.flankAngleRad = 60 * deg;  // allows 0.87 spacings
  EXPECT_FALSE(es::isLeft(es::judgeFeature(f, opt)));
  f.flankAngleRad = 45 * deg;  // allows 0.71
  EXPECT_TRUE(es::isLeft(es::judgeFeature(f, opt)));
  f.maxOffPlane = 0.65;
  EXPECT_FALSE(es::isLeft(es::judgeFeature(f, opt)));
  f.offPlaneMedian = 0.08;  // beyond 0.1 x sin 45 degrees
  EXPECT_TRUE(es::isLeft(es::judgeFeature(f, opt)));
  es::Feature corner = feature(1, 1, /*offPlane=*/0.8, /*corner=*/true);
  corner.offPlaneMedian = 0.05;
  corner.flankAngleRad = 30 * deg;  // a corner's angle is not an edge's
  EXPECT_FALSE(es::isLeft(es::judgeFeature(corner, opt)));
}

// A vertex of a feature kept goes back on its own evidence: a far sample,
// or a long move from samples off their planes.
TEST(FeatureEvidence, ALongMoveNeedsItsSamplesOnTheirPlanes) {
  const es::SharpenOptions opt;  // far: 0.6 spacings; long: 2 spacings, 0.3 off
  const bool edge = false, corner = true;
  EXPECT_FALSE(es::vertexEvidenceIsWeak(0.5, 0.0, edge, opt));
  EXPECT_TRUE(es::vertexEvidenceIsWeak(0.5, 0.7, edge, opt));  // a far sample, whatever the move
  EXPECT_TRUE(es::vertexEvidenceIsWeak(0.5, 0.7, corner, opt));
  EXPECT_FALSE(es::vertexEvidenceIsWeak(0.9, 0.5, edge, opt));   // short: the feature's bound
  EXPECT_FALSE(es::vertexEvidenceIsWeak(2.5, 0.25, edge, opt));  // long, samples on their planes
  EXPECT_TRUE(es::vertexEvidenceIsWeak(2.5, 0.35, edge, opt));
  EXPECT_FALSE(es::vertexEvidenceIsWeak(2.5, 0.35, corner, opt));  // pinned by three planes
  EXPECT_FALSE(es::vertexEvidenceIsWeak(2.0, 0.35, edge, opt));    // not longer than the bound
  es::SharpenOptions off = opt;
  off.rules.vertex.longMoveSpacings = 0;
  EXPECT_FALSE(es::vertexEvidenceIsWeak(2.5, 0.35, edge, off));
  EXPECT_TRUE(es::vertexEvidenceIsWeak(2.5, 0.7, edge, off));
}

// The median edge feature, weighted by its new vertices, decides: exact
// samplers put nine in ten of a sharp edge's samples on its planes (within a
// thousandth of a spacing), marching cubes and voxel remeshers do not.
TEST(FeatureEvidence, AMeshIsSampledExactlyWhenItsMedianFeatureIs) {
  const es::SharpenOptions opt;  // exact: 0.001 spacings
  std::vector<es::Feature> features = {feature(100, 100, 0.0), feature(60, 60, 0.2),
                                       feature(30, 30, 0.3)};
  EXPECT_TRUE(es::sampledExactly(features, opt));  // 100 of 190 new vertices on their planes
  features[1].vertices = features[1].moved = 80;
  EXPECT_FALSE(es::sampledExactly(features, opt));  // 100 of 210
  features[0].offPlaneQ90 = 0.0005;
  features[1].offPlaneQ90 = 0.0008;
  EXPECT_TRUE(es::sampledExactly(features, opt));
  // Corners and features that did not move do not count.
  EXPECT_FALSE(es::sampledExactly(
      {feature(100, 0, 0.0), feature(100, 100, 0.2), feature(300, 300, 0.0, /*corner=*/true)},
      opt));
  EXPECT_FALSE(es::sampledExactly({}, opt));
  es::SharpenOptions off = opt;
  off.rules.mesh.exactSamplingSpacings = 0;
  EXPECT_FALSE(es::sampledExactly({feature(100, 100, 0.0)}, off));
}

// On a mesh sampled exactly, samples off their planes are the surface: a
// designed bevel's samples lie on it, 0.1-0.5 spacings off both flanks.
TEST(FeatureEvidence, OnAnExactlySampledMeshSamplesOffTheirPlanesAreTheSurface) {
  const es::SharpenOptions opt;  // on-plane: 0.05 spacings
  const es::Feature bevel = feature(40, 40, /*offPlane=*/0.2);
  EXPECT_FALSE(es::isLeft(es::judgeFeature(bevel, opt, /*exactSampling=*/false)));
  EXPECT_TRUE(es::isLeft(es::judgeFeature(bevel, opt, /*exactSampling=*/true)));
  EXPECT_TRUE(es::isLeft(es::judgeFeature(feature(1, 1, 0.2, /*corner=*/true), opt, true)));
  EXPECT_FALSE(es::isLeft(es::judgeFeature(feature(40, 40, 0.04), opt, true)));
  // A sharp edge with a few samples where it meets a bevel: its median on
  // its planes, the feature stays; the far samples' own new vertices rest.
  es::Feature edge = feature(40, 40, /*offPlane=*/2.5);
  edge.offPlaneQ90 = 0.04;
  edge.offPlaneMedian = 0;
  EXPECT_FALSE(es::isLeft(es::judgeFeature(edge, opt, true)));
  const bool notCorner = false;
  EXPECT_FALSE(es::vertexEvidenceIsWeak(0.5, 0.2, notCorner, opt, /*exactSampling=*/false));
  EXPECT_TRUE(es::vertexEvidenceIsWeak(0.5, 0.2, notCorner, opt, /*exactSampling=*/true));
  EXPECT_FALSE(es::vertexEvidenceIsWeak(0.5, 0.04, notCorner, opt, true));
  es::SharpenOptions off = opt;
  off.rules.feature.onPlaneSpacings = 0;
  EXPECT_FALSE(es::isLeft(es::judgeFeature(bevel, off, true)));
  EXPECT_FALSE(es::vertexEvidenceIsWeak(0.5, 0.2, notCorner, off, true));
}

TEST(FeatureEvidence, QuantileIsTheNearestRank) {
  std::vector<double> none;
  EXPECT_EQ(es::detail::quantileOf(none, 0.9), 0.0);
  std::vector<double> values = {5, 0, 9, 1, 2, 3, 4, 6, 7, 8, 10};  // 0..10
  EXPECT_EQ(es::detail::quantileOf(values, 0.9), 9.0);
  EXPECT_EQ(es::detail::quantileOf(values, 0.5), 5.0);
  EXPECT_EQ(es::detail::quantileOf(values, 1.0), 10.0);
  std::vector<double> three = {0.0, 0.0, 3.0};  // a short feature: its farthest sample counts
  EXPECT_EQ(es::detail::quantileOf(three, 0.9), 3.0);
}

TEST(FeatureEvidence, VerticesCrossingToAnotherSheetCountAsRefused) {
  es::SharpenOptions opt;  // most refused
  es::Feature f = feature(10, 10);
  f.crossed = 5;
  EXPECT_FALSE(es::isLeft(es::judgeFeature(f, opt)));
  f.crossed = 6;
  EXPECT_TRUE(es::isLeft(es::judgeFeature(f, opt)));
  f.moved = 8, f.crossed = 4;  // two refused, four crossed: 60%
  EXPECT_TRUE(es::isLeft(es::judgeFeature(f, opt)));
}

// An edge whose flanks meet at a shallow angle (a gentle crease, or a knife
// edge) is weak; a corner is judged by its edges.
TEST(FeatureEvidence, WeakWhereTheFlanksMeetAtAShallowAngle) {
  es::SharpenOptions opt;  // 20 degrees
  const double deg = M_PI / 180;
  es::Feature f = feature(10, 10);
  f.flankAngleRad = 19 * deg;
  EXPECT_TRUE(es::isLeft(es::judgeFeature(f, opt)));
  f.flankAngleRad = 21 * deg;
  EXPECT_FALSE(es::isLeft(es::judgeFeature(f, opt)));
  es::Feature corner = feature(1, 1, 0, /*corner=*/true);
  corner.flankAngleRad = 5 * deg;
  EXPECT_FALSE(es::isLeft(es::judgeFeature(corner, opt)));
  opt.rules.feature.minFeatureAngleRad = 0;  // off
  f.flankAngleRad = 1 * deg;
  EXPECT_FALSE(es::isLeft(es::judgeFeature(f, opt)));
}

// An edge whose flanks' planes meet on a line that crosses its chamfer
// instead of running along it (the two walls beside a thin wall's cap) is
// weak; a corner is judged by its edges.
TEST(FeatureEvidence, WeakWhereThePlanesLineCrossesTheChamfer) {
  es::SharpenOptions opt;  // 45 degrees
  const double deg = M_PI / 180;
  es::Feature f = feature(10, 10);
  EXPECT_FALSE(es::isLeft(es::judgeFeature(f, opt)));  // along it
  f.lineChamferAngleRad = 44 * deg;
  EXPECT_FALSE(es::isLeft(es::judgeFeature(f, opt)));
  f.lineChamferAngleRad = 46 * deg;
  EXPECT_TRUE(es::isLeft(es::judgeFeature(f, opt)));
  es::Feature corner = feature(1, 1, 0, /*corner=*/true);
  corner.lineChamferAngleRad = 80 * deg;
  EXPECT_FALSE(es::isLeft(es::judgeFeature(corner, opt)));
  opt.rules.feature.maxFeatureLineChamferAngleRad = 0;  // off
  EXPECT_FALSE(es::isLeft(es::judgeFeature(f, opt)));
}

TEST(FeatureEvidence, PlanesMeetAtTheSmallerOfTheirAngles) {
  const double deg = M_PI / 180;
  const es::Vec3 up(0, 0, 1);
  const auto turned = [&](double a) { return es::Vec3(std::sin(a * deg), 0, std::cos(a * deg)); };
  EXPECT_NEAR(es::planeMeetingAngle(up, turned(10)), 10 * deg, 1e-9);   // shallow crease
  EXPECT_NEAR(es::planeMeetingAngle(up, turned(90)), 90 * deg, 1e-9);   // right angle
  EXPECT_NEAR(es::planeMeetingAngle(up, turned(170)), 10 * deg, 1e-9);  // knife edge
  EXPECT_NEAR(es::planeMeetingAngle(up, up), 0.0, 1e-9);
  EXPECT_NEAR(es::planeMeetingAngle(up, -up), 0.0, 1e-9);
}

// A target nearer the far side of a wall than its own surface has crossed
// the wall's middle; a face turned less than 120 degrees from the own side
// (the next flank at a corner) is not another sheet.
TEST(FeatureEvidence, ATargetPastTheMiddleOfAWallCrossesToItsOtherSide) {
  const es::Vec3 out(1, 0, 0), in(-1, 0, 0), side(0, 1, 0);
  EXPECT_TRUE(es::crossesSheet(0.10, out, 0.05, in));
  EXPECT_FALSE(es::crossesSheet(0.05, out, 0.10, in));  // not past the middle
  EXPECT_FALSE(es::crossesSheet(0.10, out, 0.05, side));
  EXPECT_FALSE(es::crossesSheet(0.10, out, 0.05, out));
  const es::Vec3 turned110(std::cos(110 * M_PI / 180), std::sin(110 * M_PI / 180), 0);
  EXPECT_FALSE(es::crossesSheet(0.10, out, 0.05, turned110));
}

TEST(FeatureEvidence, RefusedFractionCountsOnlyFeaturesThatMoved) {
  EXPECT_DOUBLE_EQ(es::refusedFraction({feature(10, 10), feature(10, 0)}), 0.0);
  EXPECT_DOUBLE_EQ(es::refusedFraction({feature(10, 5), feature(30, 30)}), 5.0 / 40.0);
  EXPECT_DOUBLE_EQ(es::refusedFraction({}), 0.0);
}

TEST(FeatureEvidence, AWeakEdgeTakesItsCornerButNotTheOtherEdge) {
  TwoStripsAndACorner t;
  std::vector<es::Feature> features;
  const auto featureOf = t.group(features);
  const std::uint32_t a = featureOf[0], b = featureOf[4], corner = featureOf[7];
  features[a] = feature(4, 4);
  features[b] = feature(3, 3);
  features[corner] = feature(1, 1, 0, true);
  es::SharpenOptions opt;
  auto verdict = es::featureVerdicts(t.plan, features, featureOf, /*lift=*/1.0, kRoughSurface, opt);
  EXPECT_FALSE(es::isLeft(verdict[a]) || es::isLeft(verdict[b]) || es::isLeft(verdict[corner]));

  features[a] = feature(4, 4, /*offPlane=*/1.0);  // a sample of strip A lies off its plane
  verdict = es::featureVerdicts(t.plan, features, featureOf, /*lift=*/1.0, kRoughSurface, opt);
  EXPECT_EQ(verdict[a], es::Verdict::OffItsPlanes);
  EXPECT_EQ(verdict[corner], es::Verdict::CornerOfWeakEdge);
  EXPECT_EQ(verdict[b], es::Verdict::Restored);
}

// An edge whose planes meet across its chamfer takes its corner with it,
// unless it is joined to that corner as one patch (EvidenceGuard's corner
// patches: the planes of both fix one point), where it is judged with it.
TEST(FeatureEvidence, AnEdgeJoinedToItsCornerIsJudgedWithIt) {
  TwoStripsAndACorner t;
  std::vector<es::Feature> features;
  const auto featureOf = t.groupAllMoved(features);
  const std::uint32_t a = featureOf[0], b = featureOf[4], corner = featureOf[7];
  features[a].lineChamferAngleRad = 80.0 * M_PI / 180.0;
  es::SharpenOptions opt;
  auto verdict = es::featureVerdicts(t.plan, features, featureOf, /*lift=*/1.0, kRoughSurface, opt);
  EXPECT_EQ(verdict[a], es::Verdict::LineAcrossChamfer);
  EXPECT_EQ(verdict[corner], es::Verdict::CornerOfWeakEdge);

  std::vector<char> patch(features.size(), 0);
  patch[a] = 1;
  verdict = es::featureVerdicts(t.plan, features, featureOf, /*lift=*/1.0, kRoughSurface, opt,
                                /*exactSampling=*/false, /*held=*/{}, patch);
  EXPECT_EQ(verdict[a], es::Verdict::Restored);
  EXPECT_EQ(verdict[corner], es::Verdict::Restored);
  EXPECT_EQ(verdict[b], es::Verdict::Restored);

  // An edge whose moves placement mostly refused (the line of two faces
  // that touch only at the corner runs off the solid past it) is judged
  // with its corner as well.
  features[a].lineChamferAngleRad = 0;
  features[a].moved = features[a].vertices / 4;
  verdict = es::featureVerdicts(t.plan, features, featureOf, /*lift=*/1.0, kRoughSurface, opt);
  EXPECT_EQ(verdict[a], es::Verdict::MostlyRefused);
  EXPECT_EQ(verdict[corner], es::Verdict::CornerOfWeakEdge);
  verdict = es::featureVerdicts(t.plan, features, featureOf, /*lift=*/1.0, kRoughSurface, opt,
                                /*exactSampling=*/false, /*held=*/{}, patch);
  EXPECT_EQ(verdict[a], es::Verdict::Restored);
  EXPECT_EQ(verdict[corner], es::Verdict::Restored);

  // A patch does not excuse another rule: an edge off its planes stays left.
  features[a].moved = features[a].vertices;
  features[a].maxOffPlane = features[a].offPlaneQ90 = features[a].offPlaneMedian = 1.0;
  features[a].lineChamferAngleRad = 0;
  verdict = es::featureVerdicts(t.plan, features, featureOf, /*lift=*/1.0, kRoughSurface, opt,
                                /*exactSampling=*/false, /*held=*/{}, patch);
  EXPECT_EQ(verdict[a], es::Verdict::OffItsPlanes);
  EXPECT_EQ(verdict[corner], es::Verdict::CornerOfWeakEdge);
}

TEST(FeatureEvidence, TooManyRefusalsLeaveTheWholeMesh) {
  TwoStripsAndACorner t;
  std::vector<es::Feature> features;
  const auto featureOf = t.groupAllMoved(features);
  es::SharpenOptions opt;
  opt.rules.mesh.maxRefusedFraction = 0.4;
  opt.rules.feature.maxFeatureFallbackFraction = 1;  // strip B alone would pass
  features[featureOf[4]] = feature(30, 10);          // 20 of 35 refused overall
  const auto verdict =
      es::featureVerdicts(t.plan, features, featureOf, /*lift=*/1.0, kRoughSurface, opt);
  for (es::Verdict v : verdict) EXPECT_EQ(v, es::Verdict::MeshEvidenceWeak);
}

TEST(FeatureEvidence, SmoothPartsMadeOfPlanesAreJudgedFeatureByFeature) {
  TwoStripsAndACorner t;
  std::vector<es::Feature> features;
  const auto featureOf = t.groupAllMoved(features);
  es::SharpenOptions opt;
  opt.rules.mesh.maxRefusedFraction = 0.4;
  opt.rules.mesh.maxRefusedFractionSmooth = 0.6;
  opt.rules.mesh.maxSmoothNoiseSpacings = 0.02;
  opt.rules.mesh.minPlanarAreaFraction = 0.3;
  opt.rules.feature.maxFeatureFallbackFraction = 1;  // every feature alone would pass
  features[featureOf[4]] = feature(30, 10);  // 20 of 35 refused overall: above 0.4, below 0.6
  const auto allWeak = [&](const es::SurfaceMeasures &surface) {
    const auto verdict =
        es::featureVerdicts(t.plan, features, featureOf, /*lift=*/1.0, surface, opt);
    return std::all_of(verdict.begin(), verdict.end(),
                       [](es::Verdict v) { return v == es::Verdict::MeshEvidenceWeak; });
  };
  EXPECT_FALSE(allWeak({/*noiseSpacings=*/0.01, /*planarFraction=*/0.5}));
  EXPECT_TRUE(allWeak({/*noiseSpacings=*/0.03, /*planarFraction=*/0.5}));  // rough: a scan
  EXPECT_TRUE(allWeak({/*noiseSpacings=*/0.01, /*planarFraction=*/0.1}));  // freeform
  opt.rules.mesh.maxSmoothNoiseSpacings = 0;                               // off
  EXPECT_TRUE(allWeak({/*noiseSpacings=*/0.0, /*planarFraction=*/1.0}));
  opt.rules.mesh.maxSmoothNoiseSpacings = 0.02;
  features[featureOf[4]] = feature(30, 5);  // 25 of 35 refused: above the smooth bound too
  EXPECT_TRUE(allWeak({/*noiseSpacings=*/0.01, /*planarFraction=*/0.5}));
}

TEST(FeatureEvidence, MovesThatOnlySlideLeaveTheWholeMesh) {
  TwoStripsAndACorner t;
  std::vector<es::Feature> features;
  const auto featureOf = t.groupAllMoved(features);
  es::SharpenOptions opt;  // median lift at least 0.07
  for (es::Verdict v :
       es::featureVerdicts(t.plan, features, featureOf, /*lift=*/0.8, kRoughSurface, opt))
    EXPECT_EQ(v, es::Verdict::Restored);
  for (es::Verdict v :
       es::featureVerdicts(t.plan, features, featureOf, /*lift=*/0.03, kRoughSurface, opt))
    EXPECT_EQ(v, es::Verdict::MeshEvidenceWeak);
  opt.rules.mesh.minMedianLift = 0;  // off
  for (es::Verdict v :
       es::featureVerdicts(t.plan, features, featureOf, /*lift=*/0.03, kRoughSurface, opt))
    EXPECT_EQ(v, es::Verdict::Restored);
}

// A remesher casting its vertices onto the input puts them on the convex
// edges it meets and leaves others chamfered: on a mesh sampled exactly,
// a mostly sliding median leaves only the sliding features, and the
// chamfered strip lifting to its edge is judged alone. An edge already
// sharp is no evidence against the corner it runs into, and is flagged as
// such: of its moves only those that slide go back (the guard judges the
// others one by one).
TEST(FeatureEvidence, OnAMeshSampledExactlyOnlyTheFeaturesThatSlideAreAlreadySharp) {
  TwoStripsAndACorner t;
  std::vector<es::Feature> features;
  const auto featureOf = t.groupAllMoved(features);
  const std::uint32_t a = featureOf[0], b = featureOf[4], corner = featureOf[7];
  features[a].medianLift = 0.0;  // strip A slides along the input
  features[b].medianLift = 0.8;  // strip B lifts to its edge
  es::SharpenOptions opt;        // median lift at least 0.07
  auto verdict = es::featureVerdicts(t.plan, features, featureOf, /*lift=*/0.03, kRoughSurface, opt,
                                     /*exactSampling=*/true);
  EXPECT_TRUE(es::isLeft(verdict[a]));
  EXPECT_FALSE(es::isLeft(verdict[b]));
  EXPECT_FALSE(es::isLeft(verdict[corner]));
  // Strip A is weak for sliding alone: its moves that lift are judged one by one.
  ASSERT_EQ(verdict.size(), features.size());
  EXPECT_TRUE((verdict[a] == es::Verdict::AlreadySharp));
  EXPECT_FALSE((verdict[b] == es::Verdict::AlreadySharp) ||
               (verdict[corner] == es::Verdict::AlreadySharp));
  features[corner].medianLift = 0.0;  // the corner slides too
  verdict = es::featureVerdicts(t.plan, features, featureOf, /*lift=*/0.03, kRoughSurface, opt,
                                /*exactSampling=*/true);
  EXPECT_TRUE(es::isLeft(verdict[corner]));
  EXPECT_TRUE((verdict[corner] == es::Verdict::AlreadySharp));
  features[corner].medianLift = 1.0;
  features[b] = feature(3, 3, /*offPlane=*/1.0);  // strip B weak by its evidence: its corner too
  features[b].medianLift = 0.8;
  verdict = es::featureVerdicts(t.plan, features, featureOf, /*lift=*/0.03, kRoughSurface, opt,
                                /*exactSampling=*/true);
  EXPECT_TRUE(es::isLeft(verdict[b]));
  EXPECT_TRUE(es::isLeft(verdict[corner]));
  // Weak by their evidence, not by sliding: every move of theirs goes back.
  EXPECT_FALSE((verdict[b] == es::Verdict::AlreadySharp) ||
               (verdict[corner] == es::Verdict::AlreadySharp));
  features[b].medianLift = 0.0;  // weak by its evidence and sliding: the evidence decides
  verdict = es::featureVerdicts(t.plan, features, featureOf, /*lift=*/0.03, kRoughSurface, opt,
                                /*exactSampling=*/true);
  EXPECT_TRUE(es::isLeft(verdict[b]));
  EXPECT_FALSE((verdict[b] == es::Verdict::AlreadySharp));
  features[b] = feature(3, 3);
  features[b].medianLift = 0.8;
  EXPECT_FALSE(es::meshEvidenceIsWeak(0.0, 0.03, kRoughSurface, opt, /*exactSampling=*/true));
  EXPECT_TRUE(es::meshEvidenceIsWeak(0.0, 0.03, kRoughSurface, opt, /*exactSampling=*/false));
  // Where the median lifts, a feature sliding alone is judged as before.
  verdict = es::featureVerdicts(t.plan, features, featureOf, /*lift=*/0.5, kRoughSurface, opt,
                                /*exactSampling=*/true);
  EXPECT_FALSE(es::isLeft(verdict[a]) || es::isLeft(verdict[b]) || es::isLeft(verdict[corner]));
  // Not sampled exactly: the whole mesh is already sharp, every move goes back.
  verdict = es::featureVerdicts(t.plan, features, featureOf, /*lift=*/0.03, kRoughSurface, opt,
                                /*exactSampling=*/false);
  for (es::Verdict v : verdict) EXPECT_EQ(v, es::Verdict::MeshEvidenceWeak);
}

TEST(FeatureEvidence, EachFeatureTakesTheMedianLiftOfItsOwnMoves) {
  std::vector<es::Feature> features(2);
  es::measureFeatureLifts({0.9, -1, 0.7, 0.8, 0.0, 0.1, 0.02}, {0, 0, 0, 0, 1, 1, 1}, features);
  EXPECT_DOUBLE_EQ(features[0].medianLift, 0.8);  // the unmoved vertex does not count
  EXPECT_DOUBLE_EQ(features[1].medianLift, 0.02);
}

TEST(FeatureEvidence, MedianLiftCountsOnlyTheMoves) {
  EXPECT_DOUBLE_EQ(es::medianLift({-1, 0.9, -1, 0.7, 0.8}), 0.8);
  EXPECT_DOUBLE_EQ(es::medianLift({-1, -1}), 1.0);  // nothing moved: nothing against it
  EXPECT_DOUBLE_EQ(es::medianLift({}), 1.0);
}

// A 90-degree edge chamfered at 45 degrees: the flanks z = 0 (x <= 0) and
// x = 0 (z <= 0) cut back by the chamfer from (-1, 0) to (0, -1) in (x, z).
// Cutting the chamfer back moves its midpoint (-0.5, -0.5) to the edge at
// the origin, by 1/sqrt(2); the nearest input face, the chamfer, is as far
// from the edge: lift 1.
TEST(FeatureEvidence, CuttingAChamferBackLiftsTheSurface) {
  using T = vcg::Triangle3<double>;
  const std::vector<T> chamfered{T({-1, 0, 0}, {-1, 1, 0}, {-3, 0, 0}),  // flank z = 0
                                 T({0, 0, -1}, {0, 1, -1}, {0, 0, -3}),  // flank x = 0
                                 T({-1, 0, 0}, {0, 0, -1}, {0, 1, -1}),
                                 T({-1, 0, 0}, {0, 1, -1}, {-1, 1, 0})};  // chamfer
  EXPECT_NEAR(es::moveLift({0, 0.5, 0}, {-0.5, 0.5, -0.5}, chamfered), 1.0, 1e-12);
}

// The same edge already sharp: the inserted vertex sat on a thin triangle
// across the edge and its move slides it onto the edge, which lies on the
// input's faces: nothing is lifted.
TEST(FeatureEvidence, SlidingAlongASharpInputLiftsNothing) {
  using T = vcg::Triangle3<double>;
  const std::vector<T> sharp{T({0, 0, 0}, {0, 1, 0}, {-3, 0, 0}),   // flank z = 0
                             T({0, 0, 0}, {0, 0, -3}, {0, 1, 0})};  // flank x = 0
  EXPECT_NEAR(es::moveLift({0, 0.5, 0}, {-0.2, 0.5, 0}, sharp), 0.0, 1e-12);
  // Half-way: a move along a face and then off it lifts by the part off it.
  EXPECT_NEAR(es::moveLift({0.3, 0.5, 0}, {-0.3, 0.5, 0}, sharp), 0.5, 1e-12);
  // A move of no length, or with no faces to measure against, counts as lifting.
  EXPECT_EQ(es::moveLift({0, 0, 0}, {0, 0, 0}, sharp), 1.0);
  EXPECT_EQ(es::moveLift({1, 0, 0}, {0, 0, 0}, {}), 1.0);
}

// A slab 0.1 thick: a new vertex on its top face's diagonal, moved down into
// it, crosses to the bottom face once it is past the middle; the mesh pass
// (one look-up of the faces near each target) finds that face.
TEST(FeatureEvidence, SheetCrossingsAreFoundInTheMesh) {
  const double t = 0.1;
  es::Mesh m;
  es::hand_built::makeMesh(
      m, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, t}, {1, 0, t}, {1, 1, t}, {0, 1, t}},
      {{0, 2, 1},
       {0, 3, 2},
       {4, 5, 6},
       {4, 6, 7},
       {0, 1, 5},
       {0, 5, 4},
       {1, 2, 6},
       {1, 6, 5},
       {2, 3, 7},
       {2, 7, 6},
       {3, 0, 4},
       {3, 4, 7}});
  vcg::tri::Allocator<es::Mesh>::AddVertices(m, 1);  // the new vertex, in no face
  es::SplitPlan plan;
  plan.originalVertexCount = 8;
  plan.inserted.push_back(edgeVertex(4, 6));
  plan.inserted[0].rest = es::Vec3(0.5, 0.5, t);
  es::MeshLabels<es::Mesh> labels(m);
  const es::VertexMoves<es::Mesh> moves(m, plan, labels, false);
  es::SupportPlanes support;
  support.reset(9);
  support.setFit(4, es::SupportFit::of(es::Plane{es::Vec3(0, 0, t), es::Vec3(0, 0, 1)}));
  support.shareFit(6, 4);
  std::vector<es::Feature> features(1);
  const auto crossedWhenMovedDownBy = [&](double depth, double lift) {
    m.vert[8].P() = es::Mesh::CoordType::Construct(es::Vec3(0.5, 0.5, t - depth));
    es::countSheetCrossings(m, moves, support, {lift}, {0}, std::sqrt(2.0), features);
    return features[0].crossed;
  };
  EXPECT_EQ(crossedWhenMovedDownBy(0.07, 1.0), 1u);   // 0.03 from the bottom, 0.07 from the top
  EXPECT_EQ(crossedWhenMovedDownBy(0.03, 1.0), 0u);   // still nearer its own side
  EXPECT_EQ(crossedWhenMovedDownBy(0.07, -1.0), 0u);  // not moved
}

// A fillet the sampler did not make: an edge whose samples lie on an arc
// wider, by more than the ambiguous width, than the arcs of the edges a grid
// meets alike is left on the surface; as wide as those, it is restored.
TEST(FeatureEvidence, AnArcWiderThanTheSamplersAtAlikeEdgesIsADesignedFillet) {
  const es::SharpenOptions opt;
  const es::Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const auto edge = [&](es::Vec3 a, es::Vec3 b, double width, std::size_t samples,
                        double rms = 0.02) {
    es::Feature f = feature(10, 10);
    f.flankNormals = {a, b};
    f.filletWidthSpacings = width;
    f.filletRmsSpacings = rms;
    f.wedgeRmsSpacings = 0.3;  // samples off the sharp wedge
    f.filletSamples = samples;
    return f;
  };
  // A plate's top edges, sharp, and its bottom edges, filleted 2.4 spacings
  // across: all four pairs of axis planes, alike to a grid.
  std::vector<es::Feature> plate{edge(x, z, 0.3, 100), edge(-y, z, 0.1, 90), edge(x, -z, 2.4, 100),
                                 edge(-y, -z, 2.4, 90)};
  es::measurePeerRounding(plate);
  EXPECT_EQ(es::judgeFeature(plate[0], opt), es::Verdict::Restored);
  EXPECT_EQ(es::judgeFeature(plate[2], opt), es::Verdict::OnTheSurface);
  EXPECT_EQ(es::judgeFeature(plate[3], opt), es::Verdict::OnTheSurface);
  // A voxel remesher's rounding: every edge alike as wide: restored.
  std::vector<es::Feature> voxels{edge(x, z, 2.3, 100), edge(-y, z, 2.4, 90), edge(x, -z, 2.4, 100),
                                  edge(-y, -z, 2.2, 90)};
  es::measurePeerRounding(voxels);
  for (const es::Feature &f : voxels) EXPECT_EQ(es::judgeFeature(f, opt), es::Verdict::Restored);
  // A sharp edge the grid meets otherwise says nothing of the arcs: alone
  // in its kind, an arc is measured against itself.
  const es::Vec3 oblique = es::Vec3(1, 1, 0).Normalize();
  std::vector<es::Feature> mixed{edge(x, z, 0.0, 300), edge(oblique, z, 2.4, 100)};
  es::measurePeerRounding(mixed);
  EXPECT_EQ(es::judgeFeature(mixed[1], opt), es::Verdict::Restored);
  // Samples no fillet fits tell nothing either; the rule can be turned off.
  std::vector<es::Feature> unfit{edge(x, z, 0.3, 100), edge(x, -z, 2.4, 100, 0.3)};
  es::measurePeerRounding(unfit);
  EXPECT_EQ(es::judgeFeature(unfit[1], opt), es::Verdict::Restored);
  // Samples the sharp wedge fits as well (a shallow edge, where any wide
  // arc runs near its planes) tell nothing of a fillet.
  es::Feature shallow = plate[2];
  shallow.wedgeRmsSpacings = 0.05;
  EXPECT_EQ(es::judgeFeature(shallow, opt), es::Verdict::Restored);
  es::SharpenOptions off;
  off.rules.feature.designedFilletMarginSpacings = 0;
  EXPECT_EQ(es::judgeFeature(plate[2], off), es::Verdict::Restored);
}
