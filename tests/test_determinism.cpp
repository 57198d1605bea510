// The output of the core does not depend on the OpenMP thread count, and the
// fast face-face adjacency (fast_topology.h, and its local update after the
// subdivision) is the one vcglib's UpdateTopology::FaceFace builds.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/extended/plane_patches.h"
#include "edge_sharpener/util/fast_topology.h"
#include "edge_sharpener/util/mesh_types.h"
#include "hand_built_meshes.h"
#include "test_meshes/shapes.h"

namespace es = edge_sharpener;
namespace shapes = edge_sharpener::test_meshes;

namespace {

/// Restores the thread count on scope exit.
class ThreadCount {
 public:
  explicit ThreadCount(int n) {
#ifdef _OPENMP
    saved_ = omp_get_max_threads();
    omp_set_num_threads(n);
#else
    (void)n;
#endif
  }
  ~ThreadCount() {
#ifdef _OPENMP
    omp_set_num_threads(saved_);
#endif
  }

 private:
  int saved_ = 1;
};

/// A marching-cubes mesh of `shape` with about `faces` faces (the face count
/// grows as 1/cell^2; calibrated on a coarse grid). Large enough meshes run
/// the parallel loops on several threads (fast_topology.h: kParallelMin).
const es::Mesh &inputMesh(const std::string &shape, double faces) {
  static std::map<std::string, es::Mesh> cache;
  const std::string key = shape + "@" + std::to_string(faces);
  auto it = cache.find(key);
  if (it == cache.end()) {
    it = cache.emplace(std::piecewise_construct, std::forward_as_tuple(key), std::tuple<>()).first;
    const shapes::Shape &s = shapes::shapeByName(shape);
    const double h0 = shapes::cellSizeForDiagonalFraction(s, 0.02);
    es::Mesh coarse;
    shapes::marchingCubes(s, h0, coarse);
    shapes::marchingCubes(s, h0 * std::sqrt(coarse.fn / faces), it->second);
  }
  return it->second;
}

void copyMesh(es::Mesh &dst, const es::Mesh &src) {
  vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(dst, const_cast<es::Mesh &>(src));
}

/// Everything the output consists of, bit for bit.
struct Snapshot {
  std::vector<float> coords, faceNormals, vertexNormals;
  std::vector<std::size_t> faces;
  std::vector<unsigned> colors, flags;
  bool operator==(const Snapshot &o) const {
    return coords == o.coords && faceNormals == o.faceNormals && vertexNormals == o.vertexNormals &&
           faces == o.faces && colors == o.colors && flags == o.flags;
  }
};

Snapshot snapshot(es::Mesh &m) {
  Snapshot s;
  for (auto &v : m.vert)
    for (int k = 0; k < 3; ++k) {
      s.coords.push_back(v.P()[k]);
      s.vertexNormals.push_back(v.N()[k]);
    }
  for (auto &v : m.vert) s.colors.push_back(*reinterpret_cast<const unsigned *>(&v.C()));
  for (auto &f : m.face) {
    for (int k = 0; k < 3; ++k) {
      s.faces.push_back(vcg::tri::Index(m, f.V(k)));
      s.faceNormals.push_back(f.N()[k]);
    }
    s.colors.push_back(*reinterpret_cast<const unsigned *>(&f.C()));
    s.flags.push_back(f.Flags());
  }
  return s;
}

struct Outcome {
  Snapshot mesh;
  es::SharpenReport report;
};

Outcome runWithThreads(const es::Mesh &input, int threads, const es::SharpenOptions &opt,
                       bool detectOnly) {
  ThreadCount scope(threads);
  Outcome r;
  es::Mesh m;
  copyMesh(m, input);
  r.report = detectOnly ? es::detectChamfers(m, opt) : es::sharpen(m, opt);
  r.mesh = snapshot(m);
  return r;
}

/// The FF adjacency as (face index, edge index) per face edge.
std::vector<std::size_t> adjacency(es::Mesh &m) {
  std::vector<std::size_t> a;
  for (auto &f : m.face) {
    if (f.IsD()) continue;
    for (int i = 0; i < 3; ++i) {
      a.push_back(vcg::tri::Index(m, f.FFp(i)));
      a.push_back(std::size_t(f.FFi(i)));
    }
  }
  return a;
}

struct Case {
  std::string shape;
  double faces;
};

class DeterminismTest : public ::testing::TestWithParam<Case> {};

TEST_P(DeterminismTest, SharpenIsIdenticalForAnyThreadCount) {
  const es::Mesh &input = inputMesh(GetParam().shape, GetParam().faces);
  ASSERT_GT(input.fn, GetParam().faces / 2);
  for (const es::Method method : {es::Method::Paper, es::Method::Extended, es::Method::Auto}) {
    es::SharpenOptions opt;
    opt.method = method;
    opt.colorize = true;
    const Outcome one = runWithThreads(input, 1, opt, false);
    ASSERT_GT(one.report.subdivision.insertedVertices, 0u) << "nothing was sharpened";
    for (const int threads : {2, 3, 8}) {
      const Outcome other = runWithThreads(input, threads, opt, false);
      EXPECT_TRUE(one.mesh == other.mesh) << threads << " threads, method " << int(method);
      EXPECT_EQ(one.report.smooth.meanAngleRad, other.report.smooth.meanAngleRad);
      EXPECT_EQ(one.report.smooth.smoothEdges, other.report.smooth.smoothEdges);
      EXPECT_EQ(one.report.outputVertices, other.report.outputVertices);
      EXPECT_EQ(one.report.outputFaces, other.report.outputFaces);
      EXPECT_EQ(one.report.placement.maxDisplacement, other.report.placement.maxDisplacement);
      EXPECT_EQ(one.report.intersections.intersectingPairs,
                other.report.intersections.intersectingPairs);
      EXPECT_EQ(one.report.intersections.reverted, other.report.intersections.reverted);
    }
  }
}

TEST_P(DeterminismTest, DetectChamfersIsIdenticalForAnyThreadCount) {
  const es::Mesh &input = inputMesh(GetParam().shape, GetParam().faces);
  const Outcome one = runWithThreads(input, 1, {}, true);
  for (const int threads : {2, 3}) {
    const Outcome other = runWithThreads(input, threads, {}, true);
    EXPECT_TRUE(one.mesh == other.mesh) << threads << " threads";
    EXPECT_EQ(one.report.filters.chamferEdges, other.report.filters.chamferEdges);
  }
}

TEST_P(DeterminismTest, FastFaceFaceEqualsVcglibForAnyThreadCount) {
  es::Mesh m;
  copyMesh(m, inputMesh(GetParam().shape, GetParam().faces));
  vcg::tri::UpdateTopology<es::Mesh>::FaceFace(m);
  const std::vector<std::size_t> expected = adjacency(m);
  for (const int threads : {1, 2, 3}) {
    ThreadCount scope(threads);
    for (auto &f : m.face)
      for (int i = 0; i < 3; ++i) f.FFp(i) = nullptr;
    es::buildFaceFace(m);
    EXPECT_EQ(adjacency(m), expected) << threads << " threads";
  }
}

TEST_P(DeterminismTest, LocalAdjacencyUpdateAfterSubdivisionEqualsFullRebuild) {
  es::Mesh m;
  copyMesh(m, inputMesh(GetParam().shape, GetParam().faces));
  ASSERT_EQ(es::findInputProblem(m), "");
  es::MeshLabels<es::Mesh> labels(m);
  es::computeFaceNormals(m, labels);
  es::labelSmoothEdges(m, labels, 2.0);
  es::runSixFilters(m, labels);
  const es::SplitPlan plan = es::planSplits(m, labels);
  ASSERT_FALSE(plan.faces.empty());
  es::subdivide(m, plan, labels);
  const std::vector<std::size_t> local = adjacency(m);
  vcg::tri::UpdateTopology<es::Mesh>::FaceFace(m);
  EXPECT_EQ(local, adjacency(m));
}

// The MeshLab plugin leaves the mesh's FF adjacency as sharpen() left it
// (no vcglib rebuild): it must be the adjacency vcglib builds, for every method.
TEST_P(DeterminismTest, FaceFaceAfterSharpenEqualsVcglibRebuild) {
  for (const es::Method method : {es::Method::Paper, es::Method::Extended, es::Method::Auto}) {
    es::Mesh m;
    copyMesh(m, inputMesh(GetParam().shape, GetParam().faces));
    es::SharpenOptions opt;
    opt.method = method;
    es::sharpen(m, opt);
    const std::vector<std::size_t> kept = adjacency(m);
    vcg::tri::UpdateTopology<es::Mesh>::FaceFace(m);
    EXPECT_EQ(kept, adjacency(m)) << "method " << int(method);
  }
}

// The auto method gives their input faces back to split faces it left at
// rest, and updates FF adjacency there locally: on shapes where it does, the
// adjacency must be what a full vcglib rebuild gives.
TEST(Determinism, FaceFaceAfterGivingBackEqualsVcglibRebuild) {
  std::size_t givenBack = 0;
  for (const char *shape : {"lblock_tilted", "bevelled_block", "finished_hexprism"}) {
    es::Mesh m;
    copyMesh(m, inputMesh(shape, 60000));
    const es::SharpenReport r = es::sharpen(m, es::SharpenOptions{});
    givenBack += r.evidence.facesGivenBack;
    const std::vector<std::size_t> kept = adjacency(m);
    vcg::tri::UpdateTopology<es::Mesh>::FaceFace(m);
    EXPECT_EQ(kept, adjacency(m)) << shape << ": " << r.evidence.facesGivenBack
                                  << " faces given back";
  }
  EXPECT_GT(givenBack, 0u);  // the local update ran
}

INSTANTIATE_TEST_SUITE_P(Shapes, DeterminismTest,
                         ::testing::Values(Case{"lblock_tilted", 150000}, Case{"cube", 80000},
                                           Case{"pyramid", 80000}, Case{"cross_prism", 80000},
                                           Case{"lblock", 10000}),
                         [](const ::testing::TestParamInfo<Case> &info) {
                           return info.param.shape + "_" + std::to_string(info.index);
                         });

TEST(Determinism, OpenBoundaryAndNonManifoldRingsMatchVcglib) {
  // A fan of three faces on one edge (non-manifold) plus an open strip: the
  // boundary edges point at themselves, the ring visits every face once.
  es::Mesh m;
  auto v = vcg::tri::Allocator<es::Mesh>::AddVertices(m, 6);
  const float p[6][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {2, 1, 0}};
  for (int i = 0; i < 6; ++i) v[i].P() = vcg::Point3f(p[i][0], p[i][1], p[i][2]);
  const int t[5][3] = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {1, 5, 2}, {2, 5, 4}};
  auto f = vcg::tri::Allocator<es::Mesh>::AddFaces(m, 5);
  for (int i = 0; i < 5; ++i)
    for (int k = 0; k < 3; ++k) f[i].V(k) = &m.vert[t[i][k]];
  es::buildFaceFace(m);
  int ringEdges = 0;
  for (auto &face : m.face)
    for (int i = 0; i < 3; ++i) {
      if (face.FFp(i) == &face) {
        EXPECT_EQ(face.FFi(i), i);
        continue;
      }
      // Following the ring from any face edge comes back to it.
      auto *g = face.FFp(i);
      int gi = face.FFi(i), steps = 1;
      while (g != &face && steps < 10) {
        auto *h = g->FFp(gi);
        gi = g->FFi(gi);
        g = h;
        ++steps;
      }
      EXPECT_EQ(g, &face);
      if (steps == 3) ++ringEdges;
    }
  EXPECT_EQ(ringEdges, 3);  // the three faces on edge 0-1
  bool nonManifold = false;
  EXPECT_EQ(es::findInputProblem(m, &nonManifold), "");  // processed, its spot held
  EXPECT_TRUE(nonManifold);
}

}  // namespace

