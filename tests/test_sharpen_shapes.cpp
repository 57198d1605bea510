// End to end: marching-cubes meshes of the exact test shapes, sharpened with
// the paper's method; distances to the exact shapes before and after, and the
// invariants every output must keep.
#include <gtest/gtest.h>
#include <vcg/complex/algorithms/clean.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/util/mesh_types.h"
#include "mesh_distance.h"
#include "test_meshes/shapes.h"

namespace es = edge_sharpener;
namespace shapes = edge_sharpener::test_meshes;

namespace {

struct Case {
  std::string shape;
  double cellFraction;     // of the bounding-box diagonal
  double minMaxReduction;  // required max-error ratio before/after
  double minRmsReduction;  // required RMS ratio before/after
  es::Method method = es::Method::Paper;
};

std::ostream &operator<<(std::ostream &os, const Case &c) {
  return os << c.shape << "@" << c.cellFraction * 100 << "%"
            << (c.method == es::Method::Extended ? " extended" : " paper");
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

/// A shape's marching-cubes mesh (cells of `cellFraction` of its diagonal)
/// sharpened with `opt`: the report, and the distances to the exact shape
/// before and after.
struct SharpenedShape {
  es::SharpenReport report;
  es::DistanceReport before, after;
};

SharpenedShape sharpenShape(const std::string &name, double cellFraction,
                            const es::SharpenOptions &opt) {
  const shapes::Shape &shape = shapes::shapeByName(name);
  es::Mesh reference, input, output;
  shapes::buildReference(shape, reference);
  shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, cellFraction), input);
  vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(output, input);
  vcg::tri::UpdateTopology<es::Mesh>::FaceFace(output);
  const es::SharpenReport report = es::sharpen(output, opt);
  return {report, es::measureDistance(input, reference), es::measureDistance(output, reference)};
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

  es::SharpenOptions opt;
  opt.method = c.method;
  const es::SharpenReport r = es::sharpen(output, opt);
  EXPECT_EQ(topologyProblem(output), "");

  // Original vertices keep their index and bit-identical position; the
  // extended method may move feature-zone vertices (exactly the projected
  // ones), never a vertex of a smooth region (a face the detection paints red).
  ASSERT_GE(output.vert.size(), input.vert.size());
  std::vector<char> inRegion(input.vert.size(), 1);
  if (c.method == es::Method::Extended) {
    es::Mesh detected;
    vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(detected, input);
    es::detectChamfers(detected, opt);
    std::fill(inRegion.begin(), inRegion.end(), 0);
    for (auto &f : detected.face)
      if (f.C() == es::faceLabelColor(es::FaceLabel::Red))
        for (int k = 0; k < 3; ++k) inRegion[vcg::tri::Index(detected, f.V(k))] = 1;
  }
  std::size_t changed = 0;
  for (std::size_t i = 0; i < input.vert.size(); ++i) {
    if (output.vert[i].P() == input.vert[i].P()) continue;
    ++changed;
    ASSERT_FALSE(inRegion[i]) << "smooth-region vertex " << i << " moved";
  }
  EXPECT_EQ(changed, r.extended.projectedVertices);
  // Counts follow the report's arithmetic.
  EXPECT_EQ(r.outputVertices,
            r.inputVertices + r.subdivision.insertedVertices - r.cleanup.collapses);
  EXPECT_EQ(r.outputFaces, r.inputFaces + r.subdivision.addedFaces - r.cleanup.removedFaces);
  EXPECT_EQ(r.cleanup.removedFaces, 2 * r.cleanup.collapses);  // closed input: no border
  EXPECT_EQ(r.cleanup.remaining, 0u);

  const es::DistanceReport before = es::measureDistance(input, reference);
  const es::DistanceReport after = es::measureDistance(output, reference);
  std::printf(
      "%-8s %-14s cell %.1f%%: faces %zu -> %zu, chamfer edges %zu, corners %zu, moved %zu, "
      "fallbacks %zu | max %.4f%% -> %.4f%% (x%.2f), rms %.5f%% -> %.5f%% (x%.2f)\n",
      c.method == es::Method::Extended ? "extended" : "paper", c.shape.c_str(),
      c.cellFraction * 100, r.inputFaces, r.outputFaces, r.filters.chamferEdges,
      r.filters.cornerFaces, r.placement.moved(), r.placement.fallbacks(), before.maxPercent(),
      after.maxPercent(), before.max() / after.max(), before.rmsPercent(), after.rmsPercent(),
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
      return info.param.shape + "_" + std::to_string(int(info.param.cellFraction * 1000)) +
             "permille" + (info.param.method == es::Method::Extended ? "_extended" : "");
    });

