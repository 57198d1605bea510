// Invariants of sharpen() over many generated inputs (issue 6): every test
// shape x 3 marching-cubes resolutions x 3 smooth-edge multipliers; for each,
// the result keeps the invariants of invariants.h, is deterministic, commutes
// with a random rigid motion and with a random similarity (rotation +
// translation + uniform scale, scales 1e-6 .. 1e6), changes little when
// sharpened again, and adds no self-intersection (coarsest resolution).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "edge_sharpener/edge_sharpener.h"
#include "mesh_distance.h"
#include "edge_sharpener/util/mesh_types.h"
#include "reliability/invariants.h"
#include "test_meshes/shapes.h"

namespace es = edge_sharpener;
namespace shapes = edge_sharpener::test_meshes;
using es::Mesh;
using es_reliability::P3;

namespace {

constexpr double kFractions[] = {0.03, 0.02, 0.015};
constexpr double kMultipliers[] = {1.5, 2.0, 3.0};
constexpr double kScales[] = {1e-6, 1e6, 0.37, 2.5};
/// Largest allowed deviation between sharpen(T(M)) and T(sharpen(M)), as a
/// fraction of the bounding-box diagonal (float coordinates: ~1e-7 relative
/// rounding, amplified by plane intersections).
constexpr double kMotionTolerance = 1e-3;
/// Bound on the two-sided distance between sharpen(M) and sharpen(sharpen(M)),
/// in % of the bounding-box diagonal (measured maximum in docs/reliability.md).
// Measured: a second pass moves the surface by at most 2.05% of the diagonal
// (it finds the one-triangle chamfers the first pass's split faces form).
constexpr double kResharpenBoundPercent = 2.5;

struct Case {
  std::string shape;
  double fraction;
  double multiplier;
  int index;
};

std::ostream &operator<<(std::ostream &os, const Case &c) {
  return os << c.shape << "@" << c.fraction * 100 << "%x" << c.multiplier;
}

/// The shapes this suite was sized on (9 cases each, also run under AddressSanitizer). The
/// curved-edge shapes allShapes() gained for issue 60 (cylinder_cut, cone_cut, torus_cut,
/// two_cylinders) are left out, so that the suite's length stays what it was.
const char *const kShapes[] = {"cube",           "lblock",           "wedge",  "pyramid",
                               "cross_prism",    "cylinder_block",   "sphere", "lblock_tilted",
                               "bevelled_block", "finished_hexprism"};

std::vector<Case> allCases() {
  std::vector<Case> cases;
  for (const char *s : kShapes)
    for (double f : kFractions)
      for (double m : kMultipliers) cases.push_back({s, f, m, int(cases.size())});
  return cases;
}

/// p -> scale * R p + t, computed in double.
struct Similarity {
  double r[3][3];
  P3 t;
  double scale;
  P3 apply(const P3 &p) const {
    P3 q;
    for (int i = 0; i < 3; ++i) q[i] = scale * (r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2]);
    return q + t;
  }
};

Similarity randomSimilarity(std::mt19937 &rng, double scale, double diagonal) {
  std::normal_distribution<double> g;
  // Uniform random rotation from a random unit quaternion.
  double q[4];
  double n = 0;
  for (double &x : q) x = g(rng), n += x * x;
  n = std::sqrt(n);
  for (double &x : q) x /= n;
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  Similarity s{{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}},
               P3(0, 0, 0),
               scale};
  std::uniform_real_distribution<double> u(-3, 3);
  s.t = P3(u(rng), u(rng), u(rng)) * (diagonal * scale);
  return s;
}

void transform(Mesh &m, const Similarity &s) {
  for (auto &v : m.vert) v.P().Import(s.apply(es_reliability::pos(v)));
}

void copy(Mesh &dst, Mesh &src) {
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(dst, src);
  vcg::tri::UpdateTopology<Mesh>::FaceFace(dst);
}

