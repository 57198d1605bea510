// Stages 3 and 4 (planSplits, subdivide) on hand-labelled tetrahedra and a
// marching-cubes cube: a face with one chamfer edge splits in 2, with two in
// 3 along the shorter diagonal, a corner into a fan of 6 around its centre;
// the children tile their parent with its orientation, and the mesh stays
// closed, 2-manifold and consistently oriented with the adjacency a full
// rebuild gives.
#include <gtest/gtest.h>

#include <map>

#include "edge_sharpener/filters.h"
#include "edge_sharpener/smooth_edges.h"
#include "edge_sharpener/subdivision.h"
#include "hand_built_meshes.h"
#include "test_meshes/shapes.h"

namespace es = edge_sharpener;
using es::Vec3;
using es::hand_built::closedOrientedManifold;
using es::hand_built::hasEdge;

namespace {

// Tetrahedron a b c d; face 0 = a b c (normal +z), d below. Face 0's edges:
// 0 = a-b, 1 = b-c, 2 = c-a.
enum : std::size_t { kA, kB, kC, kD };

void tetrahedron(es::Mesh &m, double cx) {
  es::hand_built::makeMesh(m, {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(cx, 1, 0), Vec3(0.4, 0.4, -1)},
                           {{kA, kB, kC}, {kB, kA, kD}, {kC, kB, kD}, {kA, kC, kD}});
}

/// Marks edges of face 0 as chamfer edges (on both sides), then labels the
/// faces by their chamfer edges as filter 6 does.
void markChamferEdges(es::Mesh &m, es::MeshLabels<es::Mesh> &labels,
                      std::initializer_list<int> edges) {
  for (const int i : edges) labels.setEdge(&m.face[0], i, es::EdgeLabel::Chamfer);
  es::paintCornerAndChamferFaces(m, labels);
}

/// Each face before the split: its area normal. The face's quality holds its
/// index, which subdivide() copies to the children (they keep the parent's data).
struct Parents {
  std::vector<Vec3> areaNormal;
  std::vector<Vec3> point;

  explicit Parents(es::Mesh &m) {
    for (std::size_t f = 0; f < m.face.size(); ++f) {
      m.face[f].Q() = float(f);
      areaNormal.push_back(es::hand_built::areaNormal(m.face[f]));
      point.push_back(es::positionOf(m.face[f].cV(0)));
    }
  }

  /// Every live face lies in its parent's plane with the parent's
  /// orientation, and the children's areas add up to the parent's: they tile
  /// it without folding over.
  ::testing::AssertionResult tiledWithParentOrientation(const es::Mesh &m) const {
    std::vector<double> childArea(areaNormal.size(), 0.0);
    for (const auto &f : m.face) {
      if (f.IsD()) continue;
      const std::size_t p = std::size_t(f.cQ());
      const Vec3 n = areaNormal[p] / areaNormal[p].Norm();
      const Vec3 child = es::hand_built::areaNormal(f);
      if (!(child * n > 0))
        return ::testing::AssertionFailure() << "a child of face " << p << " is flipped";
      for (int k = 0; k < 3; ++k) {
        const double offset = std::abs(n * (es::positionOf(f.cV(k)) - point[p]));
        if (offset > 1e-6)
          return ::testing::AssertionFailure()
                 << "a child of face " << p << " leaves its plane by " << offset;
      }
      childArea[p] += child.Norm();
    }
    for (std::size_t p = 0; p < areaNormal.size(); ++p)
      if (std::abs(childArea[p] - areaNormal[p].Norm()) > 1e-6 * areaNormal[p].Norm())
        return ::testing::AssertionFailure() << "children of face " << p << " cover "
                                             << childArea[p] << " of " << areaNormal[p].Norm();
    return ::testing::AssertionSuccess();
  }
};

/// The inserted vertex (as a mesh index) placed between original vertices u and w.
std::size_t insertedBetween(const es::SplitPlan &plan, std::size_t u, std::size_t w) {
  for (std::size_t k = 0; k < plan.inserted.size(); ++k) {
    const auto &s = plan.inserted[k];
    if (s.originalCount == 2 &&
        ((s.original[0] == u && s.original[1] == w) || (s.original[0] == w && s.original[1] == u)))
      return plan.originalVertexCount + k;
  }
  ADD_FAILURE() << "no inserted vertex between " << u << " and " << w;
  return plan.originalVertexCount;
}

double distance(const es::Mesh &m, std::size_t u, std::size_t w) {
  return (es::positionOf(&m.vert[u]) - es::positionOf(&m.vert[w])).Norm();
}

/// subdivide()'s counts: faces split in 2, 3 and 6, vertices inserted, faces added.
void expectCounts(const es::SubdivisionStats &s, std::size_t in2, std::size_t in3, std::size_t in6,
                  std::size_t inserted, std::size_t added) {
  EXPECT_EQ(s.facesSplitIn2, in2);
  EXPECT_EQ(s.facesSplitIn3, in3);
  EXPECT_EQ(s.facesSplitIn6, in6);
  EXPECT_EQ(s.insertedVertices, inserted);
  EXPECT_EQ(s.addedFaces, added);
}

/// The children tile their parents with their orientation, and the mesh is
/// closed, 2-manifold and oriented, with the adjacency a full rebuild gives.
void expectCleanSplit(const Parents &parents, es::Mesh &m) {
  EXPECT_TRUE(parents.tiledWithParentOrientation(m));
  EXPECT_TRUE(closedOrientedManifold(m));
  EXPECT_TRUE(es::hand_built::adjacencyMatchesRebuild(m));
}

}  // namespace