// The extended method on the same inputs. Thresholds are about 80% of the
// measured reductions (max / RMS): cube 2% x6.4/x20.8, 1% x19.1/x25.2;
// lblock 2% x3.2/x13.8, 1% x11.7/x16.3; lblock_tilted 2% x1.65/x4.9 (x2.2/x5.3
// before the bend test of placement.h, which at this coarse resolution takes
// the staircase of one flank for curvature: a known cost of fandisk's gain);
// wedge 2% x4.5/x8.6; pyramid 2% x4.6/x9.9; cross_prism 2% x2.2/x3.2;
// cylinder_block 2% x3.5/x5.9.
constexpr es::Method kExt = es::Method::Extended;
INSTANTIATE_TEST_SUITE_P(
    MarchingCubesExtended, SharpenShapes,
    ::testing::Values(Case{"cube", 0.02, 5.0, 16.0, kExt}, Case{"cube", 0.01, 15.0, 20.0, kExt},
                      Case{"lblock", 0.02, 2.5, 11.0, kExt}, Case{"lblock", 0.01, 9.0, 13.0, kExt},
                      Case{"lblock_tilted", 0.02, 1.35, 3.9, kExt},
                      Case{"wedge", 0.02, 3.6, 6.8, kExt}, Case{"pyramid", 0.02, 3.6, 7.9, kExt},
                      Case{"cross_prism", 0.02, 1.75, 2.55, kExt},
                      Case{"cylinder_block", 0.02, 2.8, 4.7, kExt}),
    [](const ::testing::TestParamInfo<Case> &info) {
      return info.param.shape + "_" + std::to_string(int(info.param.cellFraction * 1000)) +
             "permille_extended";
    });

TEST(SharpenShapes, SphereWithoutFeaturesIsEssentiallyUnchanged) {
  const auto [r, before, after] = sharpenShape("sphere", 0.02, es::SharpenOptions::paperMethod());
  std::printf("sphere: chamfer edges %zu, moved %zu | max %.4f%% -> %.4f%%, rms %.5f%% -> %.5f%%\n",
              r.filters.chamferEdges, r.placement.moved(), before.maxPercent(), after.maxPercent(),
              before.rmsPercent(), after.rmsPercent());
  EXPECT_LE(after.max(), before.max() * 1.05);
  EXPECT_LE(after.rms(), before.rms() * 1.05);
}

// The auto method's report names the unit of its `...Spacings` measures (the
// input's median edge length) and the refused bound it judged the mesh by.
TEST(SharpenShapes, AutoReportsItsSampleSpacingAndRefusedBound) {
  const es::SharpenOptions opt;
  for (const char *name : {"cross_prism", "sphere"}) {
    const shapes::Shape &shape = shapes::shapeByName(name);
    const double cell = shapes::cellSizeForDiagonalFraction(shape, 0.01);
    es::Mesh m;
    shapes::marchingCubes(shape, cell, m);
    const double median = es::medianEdgeLength(m);
    vcg::tri::UpdateTopology<es::Mesh>::FaceFace(m);
    const es::SharpenReport r = es::sharpen(m, opt);
    EXPECT_DOUBLE_EQ(r.extended.sampleSpacing, median) << name;
    EXPECT_GT(r.extended.sampleSpacing, 0.3 * cell) << name;  // marching cubes: about a cell
    EXPECT_LT(r.extended.sampleSpacing, 1.5 * cell) << name;
    EXPECT_TRUE(r.evidence.refusedBound == opt.rules.mesh.maxRefusedFraction ||
                r.evidence.refusedBound == opt.rules.mesh.maxRefusedFractionSmooth)
        << name << ": " << r.evidence.refusedBound;
    if (r.evidence.refusedFraction > r.evidence.refusedBound) {
      EXPECT_TRUE(r.evidence.wholeMeshLeft) << name;
    }
  }
}