/// Shape `name` sampled into `out` by the project's marching cubes, cells
/// `fraction` of its diagonal.
const shapes::Shape &marchingCubesOf(const std::string &name, double fraction, Mesh &out) {
  const shapes::Shape &shape = shapes::shapeByName(name);
  shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, fraction), out);
  return shape;
}

/// Max distance between corresponding vertices of two meshes with the same
/// connectivity; a negative value when the connectivity differs.
/// Vertices the self-intersection guard moved back are skipped when
/// `skipGuarded` (colorize paints them; their retreat is a threshold decision).
double maxDeviation(const Mesh &a, const Mesh &b, bool skipGuarded = false) {
  const vcg::Color4b guarded =
      es::placementColor(es::Placement::IntersectionRevert, es::VertexLabel::Gray);
  if (a.vert.size() != b.vert.size() || a.face.size() != b.face.size()) return -1;
  for (std::size_t i = 0; i < a.face.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (vcg::tri::Index(a, a.face[i].cV(k)) != vcg::tri::Index(b, b.face[i].cV(k))) return -1;
  double worst = 0;
  for (std::size_t i = 0; i < a.vert.size(); ++i) {
    if (skipGuarded && (a.vert[i].cC() == guarded || b.vert[i].cC() == guarded)) continue;
    worst =
        std::max(worst, (es_reliability::pos(a.vert[i]) - es_reliability::pos(b.vert[i])).Norm());
  }
  return worst;
}

class SharpenInvariants : public ::testing::TestWithParam<Case> {};

}  // namespace

TEST_P(SharpenInvariants, HoldOnShapeUnderMotionScaleAndResharpening) {
  const Case c = GetParam();
  Mesh input;
  marchingCubesOf(c.shape, c.fraction, input);
  const double diagonal = es_reliability::bboxDiagonal(input);
  es::SharpenOptions opt = es::SharpenOptions::paperMethod();
  opt.smoothMultiplier = c.multiplier;
  opt.colorize = true;  // marks the vertices the self-intersection guard moved back

  // Invariants of the result.
  Mesh base;
  copy(base, input);
  const es::SharpenReport r = es::sharpen(base, opt);
  ASSERT_EQ(es_reliability::sharpenProblem(input, base, r, opt.degenerateAngleRad), "");
  EXPECT_TRUE(es_reliability::topologyOf(base).oriented);
  EXPECT_EQ(es_reliability::topologyOf(base).boundaryEdges, 0);

  // Deterministic: a second run gives bit-identical output and report.
  Mesh again;
  copy(again, input);
  const es::SharpenReport r2 = es::sharpen(again, opt);
  EXPECT_TRUE(es_reliability::identical(base, again));
  EXPECT_EQ(formatReport(r), formatReport(r2));

  // Rigid motion, then similarity with a scale far from 1.
  std::mt19937 rng(1000 + c.index);
  double deviation[2] = {0, 0};
  bool flips[2] = {false, false};
  for (int k = 0; k < 2; ++k) {
    const double scale = k == 0 ? 1.0 : kScales[c.index % 4];
    const Similarity s = randomSimilarity(rng, scale, diagonal);
    Mesh moved, expected;
    copy(moved, input);
    transform(moved, s);
    const es::SharpenReport rm = es::sharpen(moved, opt);
    copy(expected, base);
    transform(expected, s);
    // Smooth/chamfer decisions and the self-intersection guard's retreats
    // are thresholds on float data: rounding the moved coordinates to float
    // can flip some (docs/reliability.md: 11 of 72 cases flip a
    // classification, none when the coordinates are double). Then the
    // results must still agree to within one marching-cubes cell.
    // The guard's retreats are such decisions too: the vertices it moved
    // back are compared by the distance bound only, every other vertex
    // strictly.
    deviation[k] = maxDeviation(moved, expected, true);
    const bool decisionsFlipped = deviation[k] < 0 ||
                                  rm.placement.byOutcome != r.placement.byOutcome ||
                                  rm.intersections.rounds != r.intersections.rounds;
    flips[k] = decisionsFlipped;
    if (!decisionsFlipped) {
      deviation[k] /= diagonal * scale;
      EXPECT_LE(deviation[k], kMotionTolerance) << "scale " << scale;
    }
    if (decisionsFlipped || r.intersections.rounds > 0) {
      es::DistanceOptions dopt;
      dopt.faceSamples = 20000;
      const double distance = es::measureDistance(moved, expected, dopt).max() / (diagonal * scale);
      EXPECT_LE(distance, c.fraction) << "decisions flipped, scale " << scale;
      if (decisionsFlipped) deviation[k] = distance;
    }
  }

  // Sharpening again changes little.
  Mesh twice;
  copy(twice, base);
  const es::SharpenReport rr = es::sharpen(twice, opt);
  EXPECT_EQ(es_reliability::sharpenProblem(base, twice, rr, opt.degenerateAngleRad), "");
  es::DistanceOptions dopt;
  dopt.faceSamples = 20000;
  const double resharpen = es::measureDistance(twice, base, dopt).maxPercent();
  EXPECT_LE(resharpen, kResharpenBoundPercent);

  // No new self-intersections (small meshes: the coarsest resolution).
  std::size_t intersectingIn = 0, intersectingOut = 0;
  if (c.fraction == kFractions[0]) {
    intersectingIn = es_reliability::selfIntersectingFaces(input);
    intersectingOut = es_reliability::selfIntersectingFaces(base);
    // Before the intersection guard (intersection_guard.h) the tilted
    // L-block, the pyramid and the sphere got up to 15 self-intersecting
    // faces here; now none may appear.
    EXPECT_LE(intersectingOut, intersectingIn);
  }
  std::printf(
      "RELIABILITY-INVARIANTS %s %.1f%% x%.1f faces %zu->%zu moved %zu inherited %zu | "
      "motion dev %.2e%s, similarity(x%g) dev %.2e%s | resharpen moved %zu, dist %.4f%% | "
      "self-intersecting %zu->%zu (guard: %zu pairs, %zu reverted)\n",
      c.shape.c_str(), c.fraction * 100, c.multiplier, r.inputFaces, r.outputFaces,
      r.placement.moved(), r.cleanup.inherited, deviation[0], flips[0] ? " (flipped)" : "",
      kScales[c.index % 4], deviation[1], flips[1] ? " (flipped)" : "", rr.placement.moved(),
      resharpen, intersectingIn, intersectingOut, r.intersections.intersectingPairs,
      r.intersections.reverted);
}

