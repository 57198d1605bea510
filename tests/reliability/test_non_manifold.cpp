// Meshes with non-manifold spots (issue 59): the faces at a non-manifold
// vertex or edge come out exactly as they came, the features away from them
// are sharpened exactly as on the clean mesh, and every invariant holds.
#include <gtest/gtest.h>
#include <vcg/complex/complex.h>
// (append.h is included by complex.h)

#include <limits>
#include <set>
#include <string>
#include <tuple>

#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/util/mesh_types.h"
#include "reliability/invariants.h"
#include "test_meshes/non_manifold_spots.h"
#include "test_meshes/shapes.h"

namespace es = edge_sharpener;
namespace shapes = edge_sharpener::test_meshes;
using shapes::SpotKind;
using shapes::SpotPlace;

namespace {

/// The L-block by marching cubes at 2% cells (as test_meshes/generated/lblock_mc2.ply).
const es::Mesh &cleanLBlock() {
  static es::Mesh *mesh = [] {
    auto *m = new es::Mesh;
    const shapes::Shape &shape = shapes::shapeByName("lblock");
    shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, 0.02), *m);
    return m;
  }();
  return *mesh;
}

void copy(es::Mesh &to, const es::Mesh &from) {
  vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(to, const_cast<es::Mesh &>(from));
}

es::SharpenReport sharpenCopy(const es::Mesh &input, es::Mesh &out, es::Method method) {
  copy(out, input);
  es::SharpenOptions opt;
  opt.method = method;
  return es::sharpen(out, opt);
}

std::set<std::tuple<float, float, float>> insertedPositions(const es::Mesh &m, std::size_t first) {
  std::set<std::tuple<float, float, float>> out;
  for (std::size_t v = first; v < m.vert.size(); ++v)
    out.insert({m.vert[v].cP()[0], m.vert[v].cP()[1], m.vert[v].cP()[2]});
  return out;
}

const char *name(SpotKind k) {
  return k == SpotKind::Vertex ? "vertex" : "edge";
}
const char *name(SpotPlace p) {
  return p == SpotPlace::OnChamfer     ? "on_chamfer"
         : p == SpotPlace::NearChamfer ? "near_chamfer"
                                       : "far_from_chamfers";
}

class NonManifoldSpot : public ::testing::TestWithParam<std::tuple<SpotKind, SpotPlace>> {};

// Every method: the spot's faces as they came, the invariants (invariants.h
// checks the faces at spots by vertex indices, original positions bit for bit).
TEST_P(NonManifoldSpot, SpotFacesComeOutAsTheyCame) {
  const auto [kind, place] = GetParam();
  es::Mesh input;
  copy(input, cleanLBlock());
  shapes::addSpot(input, kind, shapes::spotVertex(input, place));
  for (const es::Method method : {es::Method::Paper, es::Method::Extended, es::Method::Auto}) {
    SCOPED_TRACE(int(method));
    es::Mesh out, in;
    copy(in, input);
    const es::SharpenReport r = sharpenCopy(input, out, method);
    EXPECT_EQ(r.nonManifold.edges, kind == SpotKind::Edge ? 1u : 0u);
    EXPECT_EQ(r.nonManifold.vertices, kind == SpotKind::Edge ? 2u : 1u);
    EXPECT_GT(r.nonManifold.heldFaces, 0u);
    EXPECT_GE(r.nonManifold.firstHeldFace, 0u);
    EXPECT_EQ(es_reliability::sharpenProblem(in, out, r, es::SharpenOptions().degenerateAngleRad),
              "");
    EXPECT_GT(r.outputVertices, r.inputVertices) << "nothing was sharpened";
  }
}