TEST(Determinism, IndicesWhereKeepsIndexOrderForAnyThreadCount) {
  const std::int64_t n = 100003;
  const auto keep = [](std::int64_t i) { return i % 7 == 3 || i % 11 == 0; };
  std::vector<std::uint32_t> expected;
  for (std::int64_t i = 0; i < n; ++i)
    if (keep(i)) expected.push_back(std::uint32_t(i));
  for (const int threads : {1, 2, 3, 8}) {
    ThreadCount scope(threads);
    EXPECT_EQ(es::detail::indicesWhere(n, keep, /*minParallel=*/0), expected)
        << threads << " threads";
  }
  EXPECT_TRUE(es::detail::indicesWhere(0, keep, 0).empty());
}

// A rough input's flattening (planar_regions.h: flattenPlanarRegions) decides
// on every core: a rough box of over 50,000 vertices, flattened onto its
// grown planes (plane_patches.h), comes out the same for any thread count.
TEST(Determinism, FlatteningIsIdenticalForAnyThreadCount) {
  es::Mesh rough;
  const int n = 100;
  es::hand_built::voxelSurface(rough, {{0, 0, 0}}, n);
  ASSERT_GT(rough.vert.size(), std::size_t(es::kParallelMin));
  std::mt19937 random(11);
  std::uniform_real_distribution<double> offset(-0.2 / n, 0.2 / n);
  for (auto &v : rough.vert)
    v.P() += es::Mesh::CoordType(offset(random), offset(random), offset(random));
  const es::VertexFaceTable vf(rough);
  const es::PlanePatches patches =
      es::growPlanePatches(rough, vf, 1.0 / n, es::PlanePatchSettings{});
  ASSERT_GE(patches.count(), 6u);
  std::vector<es::Mesh::CoordType> expected;
  for (const int threads : {1, 2, 3, 8}) {
    ThreadCount scope(threads);
    es::Mesh m;
    vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(m, rough);
    const std::size_t moved = es::flattenPlanarRegions(m, vf, patches.labels, patches.planes,
                                                       1e-3 / n, 2.0 / n, es::outwardSign(m));
    EXPECT_GT(moved, rough.vert.size() / 4) << threads << " threads";
    std::vector<es::Mesh::CoordType> positions;
    for (const auto &v : m.vert) positions.push_back(v.cP());
    if (expected.empty()) expected = positions;
    EXPECT_TRUE(positions == expected) << threads << " threads";
  }
}