INSTANTIATE_TEST_SUITE_P(Shapes, SharpenInvariants, ::testing::ValuesIn(allCases()),
                         [](const ::testing::TestParamInfo<Case> &info) {
                           return info.param.shape + "_" +
                                  std::to_string(int(info.param.fraction * 1000)) + "permille_x" +
                                  std::to_string(int(info.param.multiplier * 10));
                         });

// Two copies of one chamfered mesh side by side are sharpened exactly like
// one copy: components do not influence each other (same mean angle).
TEST(SharpenInvariantsComponents, TwoCopiesSharpenLikeOne) {
  Mesh one, two, single;
  marchingCubesOf("lblock", 0.02, one);
  // Coordinates on a 2^-20 grid, so that the shift by 4 below is exact in
  // float (it is not for arbitrary coordinates near 0).
  for (auto &v : one.vert)
    for (int c = 0; c < 3; ++c) v.P()[c] = std::ldexp(std::round(std::ldexp(v.P()[c], 20)), -20);
  copy(two, one);
  Mesh shifted;
  copy(shifted, one);
  // Shift by a power of two larger than the shape: exact on the 2^-20 grid.
  for (auto &v : shifted.vert) v.P()[0] += 4.0f;
  vcg::tri::Append<Mesh, Mesh>::Mesh(two, shifted);
  vcg::tri::UpdateTopology<Mesh>::FaceFace(two);
  copy(single, one);
  const es::SharpenReport r1 = es::sharpen(single, es::SharpenOptions::paperMethod());
  const es::SharpenReport r2 = es::sharpen(two, es::SharpenOptions::paperMethod());
  EXPECT_EQ(r2.filters.chamferEdges, 2 * r1.filters.chamferEdges);
  EXPECT_EQ(r2.outputFaces, 2 * r1.outputFaces);
  // The self-intersection guard's retreats decide touching contacts, which
  // the shifted copy's rounding can make or break: moved + retreated match.
  const auto placed = [](const es::SharpenReport &r) {
    return r.placement.moved() + r.placement.count(es::Placement::IntersectionRevert);
  };
  EXPECT_EQ(placed(r2), 2 * placed(r1));
  // Same geometry per component, as multisets of face centroids.
  auto centroids = [](const Mesh &m, bool left) {
    std::vector<std::array<double, 3>> out;
    for (const auto &f : m.face) {
      const P3 c = (es_reliability::pos(*f.cV(0)) + es_reliability::pos(*f.cV(1)) +
                    es_reliability::pos(*f.cV(2))) /
                   3.0;
      if ((c[0] < 2.5) != left) continue;
      out.push_back({std::round(c[0] * 1e5), std::round(c[1] * 1e5), std::round(c[2] * 1e5)});
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  auto left = centroids(two, true), right = centroids(two, false), ref = centroids(single, true);
  for (auto &c : right) c[0] -= 4e5;
  EXPECT_EQ(left, ref);
  EXPECT_EQ(right.size(), ref.size());
}

// A chamfered mesh cut open: processed, boundary edges never smooth, never split,
// and the boundary vertices stay where they were.
TEST(SharpenInvariantsComponents, OpenMeshKeepsItsBoundary) {
  Mesh closed;
  const shapes::Shape &shape = marchingCubesOf("cube", 0.02, closed);
  // Remove every face whose centroid is above a plane slanted across the top corners.
  for (auto &f : closed.face) {
    const P3 c = (es_reliability::pos(*f.cV(0)) + es_reliability::pos(*f.cV(1)) +
                  es_reliability::pos(*f.cV(2))) /
                 3.0;
    if (c[2] + 0.3 * c[0] > shape.bbox.max[2] - 0.05)
      vcg::tri::Allocator<Mesh>::DeleteFace(closed, f);
  }
  vcg::tri::Clean<Mesh>::RemoveUnreferencedVertex(closed);
  vcg::tri::Allocator<Mesh>::CompactEveryVector(closed);
  Mesh input, output;
  copy(input, closed);
  copy(output, closed);
  const es_reliability::Topology tin = es_reliability::topologyOf(input);
  ASSERT_GT(tin.boundaryEdges, 0);
  auto boundaryEdges = [](Mesh &m) {
    vcg::tri::UpdateTopology<Mesh>::FaceFace(m);
    std::vector<std::pair<std::size_t, std::size_t>> edges;
    for (auto &f : m.face)
      for (int k = 0; k < 3; ++k)
        if (vcg::face::IsBorder(f, k)) {
          std::size_t a = vcg::tri::Index(m, f.V0(k)), b = vcg::tri::Index(m, f.V1(k));
          edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    std::sort(edges.begin(), edges.end());
    return edges;
  };
  const auto before = boundaryEdges(input);
  const es::SharpenReport r = es::sharpen(output, es::SharpenOptions::paperMethod());
  EXPECT_EQ(
      es_reliability::sharpenProblem(input, output, r, es::SharpenOptions{}.degenerateAngleRad),
      "");
  EXPECT_EQ(r.smooth.boundaryEdges, std::size_t(tin.boundaryEdges));
  EXPECT_GT(r.placement.moved(), 0u);
  // A boundary edge may be a chamfer edge (an open scan cut across a
  // chamfer): it is then split in two at a new vertex. Every other boundary
  // edge is kept, and the rim keeps its vertices.
  const auto after = boundaryEdges(output);
  std::size_t kept = 0;
  for (const auto &e : before) kept += std::binary_search(after.begin(), after.end(), e);
  const std::size_t split = before.size() - kept;
  EXPECT_EQ(after.size(), before.size() + split);
}