// The default method: a feature that reaches the spot is left whole; every
// other one is sharpened as on the clean mesh, vertex positions identical.
TEST_P(NonManifoldSpot, FeaturesAwayAreSharpenedAsOnTheCleanMesh) {
  const auto [kind, place] = GetParam();
  es::Mesh clean, input, cleanOut, out;
  copy(clean, cleanLBlock());
  copy(input, clean);
  shapes::addSpot(input, kind, shapes::spotVertex(input, place));
  const es::SharpenReport rc = sharpenCopy(clean, cleanOut, es::Method::Auto);
  const es::SharpenReport r = sharpenCopy(input, out, es::Method::Auto);
  const std::size_t atSpot = r.evidence.count(es::Verdict::AtNonManifoldSpot);
  const std::size_t restored = r.evidence.count(es::Verdict::Restored);
  const std::size_t cleanRestored = rc.evidence.count(es::Verdict::Restored);
  for (std::size_t v = 0; v < clean.vert.size(); ++v)
    ASSERT_EQ(out.vert[v].cP(), cleanOut.vert[v].cP()) << "vertex " << v;
  const auto inserted = insertedPositions(out, input.vert.size());
  const auto cleanInserted = insertedPositions(cleanOut, clean.vert.size());
  if (place == SpotPlace::OnChamfer) {
    EXPECT_GE(atSpot, 1u);
  }
  if (place == SpotPlace::FarFromChamfers) {
    EXPECT_EQ(atSpot, 0u);
  }
  if (atSpot == 0) {
    EXPECT_EQ(restored, cleanRestored);
    EXPECT_EQ(inserted, cleanInserted);
    return;
  }
  // The spot's held faces reach these features (a corner whose triangle is
  // held is no feature at all; the corners of a feature left are left too);
  // every other feature is restored as on the clean mesh, each of its new
  // vertices where the clean run put it. A new vertex of a feature left rests
  // on the input's surface; the end of a restored edge that runs into a
  // corner left may end a little differently (the guards see the corner
  // unsharpened), within two edges of a vertex left at rest.
  EXPECT_LE(restored + atSpot, cleanRestored);
  EXPECT_LT(inserted.size(), cleanInserted.size());
  const double onSurface = 1e-6 * es_reliability::bboxDiagonal(input);
  const double edge = vcg::Distance(input.face[0].cV(0)->cP(), input.face[0].cV(1)->cP());
  std::vector<es_reliability::P3> atRest, elsewhere;
  for (const auto &p : inserted) {
    if (cleanInserted.count(p)) continue;
    const es_reliability::P3 q(std::get<0>(p), std::get<1>(p), std::get<2>(p));
    (es_reliability::distanceToSurface(input, q) < onSurface ? atRest : elsewhere).push_back(q);
  }
  EXPECT_GT(atRest.size(), 0u);
  for (const auto &q : elsewhere) {
    double nearest = std::numeric_limits<double>::max();
    for (const auto &r : atRest) nearest = std::min(nearest, (q - r).Norm());
    EXPECT_LT(nearest, 2 * edge) << "a new vertex off the input, not where the clean run put it, "
                                 << nearest / edge << " edges from a feature left";
  }
  EXPECT_LE(elsewhere.size(), 2u);
}

INSTANTIATE_TEST_SUITE_P(Spots, NonManifoldSpot,
                         ::testing::Combine(::testing::Values(SpotKind::Vertex, SpotKind::Edge),
                                            ::testing::Values(SpotPlace::OnChamfer,
                                                              SpotPlace::NearChamfer,
                                                              SpotPlace::FarFromChamfers)),
                         [](const auto &info) {
                           return std::string(name(std::get<0>(info.param))) + "_" +
                                  name(std::get<1>(info.param));
                         });

// Duplicated faces and a lone fin are spots too: processed, left as they came.
TEST(NonManifoldSpots, TwoSpotsInOneMeshAreEachHeld) {
  es::Mesh input;
  copy(input, cleanLBlock());
  const std::size_t near = shapes::spotVertex(input, SpotPlace::NearChamfer);
  const std::size_t far = shapes::spotVertex(input, SpotPlace::FarFromChamfers);
  shapes::addSpot(input, SpotKind::Vertex, near);
  shapes::addSpot(input, SpotKind::Edge, far);
  es::Mesh in, out;
  copy(in, input);
  const es::SharpenReport r = sharpenCopy(input, out, es::Method::Auto);
  EXPECT_EQ(r.nonManifold.edges, 1u);
  EXPECT_EQ(r.nonManifold.vertices, 3u);
  EXPECT_EQ(es_reliability::sharpenProblem(in, out, r, es::SharpenOptions().degenerateAngleRad),
            "");
}

}  // namespace

namespace {

// A mesh oriented inward as a whole (every face flipped) is sharpened to the same
// surface, and keeps its orientation: the placement reads planes, not sides.
TEST(MeshesPeopleHave, InwardOrientedMeshIsSharpenedToTheSameSurface) {
  es::Mesh outward, inward;
  copy(outward, cleanLBlock());
  copy(inward, cleanLBlock());
  for (auto &f : inward.face) std::swap(f.V(1), f.V(2));
  for (const es::Method method : {es::Method::Paper, es::Method::Extended, es::Method::Auto}) {
    SCOPED_TRACE(int(method));
    es::Mesh a, b;
    sharpenCopy(outward, a, method);
    sharpenCopy(inward, b, method);
    ASSERT_EQ(a.vert.size(), b.vert.size());
    const std::size_t n = outward.vert.size();
    for (std::size_t v = 0; v < n; ++v) EXPECT_EQ(a.vert[v].cP(), b.vert[v].cP()) << v;
    // The new vertices come in another order (each face's edges are walked the other way).
    EXPECT_EQ(insertedPositions(a, n), insertedPositions(b, n));
    EXPECT_GT(shapes::signedVolume(a), 0);
    EXPECT_LT(shapes::signedVolume(b), 0);
  }
}

}  // namespace