// A saddle corner (cross_prism: a concave edge meets two convex ones) puts
// chamfer edges between a concave and a convex side. The paper's convexity
// check keeps them at rest (the extended method keeps it); the auto method
// judges them by its own tests, and sharpens the corner.
TEST(SharpenShapes, AutoSharpensSaddleCornersThePaperKeepsAtRest) {
  const shapes::Shape &shape = shapes::shapeByName("cross_prism");
  es::Mesh reference, input;
  shapes::buildReference(shape, reference);
  shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, 0.01), input);
  es::SharpenOptions extended;
  extended.method = es::Method::Extended;
  double maxAfter[2];
  std::size_t mixed[2];
  int i = 0;
  for (const es::SharpenOptions &opt : {extended, es::SharpenOptions{}}) {
    es::Mesh m;
    vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(m, input);
    vcg::tri::UpdateTopology<es::Mesh>::FaceFace(m);
    const es::SharpenReport r = es::sharpen(m, opt);
    mixed[i] = r.placement.count(es::Placement::MixedConvexity);
    maxAfter[i] = es::measureDistance(m, reference).maxPercent();
    std::printf("%s: %zu kept by the convexity check, max %.4f%%\n", i ? "auto" : "extended",
                mixed[i], maxAfter[i]);
    ++i;
  }
  EXPECT_GT(mixed[0], 0u);
  EXPECT_EQ(mixed[1], 0u);
  EXPECT_LT(maxAfter[1], maxAfter[0]);
}

// Where a flat cap cuts a torus, the torus side is a convex curved flank:
// the plane fitted to it next to the rim meets the cap's plane beyond the
// rim, outside the solid. The auto method places the rims' vertices where
// the flanks meet as curved surfaces, so it restores them no worse than
// marching cubes left them (between the planes: max 1.43% against 1.04%).
TEST(SharpenShapes, AutoRestoresACurvedFlanksRimOnItsCurve) {
  const auto [r, before, after] = sharpenShape("torus_cut", 0.02, es::SharpenOptions{});
  std::printf("torus_cut at 2%%: moved %zu | max %.4f%% -> %.4f%%, rms %.5f%% -> %.5f%%\n",
              r.placement.moved(), before.maxPercent(), after.maxPercent(), before.rmsPercent(),
              after.rmsPercent());
  EXPECT_GT(r.placement.moved(), 0u);
  EXPECT_LT(after.max(), before.max());
  EXPECT_LT(after.rms(), before.rms());
}

// The report's projections and displacements count only what the output
// keeps: on a noisy marching-cubes mesh the guards send moves back, and the
// longest projection is then that of the zone vertices still projected.
TEST(SharpenShapes, ReportCountsOnlyTheMovesTheOutputKeeps) {
  const shapes::Shape &shape = shapes::shapeByName("cylinder_block");
  for (const double amplitude : {0.0, 0.1, 0.15, 0.2, 0.5, 1.0}) {
    es::Mesh input;
    shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, 0.02), input);
    vcg::tri::UpdateNormal<es::Mesh>::PerVertexNormalized(input);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double cell = shapes::cellSizeForDiagonalFraction(shape, 0.02);
    for (auto &v : input.vert) v.P() += v.N() * float(u(rng) * amplitude * cell);
    es::Mesh m;
    vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(m, input);
    vcg::tri::UpdateTopology<es::Mesh>::FaceFace(m);
    const es::SharpenReport r = es::sharpen(m, es::SharpenOptions{});
    std::size_t moved = 0;
    double longest = 0;
    for (std::size_t v = 0; v < input.vert.size(); ++v) {
      const double d = (es::positionOf(&m.vert[v]) - es::positionOf(&input.vert[v])).Norm();
      moved += d > 0;
      longest = std::max(longest, d);
    }
    std::printf(
        "noise %.2f cell: %zu zone vertices projected (longest %g), %zu inserted moved "
        "(farthest %g)%s\n",
        amplitude, r.extended.projectedVertices, r.extended.maxProjection, r.placement.moved(),
        r.placement.maxDisplacement, r.evidence.wholeMeshLeft ? ", mesh left whole" : "");
    EXPECT_EQ(r.extended.projectedVertices, moved) << amplitude;
    EXPECT_DOUBLE_EQ(r.extended.maxProjection, longest) << amplitude;
    if (r.placement.moved() == 0) {
      EXPECT_EQ(r.placement.maxDisplacement, 0.0) << amplitude;
    }
  }
}