// The output's normals are computed on every core; they are the ones vcglib's
// UpdateNormal::PerFaceNormalized and PerVertexNormalized give (here with a
// few faces deleted, as sharpen() leaves them before its compaction).
TEST(Determinism, OutputNormalsAreVcglibs) {
  const auto input = [](es::Mesh &m) {
    copyMesh(m, inputMesh("lblock_tilted", 150000));
    for (auto &v : m.vert) v.N() = vcg::Point3f(0.3f, 0.5f, 0.7f);  // stale normals
    for (std::size_t i = 0; i < m.face.size(); i += 997)
      vcg::tri::Allocator<es::Mesh>::DeleteFace(m, m.face[i]);
  };
  es::Mesh expected;
  input(expected);
  vcg::tri::UpdateNormal<es::Mesh>::PerFaceNormalized(expected);
  vcg::tri::UpdateNormal<es::Mesh>::PerVertexNormalized(expected);
  for (const int threads : {1, 3}) {
    ThreadCount scope(threads);
    es::Mesh m;
    input(m);
    es::detail::updateOutputNormals(m);
    std::size_t facesDiffer = 0, verticesDiffer = 0;
    for (std::size_t i = 0; i < m.face.size(); ++i)
      facesDiffer += !m.face[i].IsD() && m.face[i].N() != expected.face[i].N();
    for (std::size_t i = 0; i < m.vert.size(); ++i)
      verticesDiffer += m.vert[i].N() != expected.vert[i].N();
    EXPECT_EQ(facesDiffer, 0u) << threads << " threads";
    EXPECT_EQ(verticesDiffer, 0u) << threads << " threads";
  }
}