TEST(Subdivision, OneChamferEdgeSplitsBothItsFacesInTwo) {
  es::Mesh m;
  tetrahedron(m, 0.3);
  es::MeshLabels<es::Mesh> labels(m);
  markChamferEdges(m, labels, {0});  // a-b: faces a b c and b a d
  es::computeFaceNormals(m, labels);
  const es::SplitPlan plan = es::planSplits(m, labels);
  ASSERT_EQ(plan.originalVertexCount, 4u);
  ASSERT_EQ(plan.inserted.size(), 1u);  // one vertex, shared by both faces of the edge
  EXPECT_EQ(plan.inserted[0].originalCount, 2);
  EXPECT_LT((plan.inserted[0].rest - Vec3(0.5, 0, 0)).Norm(), 1e-12);  // the midpoint
  // Its chamfer's normal: the two faces' unit normals summed.
  const Vec3 sum = labels.normal[&m.face[0]] + labels.normal[&m.face[1]];
  EXPECT_LT((plan.inserted[0].chamferNormal - sum).Norm(), 1e-12);
  // It bisects the faces' normals, across the edge a-b (along x).
  EXPECT_GT(plan.inserted[0].chamferNormal.Norm(), 0.5);
  EXPECT_NEAR(plan.inserted[0].chamferNormal[0], 0.0, 1e-12);
  EXPECT_NEAR(plan.inserted[0].chamferNormal * labels.normal[&m.face[0]],
              plan.inserted[0].chamferNormal * labels.normal[&m.face[1]], 1e-12);
  ASSERT_EQ(plan.faces.size(), 2u);
  for (const es::SplitFace &sf : plan.faces) {
    EXPECT_EQ(sf.centerVertex, -1);
    int withVertex = 0;
    for (const int v : sf.edgeVertex) withVertex += v == 0;
    EXPECT_EQ(withVertex, 1);
  }

  const Parents parents(m);
  expectCounts(es::subdivide(m, plan, labels), 2, 0, 0, 1, 2);
  ASSERT_EQ(m.vert.size(), 5u);
  ASSERT_EQ(m.face.size(), 6u);
  const std::size_t e = 4;
  EXPECT_FALSE(hasEdge(m, kA, kB));  // cut at e...
  EXPECT_TRUE(hasEdge(m, kA, e));
  EXPECT_TRUE(hasEdge(m, e, kB));
  EXPECT_TRUE(hasEdge(m, e, kC));  // ...and joined to both opposite vertices
  EXPECT_TRUE(hasEdge(m, e, kD));
  EXPECT_EQ(es::hand_built::valence(m, e), 4u);
  expectCleanSplit(parents, m);
  // Children keep their parent's label.
  for (const auto &f : m.face)
    EXPECT_EQ(labels.face[&f], f.cQ() < 2 ? es::FaceLabel::Chamfer : es::FaceLabel::Gray);
}