// The auto method gives a split face at rest its input face back, keeping
// only the inserted vertices a face with a move still needs: an inserted
// vertex left at rest in the output (on the midpoint of an input edge)
// always has a moved vertex within two edges of it.
TEST(SharpenShapes, AutoKeepsAnInsertedVertexAtRestOnlyBesideAMove) {
  using Key = std::array<float, 3>;
  const auto key = [](const vcg::Point3f &p) { return Key{p[0], p[1], p[2]}; };
  std::size_t exercised = 0;
  for (const char *name : {"cylinder_block", "cross_prism", "lblock_tilted", "sphere"}) {
    const shapes::Shape &shape = shapes::shapeByName(name);
    es::Mesh input, output;
    shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, 0.01), input);
    std::set<Key> inputVertices, midpoints;
    for (const auto &v : input.vert) inputVertices.insert(key(v.cP()));
    for (const auto &f : input.face)
      for (int i = 0; i < 3; ++i) {
        const es::Vec3 a = es::positionOf(f.cV(i)), b = es::positionOf(f.cV((i + 1) % 3));
        midpoints.insert(key(vcg::Point3f::Construct((a + b) / 2)));
      }
    vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(output, input);
    vcg::tri::UpdateTopology<es::Mesh>::FaceFace(output);
    const es::SharpenReport r = es::sharpen(output, es::SharpenOptions{});
    // Per output vertex: 0 at an input vertex, 1 an inserted vertex at rest, 2 moved.
    std::vector<int> kind(output.vert.size());
    for (std::size_t v = 0; v < output.vert.size(); ++v) {
      const Key k = key(output.vert[v].cP());
      kind[v] = inputVertices.count(k) ? 0 : midpoints.count(k) ? 1 : 2;
    }
    std::vector<std::set<std::size_t>> neighbours(output.vert.size());
    for (const auto &f : output.face)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (i != j)
            neighbours[vcg::tri::Index(output, f.cV(i))].insert(vcg::tri::Index(output, f.cV(j)));
    std::size_t resting = 0, alone = 0;
    for (std::size_t v = 0; v < output.vert.size(); ++v) {
      if (kind[v] != 1) continue;
      ++resting;
      bool nearMove = false;
      for (std::size_t u : neighbours[v])
        for (std::size_t w : neighbours[u]) nearMove = nearMove || kind[u] == 2 || kind[w] == 2;
      alone += !nearMove;
    }
    std::printf("%s: %zu weak features, %zu faces given back, %zu inserted vertices at rest kept\n",
                name, r.evidence.weakFeatures, r.evidence.facesGivenBack, resting);
    EXPECT_EQ(alone, 0u) << name;
    exercised += r.evidence.weakFeatures > 0 && r.evidence.facesGivenBack > 0 && resting > 0;
  }
  EXPECT_GT(exercised, 0u);  // some shape had weak features, given-back faces and kept vertices
}

// Sharpening does not depend on the model's units: a model in metres gives
// the output it gives in millimetres, scaled. Scaling by a power of two is
// exact in floating point, so the outputs must agree to the bit. (The
// intersection guard's test of faces sharing a vertex took every segment of
// a model a hundredth of a unit in size for one parallel to the face.)
TEST(SharpenShapes, SameOutputInAnyUnit) {
  for (const char *name : {"lblock_tilted", "wedge", "cross_prism"})
    for (const double fraction : {0.01, 0.02})
      for (const es::Method method : {es::Method::Auto, es::Method::Paper, es::Method::Extended}) {
        const shapes::Shape &shape = shapes::shapeByName(name);
        es::Mesh input;
        shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, fraction), input);
        es::SharpenOptions opt;
        opt.method = method;
        std::vector<es::Mesh> outputs(3);
        const double scales[3] = {1.0, std::ldexp(1.0, -14), std::ldexp(1.0, 10)};
        for (int s = 0; s < 3; ++s) {
          vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(outputs[s], input);
          for (auto &v : outputs[s].vert) v.P() *= float(scales[s]);
          vcg::tri::UpdateTopology<es::Mesh>::FaceFace(outputs[s]);
          es::sharpen(outputs[s], opt);
        }
        const std::string label = std::string(name) + " at " + std::to_string(fraction) +
                                  (method == es::Method::Auto    ? " auto"
                                   : method == es::Method::Paper ? " paper"
                                                                 : " extended");
        for (int s = 1; s < 3; ++s) {
          ASSERT_EQ(outputs[s].vert.size(), outputs[0].vert.size()) << label << ", scale " << s;
          ASSERT_EQ(outputs[s].face.size(), outputs[0].face.size()) << label << ", scale " << s;
          std::size_t differing = 0;
          for (std::size_t v = 0; v < outputs[0].vert.size(); ++v)
            differing += !(es::positionOf(&outputs[s].vert[v]) / scales[s] ==
                           es::positionOf(&outputs[0].vert[v]));
          for (std::size_t f = 0; f < outputs[0].face.size(); ++f)
            for (int k = 0; k < 3; ++k)
              differing += vcg::tri::Index(outputs[s], outputs[s].face[f].cV(k)) !=
                           vcg::tri::Index(outputs[0], outputs[0].face[f].cV(k));
          EXPECT_EQ(differing, 0u) << label << ", scale " << scales[s];
        }
      }
}