namespace {

// Two parts sampled at spacings ten times apart (the L-block, and the L-block ten
// times larger beside it, its samples ten times apart too): each is sharpened as
// it is alone, not at a spacing between the two.
TEST(MeshesPeopleHave, PartsAtDifferentSpacingsAreEachSharpenedAtTheirOwn) {
  es::Mesh small, big, both;
  copy(small, cleanLBlock());
  copy(big, cleanLBlock());
  for (auto &v : big.vert) v.P() = v.P() * 10 + vcg::Point3f(30, 0, 0);
  copy(both, small);
  vcg::tri::Append<es::Mesh, es::Mesh>::Mesh(both, big);
  es::Mesh smallOut, bigOut, bothOut, bothIn;
  const es::SharpenReport rs = sharpenCopy(small, smallOut, es::Method::Auto);
  const es::SharpenReport rb = sharpenCopy(big, bigOut, es::Method::Auto);
  copy(bothIn, both);
  const es::SharpenReport r = sharpenCopy(both, bothOut, es::Method::Auto);
  EXPECT_EQ(r.parts, 2u);
  EXPECT_EQ(r.partsRescaled, 1u);
  EXPECT_EQ(r.evidence.count(es::Verdict::Restored),
            rs.evidence.count(es::Verdict::Restored) + rb.evidence.count(es::Verdict::Restored));
  EXPECT_EQ(
      es_reliability::sharpenProblem(bothIn, bothOut, r, es::SharpenOptions().degenerateAngleRad),
      "");
  // Every new vertex where the run of its part alone put it (within float rounding of
  // the scaling there and back).
  const auto smallNew = insertedPositions(smallOut, small.vert.size());
  const auto bigNew = insertedPositions(bigOut, big.vert.size());
  ASSERT_EQ(bothOut.vert.size() - both.vert.size(), smallNew.size() + bigNew.size());
  const double tolerance = 1e-5 * es_reliability::bboxDiagonal(big);
  for (std::size_t v = both.vert.size(); v < bothOut.vert.size(); ++v) {
    const es_reliability::P3 p = es_reliability::pos(bothOut.vert[v]);
    double nearest = std::numeric_limits<double>::max();
    for (const auto *set : {&smallNew, &bigNew})
      for (const auto &q : *set)
        nearest = std::min(
            nearest,
            (p - es_reliability::P3(std::get<0>(q), std::get<1>(q), std::get<2>(q))).Norm());
    EXPECT_LT(nearest, tolerance) << "new vertex " << v;
  }
}

}  // namespace

namespace {

// Detect selects what the report counts: the paper's, the chamfer and corner faces left
// after the faces at the spots are held; the default's, the faces Sharpen changes, never
// one held at a spot (MeshLab's detect test reads the count from the log).
TEST(NonManifoldSpots, DetectSelectsWhatTheReportCounts) {
  es::Mesh input;
  copy(input, cleanLBlock());
  const std::size_t on = shapes::spotVertex(input, SpotPlace::OnChamfer);
  shapes::addSpot(input, SpotKind::Edge, on);
  for (const es::Method method : {es::Method::Paper, es::Method::Auto}) {
    SCOPED_TRACE(int(method));
    es::Mesh m;
    copy(m, input);
    es::SharpenOptions opt;
    opt.method = method;
    const es::SharpenReport r = es::detectChamfers(m, opt);
    std::size_t selected = 0;
    for (const auto &f : m.face) selected += f.IsS();
    EXPECT_GT(r.nonManifold.heldFaces, 0u);
    EXPECT_EQ(selected, r.detectedFaces);
    if (method == es::Method::Paper) {
      EXPECT_EQ(selected, r.filters.chamferFaces + r.filters.cornerFaces);
    } else {  // the faces Sharpen changes: never one held at the spot
      EXPECT_GT(selected, 0u);
      EXPECT_FALSE(m.face[r.nonManifold.firstHeldFace].IsS());
    }
  }
}

}  // namespace