TEST(Subdivision, TwoChamferEdgesSplitInThreeAlongTheShorterDiagonal) {
  // Free edge a-b, apex c, m1 on b-c, m2 on c-a: with c over x = 0.2 the
  // diagonal a-m1 is the shorter one, with c over x = 0.8 it is b-m2.
  for (const double cx : {0.2, 0.8}) {
    SCOPED_TRACE(cx);
    es::Mesh m;
    tetrahedron(m, cx);
    es::MeshLabels<es::Mesh> labels(m);
    markChamferEdges(m, labels, {1, 2});
    ASSERT_EQ(labels.face[&m.face[0]], es::FaceLabel::Chamfer);
    const es::SplitPlan plan = es::planSplits(m, labels);
    ASSERT_EQ(plan.inserted.size(), 2u);
    ASSERT_EQ(plan.faces.size(), 3u);  // a b c in 3, c b d and a c d in 2

    const Parents parents(m);
    expectCounts(es::subdivide(m, plan, labels), 2, 1, 0, 2, 4);
    ASSERT_EQ(m.face.size(), 8u);

    const std::size_t m1 = insertedBetween(plan, kB, kC), m2 = insertedBetween(plan, kC, kA);
    EXPECT_TRUE(hasEdge(m, kA, kB));  // the free edge stays
    EXPECT_TRUE(hasEdge(m, m1, m2));  // the apex triangle m1 c m2
    const bool viaA = distance(m, kA, m1) < distance(m, kB, m2);
    EXPECT_EQ(viaA, cx < 0.5);
    EXPECT_EQ(hasEdge(m, kA, m1), viaA);
    EXPECT_EQ(hasEdge(m, kB, m2), !viaA);
    expectCleanSplit(parents, m);
  }
}

TEST(Subdivision, CornerSplitsIntoAFanOfSixAroundItsCentre) {
  es::Mesh m;
  tetrahedron(m, 0.3);
  es::MeshLabels<es::Mesh> labels(m);
  markChamferEdges(m, labels, {0, 1, 2});
  ASSERT_EQ(labels.face[&m.face[0]], es::FaceLabel::Corner);
  const es::SplitPlan plan = es::planSplits(m, labels);
  ASSERT_EQ(plan.inserted.size(), 4u);  // three edge vertices and the centre
  ASSERT_EQ(plan.faces.size(), 4u);
  const es::SplitFace &corner = plan.faces[0];
  ASSERT_EQ(corner.face, 0u);
  ASSERT_GE(corner.centerVertex, 0);
  const es::InsertedVertexSource &centre = plan.inserted[corner.centerVertex];
  EXPECT_EQ(centre.originalCount, 3);
  EXPECT_EQ(centre.chamferNormal.SquaredNorm(), 0.0);  // read only for edge vertices
  const Vec3 centroid =
      (es::positionOf(&m.vert[kA]) + es::positionOf(&m.vert[kB]) + es::positionOf(&m.vert[kC])) / 3;
  EXPECT_LT((centre.rest - centroid).Norm(), 1e-12);

  const Parents parents(m);
  expectCounts(es::subdivide(m, plan, labels), 3, 0, 1, 4, 8);
  ASSERT_EQ(m.face.size(), 12u);
  const std::size_t c = plan.originalVertexCount + std::size_t(corner.centerVertex);
  // The six children of the corner are exactly the faces around the centre.
  std::size_t aroundCentre = 0, cornerChildren = 0;
  for (const auto &f : m.face) {
    bool hasCentre = false;
    for (int k = 0; k < 3; ++k) hasCentre |= vcg::tri::Index(m, f.cV(k)) == c;
    aroundCentre += hasCentre;
    cornerChildren += f.cQ() == 0;
    EXPECT_TRUE(hasCentre || f.cQ() != 0);
    EXPECT_EQ(labels.face[&f], f.cQ() == 0 ? es::FaceLabel::Corner : es::FaceLabel::Chamfer);
  }
  EXPECT_EQ(aroundCentre, 6u);
  EXPECT_EQ(cornerChildren, 6u);
  EXPECT_EQ(es::hand_built::valence(m, c), 6u);
  for (const auto &[u, w] : {std::pair{kA, kB}, {kB, kC}, {kC, kA}}) {
    const std::size_t e = insertedBetween(plan, u, w);
    EXPECT_EQ(es::hand_built::valence(m, e), 4u);  // u, w, the centre, the far vertex d
    EXPECT_TRUE(hasEdge(m, e, kD));
  }
  expectCleanSplit(parents, m);
}

