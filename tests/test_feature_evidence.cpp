// The auto method's evidence guard (guards/feature_evidence.h) on hand-made
// split plans: which inserted vertices form one feature, when a feature's
// evidence is weak, how a weak edge reaches its corners, and the mesh-wide
// gate; no mesh needed.
#include <gtest/gtest.h>

#include "edge_sharpener/guards/feature_evidence.h"

namespace es = edge_sharpener;

namespace {

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
};

es::Feature feature(std::size_t vertices, std::size_t moved, double offPlane = 0,
                    bool corner = false) {
  es::Feature f;
  f.vertices = vertices;
  f.moved = moved;
  f.medianOffPlane = offPlane;
  f.corner = corner;
  return f;
}

}  // namespace

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

TEST(FeatureEvidence, WeakWhenShortRefusedOrOffItsPlanes) {
  es::SharpenOptions opt;  // 3 vertices, 20% refused, 0.15 spacings off plane
  EXPECT_FALSE(es::featureEvidenceIsWeak(feature(10, 10), opt));
  EXPECT_FALSE(es::featureEvidenceIsWeak(feature(10, 8), opt));  // 20%: not more
  EXPECT_TRUE(es::featureEvidenceIsWeak(feature(10, 7), opt));
  EXPECT_TRUE(es::featureEvidenceIsWeak(feature(2, 2), opt));
  EXPECT_FALSE(es::featureEvidenceIsWeak(feature(1, 1, 0, /*corner=*/true), opt));
  EXPECT_FALSE(es::featureEvidenceIsWeak(feature(10, 10, 0.15), opt));
  EXPECT_TRUE(es::featureEvidenceIsWeak(feature(10, 10, 0.2), opt));
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
  auto weak = es::weakFeatures(t.plan, features, featureOf, opt);
  EXPECT_FALSE(weak[a] || weak[b] || weak[corner]);

  features[a] = feature(4, 4, /*offPlane=*/0.5);  // strip A lies off its planes
  weak = es::weakFeatures(t.plan, features, featureOf, opt);
  EXPECT_TRUE(weak[a]);
  EXPECT_TRUE(weak[corner]);
  EXPECT_FALSE(weak[b]);
}

TEST(FeatureEvidence, TooManyRefusalsLeaveTheWholeMesh) {
  TwoStripsAndACorner t;
  std::vector<es::Feature> features;
  const auto featureOf = t.group(features);
  features[featureOf[0]] = feature(4, 4);
  features[featureOf[4]] = feature(3, 3);
  features[featureOf[7]] = feature(1, 1, 0, true);
  es::SharpenOptions opt;
  opt.maxRefusedFraction = 0.4;
  opt.maxFeatureFallbackFraction = 1;        // strip B alone would pass
  features[featureOf[4]] = feature(30, 10);  // 20 of 35 refused overall
  const auto weak = es::weakFeatures(t.plan, features, featureOf, opt);
  for (char w : weak) EXPECT_TRUE(w);
}