// A coloured mesh (a scan with vertex colours, in MeshLab): each inserted
// vertex takes its sources' mean colour and quality, not vcglib's white.
TEST(Subdivision, InsertedVerticesTakeTheirSourcesMeanColourAndQuality) {
  es::Mesh m;
  tetrahedron(m, 0.3);
  const vcg::Color4b colour[4] = {vcg::Color4b(200, 0, 0, 255), vcg::Color4b(0, 100, 0, 255),
                                  vcg::Color4b(0, 0, 51, 255), vcg::Color4b(9, 9, 9, 255)};
  for (std::size_t v = 0; v < 4; ++v) {
    m.vert[v].C() = colour[v];
    m.vert[v].Q() = float(v + 1);
  }
  es::MeshLabels<es::Mesh> labels(m);
  markChamferEdges(m, labels, {0, 1, 2});
  const es::SplitPlan plan = es::planSplits(m, labels);
  es::subdivide(m, plan, labels);
  ASSERT_EQ(m.vert.size(), 8u);
  for (std::size_t v = 0; v < 4; ++v) EXPECT_EQ(m.vert[v].cC(), colour[v]);  // as they were
  const std::size_t ab = insertedBetween(plan, kA, kB), ca = insertedBetween(plan, kC, kA);
  EXPECT_EQ(m.vert[ab].cC(), vcg::Color4b(100, 50, 0, 255));
  EXPECT_EQ(m.vert[ca].cC(), vcg::Color4b(100, 0, 26, 255));  // 25.5 rounds up
  EXPECT_FLOAT_EQ(m.vert[ab].cQ(), 1.5f);
  const std::size_t centre = plan.originalVertexCount + std::size_t(plan.faces[0].centerVertex);
  EXPECT_EQ(m.vert[centre].cC(), vcg::Color4b(67, 33, 17, 255));
  EXPECT_FLOAT_EQ(m.vert[centre].cQ(), 2.0f);
}

// A chamfer edge on the mesh border (an open scan cut across a chamfer) gets
// its own vertex; its two halves stay border edges.
TEST(Subdivision, ChamferEdgeOnTheBorderStaysABorder) {
  es::Mesh m;
  es::hand_built::makeMesh(m, {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)},
                           {{0, 1, 2}, {0, 2, 3}});
  es::MeshLabels<es::Mesh> labels(m);
  markChamferEdges(m, labels, {0});
  const es::SplitPlan plan = es::planSplits(m, labels);
  const Parents parents(m);
  const es::SubdivisionStats s = es::subdivide(m, plan, labels);
  EXPECT_EQ(s.facesSplitIn2, 1u);
  ASSERT_EQ(m.face.size(), 3u);
  std::size_t borderEdges = 0;
  for (auto &f : m.face)
    for (int i = 0; i < 3; ++i) borderEdges += f.FFp(i) == &f;
  EXPECT_EQ(borderEdges, 5u);  // the square's four sides, one of them cut in two
  EXPECT_TRUE(parents.tiledWithParentOrientation(m));
  EXPECT_TRUE(es::hand_built::adjacencyMatchesRebuild(m));
}

// The real detection on a marching-cubes cube (chamfer bands along the edges,
// corner patches): every planned split keeps the mesh closed, 2-manifold and
// oriented, and the counts add up.
TEST(Subdivision, SplitOfAChamferedCubeKeepsItClosedAndOriented) {
  es::Mesh m;
  es::test_meshes::marchingCubes(es::test_meshes::shapeByName("cube"), 0.1, m);
  ASSERT_TRUE(closedOrientedManifold(m));
  const double volume = es::test_meshes::signedVolume(m);
  es::MeshLabels<es::Mesh> labels(m);
  es::computeFaceNormals(m, labels);
  es::labelSmoothEdges(m, labels, 2.0);
  const es::FilterStats filters = es::runSixFilters(m, labels);
  ASSERT_GT(filters.chamferEdges, 0u);

  const es::SplitPlan plan = es::planSplits(m, labels);
  const Parents parents(m);
  const es::SubdivisionStats s = es::subdivide(m, plan, labels);
  EXPECT_EQ(s.insertedVertices, filters.chamferEdges + filters.cornerFaces);
  EXPECT_EQ(s.facesSplitIn2 + s.facesSplitIn3, filters.chamferFaces);
  EXPECT_EQ(s.facesSplitIn6, filters.cornerFaces);
  EXPECT_EQ(s.addedFaces, s.facesSplitIn2 + 2 * s.facesSplitIn3 + 5 * s.facesSplitIn6);
  EXPECT_GT(s.facesSplitIn3, 0u);
  EXPECT_GT(s.facesSplitIn6, 0u);
  expectCleanSplit(parents, m);
  EXPECT_NEAR(es::test_meshes::signedVolume(m), volume, 1e-6 * volume);
}

// A split face left at rest is its input face again, fanned from the
// inserted edge vertices a neighbour still needs: positive areas in the
// parent's orientation that add up to the parent's, no vertex it drops.
TEST(Subdivision, RestedFaceKeepsOnlyTheEdgeVerticesItsNeighboursNeed) {
  // Parent 0 1 2 (normal +z); inserted 0, 1, 2 on edges 0-1, 1-2, 2-0 and 3
  // at the centre get indices 3 to 6.
  const std::vector<Vec3> at = {Vec3(0, 0, 0),          Vec3(1, 0, 0),     Vec3(0, 1, 0),
                                Vec3(0.5, 0, 0),        Vec3(0.5, 0.5, 0), Vec3(0, 0.5, 0),
                                Vec3(1. / 3, 1. / 3, 0)};
  const auto check = [&](const es::SplitFace &sf, std::array<bool, 3> keep,
                         std::vector<std::size_t> kept, std::vector<std::size_t> dropped) {
    const auto tris = es::detail::restedTriangles(sf, {0, 1, 2}, 3, keep);
    EXPECT_EQ(tris.size(), 1 + kept.size());
    double area = 0;
    for (const auto &t : tris) {
      const double a = ((at[t[1]] - at[t[0]]) ^ (at[t[2]] - at[t[0]])).Z() / 2;
      EXPECT_GT(a, 1e-3) << "degenerate or flipped";
      area += a;
      for (std::size_t v : dropped) EXPECT_TRUE(t[0] != v && t[1] != v && t[2] != v);
    }
    EXPECT_NEAR(area, 0.5, 1e-12);
    for (std::size_t v : kept) {
      bool used = false;
      for (const auto &t : tris) used = used || t[0] == v || t[1] == v || t[2] == v;
      EXPECT_TRUE(used) << v;
    }
  };
  es::SplitFace corner;
  corner.edgeVertex = {0, 1, 2};
  corner.centerVertex = 3;
  check(corner, {false, false, false}, {}, {3, 4, 5, 6});
  check(corner, {false, true, false}, {4}, {3, 5, 6});
  check(corner, {true, false, true}, {3, 5}, {4, 6});
  check(corner, {true, true, true}, {3, 4, 5}, {6});
  es::SplitFace chamfer;  // two chamfer edges, 1-2 and 2-0
  chamfer.edgeVertex = {-1, 1, 2};
  check(chamfer, {true, true, false}, {4}, {5});  // keep[0] names no vertex
  check(chamfer, {false, true, true}, {4, 5}, {});
}
