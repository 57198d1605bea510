// The six filters, placement and its fallbacks on hand-built height fields
// whose labels and exact results are known in closed form; the intersection
// guard's broad phase on hand-placed triangles.
#include <gtest/gtest.h>

#include <functional>
#include <limits>

#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/guards/face_contact.h"
#include "edge_sharpener/util/mesh_types.h"
#include "hand_built_meshes.h"
#include "test_meshes/shapes.h"

namespace es = edge_sharpener;

namespace {

/// A regular grid of (nx+1) x (ny+1) vertices with spacing h over z = f(x, y),
/// every cell split by the same diagonal. Open (boundary all around).
template <class MeshType>
void makeHeightField(MeshType &m, int nx, int ny, double h,
                     const std::function<double(double, double)> &f) {
  using Alloc = vcg::tri::Allocator<MeshType>;
  using Coord = typename MeshType::CoordType;
  m.Clear();
  Alloc::AddVertices(m, std::size_t(nx + 1) * (ny + 1));
  const auto id = [&](int i, int j) { return std::size_t(j) * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.vert[id(i, j)].P() = Coord(i * h, j * h, f(i * h, j * h));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      Alloc::AddFace(m, &m.vert[id(i, j)], &m.vert[id(i + 1, j)], &m.vert[id(i + 1, j + 1)]);
      Alloc::AddFace(m, &m.vert[id(i, j)], &m.vert[id(i + 1, j + 1)], &m.vert[id(i, j + 1)]);
    }
  vcg::tri::UpdateTopology<MeshType>::FaceFace(m);
}

constexpr int kNx = 20, kNy = 12;
constexpr double kH = 0.1;
constexpr double kRidgeX = 1.03;  // between grid columns 10 and 11

double ridge(double x, double) {
  return 0.5 - 0.5 * std::abs(x - kRidgeX);
}
double valley(double x, double) {
  return 0.5 * std::abs(x - kRidgeX);
}

/// True if every face lies on one side of x = kRidgeX (it does not cut
/// across the crease) and all its vertices are on the exact surface.
template <class MeshType>
double maxDeviationFromCrease(MeshType &m, double (*f)(double, double)) {
  double worst = 0;
  for (auto &face : m.face) {
    if (face.IsD()) continue;
    bool left = false, right = false;
    for (int k = 0; k < 3; ++k) {
      const auto &p = face.cP(k);
      worst = std::max(worst, std::abs(double(p[2]) - f(p[0], p[1])));
      left |= p[0] < kRidgeX - 1e-5;
      right |= p[0] > kRidgeX + 1e-5;
    }
    if (left && right) worst = std::max(worst, 1.0);  // a face still cuts the crease
  }
  return worst;
}

es::SharpenOptions defaults() {
  return es::SharpenOptions::paperMethod();
}

}  // namespace

TEST(SixFilters, RidgeLabelsMatchTheHandCount) {
  es::Mesh m;
  makeHeightField(m, kNx, kNy, kH, ridge);
  const es::SharpenReport r = es::detectChamfers(m, defaults());
  // Chamfer column: cells between x = 1.0 and 1.1, one per row (kNy rows).
  // Blue: the kNy + 1 horizontal edges (two on the border) and kNy diagonals.
  EXPECT_EQ(r.filters.chamferEdges, std::size_t(2 * kNy + 1));
  EXPECT_EQ(r.filters.chamferFaces, std::size_t(2 * kNy));
  EXPECT_EQ(r.filters.cornerFaces, 0u);
  EXPECT_EQ(r.filters.redFaces, std::size_t(2 * kNx * kNy - 2 * kNy));
  // Interior red vertices: grid vertices not on the border and not on the
  // chamfer column's lines (x = 1.0, 1.1).
  EXPECT_EQ(r.filters.interiorRedVertices, std::size_t((kNx - 1 - 2) * (kNy - 1)));
  EXPECT_EQ(r.smooth.boundaryEdges, std::size_t(2 * (kNx + kNy)));
  // The selection marks exactly the chamfer faces; geometry is unchanged.
  std::size_t selected = 0;
  for (auto &f : m.face) selected += f.IsS();
  EXPECT_EQ(selected, std::size_t(2 * kNy));
  EXPECT_EQ(m.VN(), (kNx + 1) * (kNy + 1));
}

TEST(Sharpen, ConvexRidgeIsRecoveredExactly) {
  es::Mesh m;
  makeHeightField(m, kNx, kNy, kH, ridge);
  std::vector<vcg::Point3f> before;
  for (auto &v : m.vert) before.push_back(v.P());
  EXPECT_GT(maxDeviationFromCrease(m, ridge), 0.5);  // the input cuts the crease

  const es::SharpenReport r = es::sharpen(m, defaults());
  EXPECT_EQ(r.subdivision.insertedVertices, std::size_t(2 * kNy + 1));
  EXPECT_EQ(r.subdivision.facesSplitIn3, std::size_t(2 * kNy));
  EXPECT_EQ(r.subdivision.facesSplitIn2, 0u);
  EXPECT_EQ(r.placement.moved(), r.subdivision.insertedVertices);
  EXPECT_EQ(r.placement.fallbacks(), 0u);
  EXPECT_LT(maxDeviationFromCrease(m, ridge), 1e-5);
  EXPECT_EQ(r.outputVertices, before.size() + r.subdivision.insertedVertices);
  EXPECT_EQ(r.outputFaces, r.inputFaces + r.subdivision.addedFaces);
  for (std::size_t i = 0; i < before.size(); ++i) ASSERT_EQ(m.vert[i].P(), before[i]) << i;
}

TEST(Sharpen, ConcaveValleyIsRecoveredExactly) {
  es::Mesh m;
  makeHeightField(m, kNx, kNy, kH, valley);
  const es::SharpenReport r = es::sharpen(m, defaults());
  EXPECT_EQ(r.placement.moved(), std::size_t(2 * kNy + 1));
  EXPECT_LT(maxDeviationFromCrease(m, valley), 1e-5);
}

TEST(Sharpen, DoublePrecisionMeshGivesTheSameResult) {
  es::Mesh mf;
  es::MeshD md;
  makeHeightField(mf, kNx, kNy, kH, ridge);
  makeHeightField(md, kNx, kNy, kH, ridge);
  const auto rf = es::sharpen(mf, defaults());
  const auto rd = es::sharpen(md, defaults());
  EXPECT_EQ(rf.outputFaces, rd.outputFaces);
  EXPECT_EQ(rf.placement.byOutcome, rd.placement.byOutcome);
  EXPECT_LT(maxDeviationFromCrease(md, ridge), 1e-12);
}

namespace {
// A step: two parallel slopes joined by a riser narrower than a cell. The
// chamfer is bordered by a concave edge below and a convex edge above.
double stepParallel(double x, double) {
  return x < kRidgeX ? 0.1 * x : 0.1 * x + 0.3;
}
// Slopes that are not parallel, with the same step: the plane intersection
// exists but lies far away, on the wrong side.
double stepTilted(double x, double) {
  return x < kRidgeX ? 0.3 * (x - kRidgeX) : 0.6 - 0.3 * (x - kRidgeX);
}
}  // namespace

TEST(Fallbacks, MixedConvexityKeepsVerticesAtRest) {
  es::Mesh m;
  makeHeightField(m, kNx, kNy, kH, stepTilted);
  const auto r = es::sharpen(m, defaults());
  ASSERT_GT(r.subdivision.insertedVertices, 0u);
  EXPECT_EQ(r.placement.count(es::Placement::MixedConvexity), r.subdivision.insertedVertices);
  EXPECT_EQ(r.placement.moved(), 0u);
}

// The auto method leaves the paper's convexity check to its own tests: the
// step's planes meet far away, on the wrong side, and every vertex still
// stays at rest.
TEST(Fallbacks, AutoKeepsAStepAtRestWithoutTheConvexityCheck) {
  es::Mesh m;
  makeHeightField(m, kNx, kNy, kH, stepTilted);
  const auto r = es::sharpen(m, es::SharpenOptions{});
  ASSERT_GT(r.subdivision.insertedVertices, 0u);
  EXPECT_EQ(r.placement.count(es::Placement::MixedConvexity), 0u);
  EXPECT_EQ(r.placement.moved(), 0u);
}

TEST(Fallbacks, EdgeLengthCheckRejectsFarIntersections) {
  es::Mesh m;
  makeHeightField(m, kNx, kNy, kH, stepTilted);
  es::SharpenOptions opt = es::SharpenOptions::paperMethod();
  opt.paper.convexityCheck = false;
  const auto r = es::sharpen(m, opt);
  EXPECT_EQ(r.placement.count(es::Placement::EdgeTooLong), r.subdivision.insertedVertices);
  // No edge of the output is longer than the input's longest edge.
  for (auto &f : m.face)
    for (int k = 0; k < 3; ++k)
      EXPECT_LE(vcg::Distance(f.cP(k), f.cP((k + 1) % 3)), r.longestInputEdge * (1 + 1e-6));

  es::Mesh unchecked;
  makeHeightField(unchecked, kNx, kNy, kH, stepTilted);
  opt.edgeLengthCheck = false;
  const auto u = es::sharpen(unchecked, opt);
  EXPECT_EQ(u.placement.moved(), u.subdivision.insertedVertices);
  double longest = 0;  // without the check, placements do create too long edges
  for (auto &f : unchecked.face)
    for (int k = 0; k < 3; ++k)
      longest = std::max<double>(longest, vcg::Distance(f.cP(k), f.cP((k + 1) % 3)));
  EXPECT_GT(longest, 1.5 * u.longestInputEdge);
}

TEST(Fallbacks, ParallelPlanesKeepVerticesAtRest) {
  es::Mesh m;
  makeHeightField(m, kNx, kNy, kH, stepParallel);
  es::SharpenOptions opt = es::SharpenOptions::paperMethod();
  opt.paper.convexityCheck = false;  // otherwise the step is caught as mixed first
  const auto r = es::sharpen(m, opt);
  ASSERT_GT(r.subdivision.insertedVertices, 0u);
  EXPECT_EQ(r.placement.count(es::Placement::ParallelPlanes), r.subdivision.insertedVertices);
}

TEST(Sharpen, FlatSheetIsLeftUntouched) {
  es::Mesh m;
  makeHeightField(m, 8, 8, kH, [](double, double) { return 0.25; });
  const auto r = es::sharpen(m, defaults());
  EXPECT_EQ(r.filters.chamferEdges, 0u);
  EXPECT_EQ(r.outputFaces, r.inputFaces);
  EXPECT_EQ(r.outputVertices, r.inputVertices);
}

TEST(InputErrors, RefusedMeshesAreLeftUnchanged) {
  es::Mesh cloud;
  vcg::tri::Allocator<es::Mesh>::AddVertices(cloud, 3);
  EXPECT_THROW(es::sharpen(cloud, defaults()), es::InputError);
  EXPECT_EQ(cloud.VN(), 3);

  es::Mesh empty;
  EXPECT_THROW(es::sharpen(empty, defaults()), es::InputError);

  es::Mesh nan;
  makeHeightField(nan, 4, 4, kH, ridge);
  nan.vert[7].P()[2] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(es::sharpen(nan, defaults()), es::InputError);
  EXPECT_EQ(nan.FN(), 32);

  // A third face on an interior edge makes it non-manifold.
  es::Mesh fin;
  makeHeightField(fin, 4, 4, kH, ridge);
  auto *extra = &*vcg::tri::Allocator<es::Mesh>::AddVertices(fin, 1);
  extra->P() = vcg::Point3f(0.15f, 0.15f, 1.0f);
  vcg::tri::Allocator<es::Mesh>::AddFace(fin, &fin.vert[0], &fin.vert[6], extra);
  // It is processed: the fin and the faces on its edge are left as they came.
  const int faces = fin.FN();
  const std::size_t apex = vcg::tri::Index(fin, extra);
  const es::SharpenReport finReport = es::sharpen(fin, defaults());
  EXPECT_EQ(finReport.nonManifold.edges, 1u);
  EXPECT_GE(fin.FN(), faces);
  int finFaces = 0;
  for (const auto &f : fin.face)
    for (int k = 0; k < 3; ++k)
      finFaces += f.cV(k) == &fin.vert[0] && f.cV((k + 1) % 3) == &fin.vert[6] &&
                  f.cV((k + 2) % 3) == &fin.vert[apex];
  EXPECT_EQ(finFaces, 1) << "the fin was changed";

  es::Mesh bad;
  makeHeightField(bad, 4, 4, kH, ridge);
  es::SharpenOptions opt = es::SharpenOptions::paperMethod();
  opt.smoothMultiplier = -1;
  EXPECT_THROW(es::sharpen(bad, opt), es::InputError);
}

namespace {
// A ridge whose angle fades out along y: steep at y = 0, flat from y = 0.8.
// The two flanks meet smoothly where it is flat, so they grow into one
// smooth region (fandisk has such features); the steep part is still sharp.
double fadingRidgeSlope(double y) {
  return std::max(0.0, 1.0 - y / 0.8);
}
double fadingRidge(double x, double y) {
  return -fadingRidgeSlope(y) * std::abs(x - kRidgeX);
}
}  // namespace

TEST(Extended, RidgeFadingIntoOneRegionIsStillSharpened) {
  es::SharpenOptions opt = es::SharpenOptions::paperMethod();
  opt.method = es::Method::Extended;
  es::SharpenOptions oneSurfacePerRegion = opt;
  oneSurfacePerRegion.extended.openInternalCreases = false;
  oneSurfacePerRegion.extended.sameRegionFeatureAngleRad = 0;
  {
    es::Mesh m;
    makeHeightField(m, kNx, kNy, kH, fadingRidge);
    const es::SharpenReport r = es::detectChamfers(m, oneSurfacePerRegion);
    EXPECT_EQ(r.extended.regions, 1u);      // the flanks leaked into one region...
    EXPECT_EQ(r.filters.chamferEdges, 0u);  // ...so nothing is found
  }
  es::Mesh m;
  makeHeightField(m, kNx, kNy, kH, fadingRidge);
  const auto errorAtRidge = [&m](double maxY) {
    // Largest |z - f| at x = kRidgeX over the rows y <= maxY, on the mesh
    // (faces crossing the ridge line), and whether such a face exists.
    double worst = 0;
    for (auto &f : m.face)
      for (int k = 0; k < 3; ++k) {
        const auto &p = f.cP(k), &q = f.cP((k + 1) % 3);
        if (p[1] > maxY || q[1] > maxY || (p[0] - kRidgeX) * (q[0] - kRidgeX) >= 0) continue;
        const double t = (kRidgeX - p[0]) / (q[0] - p[0]);
        const auto x = p + (q - p) * float(t);
        worst = std::max(worst, std::abs(double(x[2]) - fadingRidge(x[0], x[1])));
      }
    return worst;
  };
  const double before = errorAtRidge(0.3);
  EXPECT_GT(before, 0.02);
  const es::SharpenReport r = es::sharpen(m, opt);
  EXPECT_GT(r.extended.openedCreases, 0u);
  EXPECT_GT(r.filters.chamferEdges, 0u);
  EXPECT_GT(r.placement.moved(), 0u);
  // Where the flanks meet at 67 degrees or more the crease is cut about half
  // as deep (measured: 0.042 -> 0.021; the flanks twist, so the 2-ring plane
  // fits are not exact, and the border row keeps its chamfer).
  EXPECT_LT(errorAtRidge(0.3), 0.6 * before);
}

// A corner where a flat face meets two pieces of one coarse cylinder: toward
// the three-plane corner the curved flank's faces spread along the cylinder's
// axis, so its bend there is diluted, but along its edge with the flat face
// the flank curves away. The pair test catches what the corner test misses.
TEST(Fallbacks, CornerPairBendsAwayWhereTheCornerDoesNot) {
  using es::CrossScatter3;
  using es::Plane;
  using es::Vec3;
  // Solid x, y, z <= 0: top A (z = 0), side B (x = 0), front C (y = 0).
  es::SupportPlanes support;
  support.reset(3);
  support.measured = true;
  support.setFit(0, es::SupportFit::of(Plane{Vec3(-0.3, -0.3, 0), Vec3(0, 0, 1)}));
  support.setFit(1, es::SupportFit::of(Plane{Vec3(0, -0.5, -0.2), Vec3(1, 0, 0)}, 10 * M_PI / 180));
  support.setFit(2, es::SupportFit::of(Plane{Vec3(-0.3, 0, -0.3), Vec3(0, 1, 0)}));
  // B's faces: spread widely along y (the cylinder's axis), narrowly along z,
  // normals turning with z at curvature `k`.
  const auto curveSide = [&](double k) {
    CrossScatter3 turn, extent, self;
    for (double y : {-0.35, 0.0, 0.35})
      for (double z : {-0.1, 0.0, 0.1}) {
        const Vec3 deviation(0, 0, k * z), offset(0, y, z);
        turn.add(deviation, offset, 1.0 / 9);
        extent.add(offset, offset, 1.0 / 9);
        self.add(deviation, deviation, 1.0 / 9);
      }
    support.fits[1].normalScatter = turn;
    support.fits[1].pointScatter = extent;
    support.fits[1].normalSelfScatter = self;
  };
  es::InsertedVertexSource corner;
  corner.original = {0, 1, 2};
  corner.originalCount = 3;
  corner.rest = Vec3(-0.1, -0.1, -0.1);
  es::SharpenOptions opt = es::SharpenOptions::paperMethod();
  opt.method = es::Method::Extended;
  const Plane planes[3] = {support.plane(0), support.plane(1), support.plane(2)};

  curveSide(5.0);
  EXPECT_FALSE(es::detail::flankBendsAway(corner, planes, support, opt, Vec3(0, 0, 0)));
  EXPECT_TRUE(es::detail::cornerPairBendsAway(corner, planes, support, opt));
  Vec3 target;
  bool bent = false;
  EXPECT_EQ(es::proposePlacement(corner, support, opt, es::PlacementPolicy::extendedMethod(opt),
                                 target, bent),
            es::Placement::CurvedSupport);

  // A gently curved side passes both: the corner is sharpened.
  curveSide(0.5);
  EXPECT_FALSE(es::detail::cornerPairBendsAway(corner, planes, support, opt));
  ASSERT_EQ(es::proposePlacement(corner, support, opt, es::PlacementPolicy::extendedMethod(opt),
                                 target, bent),
            es::Placement::Moved);
  EXPECT_LT(target.Norm(), 1e-12);
  EXPECT_FALSE(bent);

  // The auto method: where the move (0.17) is at most maxBentMoveSpacings
  // sample spacings, the bend only marks the vertex, which moves to the
  // corner and stays there only with a feature whose evidence is strong.
  curveSide(5.0);
  support.sampleSpacing = 0.2;
  ASSERT_EQ(es::proposePlacement(corner, support, opt, es::PlacementPolicy::autoMethod(opt), target,
                                 bent),
            es::Placement::Moved);
  EXPECT_TRUE(bent);
  EXPECT_LT(target.Norm(), 1e-12);
  support.sampleSpacing = 0.1;  // a longer move extrapolates the curved flank
  EXPECT_EQ(es::proposePlacement(corner, support, opt, es::PlacementPolicy::autoMethod(opt), target,
                                 bent),
            es::Placement::CurvedSupport);
  support.sampleSpacing = 0.2;
  opt.rules.vertex.maxBentMoveSpacings = 0;  // off: the bend keeps the vertex at rest
  EXPECT_EQ(es::proposePlacement(corner, support, opt, es::PlacementPolicy::autoMethod(opt), target,
                                 bent),
            es::Placement::CurvedSupport);
}

// An inserted vertex whose sharp edge lies more than maxDisplacementSpacings
// sample spacings away stays at rest; within the bound, or with the bound
// off, it moves onto the planes' edge.
TEST(Fallbacks, SharpEdgeFarAwayKeepsVertexAtRest) {
  using es::Plane;
  using es::Vec3;
  // Solid x, z <= 0: side A (x = 0) and top B (z = 0), chamfer from
  // (0, 0, -0.2) to (-0.2, 0, 0); the sharp edge is the y axis.
  es::SupportPlanes support;
  support.reset(2);
  support.setFit(0, es::SupportFit::of(Plane{Vec3(0, 0, -0.2), Vec3(1, 0, 0)}));
  support.setFit(1, es::SupportFit::of(Plane{Vec3(-0.2, 0, 0), Vec3(0, 0, 1)}));
  support.sampleSpacing = 0.1;
  es::InsertedVertexSource edge;
  edge.original = {0, 1, 0};
  edge.originalCount = 2;
  edge.rest = Vec3(-0.1, 0, -0.1);
  es::SharpenOptions opt = es::SharpenOptions::paperMethod();
  opt.method = es::Method::Extended;
  Vec3 target;
  bool bent = false;
  ASSERT_EQ(es::proposePlacement(edge, support, opt, es::PlacementPolicy::extendedMethod(opt),
                                 target, bent),
            es::Placement::Moved);
  EXPECT_LT(target.Norm(), 1e-12);

  // The sharp edge lies 0.141 from the chamfer's middle, more than 2.5
  // sample spacings of 0.05 but less than 2.5 x 0.1.
  support.sampleSpacing = 0.05;
  EXPECT_EQ(es::proposePlacement(edge, support, opt, es::PlacementPolicy::extendedMethod(opt),
                                 target, bent),
            es::Placement::FarFromChamfer);
  opt.extended.maxDisplacementSpacings = 0;  // bound off
  EXPECT_EQ(es::proposePlacement(edge, support, opt, es::PlacementPolicy::extendedMethod(opt),
                                 target, bent),
            es::Placement::Moved);
}

// The intersection guard's broad phase: a hashed grid over the query boxes.
// A face in the last, partial grid cell of the boxes' bounds must still be
// found (it was taken for outside the bounds, and its intersections missed).
// Two faces meeting at one point through distinct vertices there (a
// marching-cubes mesh has them where the surface passes through a grid node)
// only touch, as faces sharing the vertex do; through the same point they
// still intersect where one crosses the other.
TEST(IntersectionGuard, FacesMeetingAtADuplicatedVertexOnlyTouch) {
  using es::Vec3;
  const auto at = [](const es::Mesh::VertexType *v) { return es::positionOf(v); };
  es::Mesh m;
  // f = 0 1 2 and g = 3 4 5, vertex 3 a copy of vertex 0; g coplanar beside f.
  es::hand_built::makeMesh(m,
                           {Vec3(0, 0, 0), Vec3(-1, 0.5, 0), Vec3(-1, -0.5, 0), Vec3(0, 0, 0),
                            Vec3(1, -0.5, 0), Vec3(1, 0.5, 0)},
                           {{0, 1, 2}, {3, 4, 5}});
  EXPECT_FALSE(es::detail::facesIntersect<es::Mesh>(&m.face[0], &m.face[1], at));
  // g standing across f: from the common point through f's inside and out.
  es::hand_built::makeMesh(m,
                           {Vec3(0, 0, 0), Vec3(-1, 0.5, 0), Vec3(-1, -0.5, 0), Vec3(0, 0, 0),
                            Vec3(-0.8, 0, -0.5), Vec3(-0.8, 0, 0.5)},
                           {{0, 1, 2}, {3, 4, 5}});
  EXPECT_TRUE(es::detail::facesIntersect<es::Mesh>(&m.face[0], &m.face[1], at));
}

// A fold through a shared vertex is found at any scale: vcglib's segment
// test took every segment of a part a hundredth of a unit in size for one
// parallel to the face, and the guard never saw such a fold.
TEST(IntersectionGuard, FoldThroughASharedVertexAtEveryScale) {
  using es::Vec3;
  const auto at = [](const es::Mesh::VertexType *v) { return es::positionOf(v); };
  for (const double scale : {1e-4, 1e-2, 1.0, 1e3}) {
    es::Mesh m;
    // g crosses f along a line from their vertex 0 through f's inside
    // (turned 13 degrees about it).
    const double rise = std::tan(5 * M_PI / 180);
    es::hand_built::makeMesh(
        m,
        {Vec3(0, 0, 0) * scale, Vec3(-1, 0.5, 0) * scale, Vec3(-1, -0.5, 0) * scale,
         Vec3(-1, 0.3, -0.8 * rise) * scale, Vec3(-1, -0.3, 0.8 * rise) * scale},
        {{0, 1, 2}, {0, 3, 4}});
    EXPECT_TRUE(es::detail::facesIntersect<es::Mesh>(&m.face[0], &m.face[1], at)) << scale;
    // g beside f, above its plane.
    es::hand_built::makeMesh(
        m,
        {Vec3(0, 0, 0) * scale, Vec3(-1, 0.5, 0) * scale, Vec3(-1, -0.5, 0) * scale,
         Vec3(1, 0.3, rise) * scale, Vec3(1, -0.3, rise) * scale},
        {{0, 1, 2}, {0, 3, 4}});
    EXPECT_FALSE(es::detail::facesIntersect<es::Mesh>(&m.face[0], &m.face[1], at)) << scale;
  }
}

// Two moves that cross only together, mirror images of each other (x and z
// swapped): new vertex a pushes the flat face a p q (z = 0.2) out to
// x = 0.3, new vertex b the upright face b r s (x = 0.2) up to z = 0.3;
// either going back parts them, as far out. The guard sends one back; a
// vertex flagged to retreat first (a move on weaker evidence: the evidence
// guard's keptMoves) is the one, whichever it chose unflagged.
TEST(IntersectionGuard, AVertexFlaggedToRetreatFirstIsTheOneSentBack) {
  using es::Vec3;
  const auto swapXZ = [](const Vec3 &v) { return Vec3(v[2], v[1], v[0]); };
  const Vec3 aRest(-0.2, 0, 0.2), aMoved(0.3, 0, 0.2), p(-1, -0.5, 0.2), q(-1, 0.5, 0.2);
  const auto sentBack = [&](const std::vector<char> *retreatFirst) {
    es::Mesh m;
    // p q r s, then the new vertices a (4) and b (5) where placement put them.
    es::hand_built::makeMesh(m, {p, q, swapXZ(q), swapXZ(p), aMoved, swapXZ(aMoved)},
                             {{4, 0, 1}, {5, 2, 3}});
    const es::SplitPlan plan = es::hand_built::planWithInserted(4, {aRest, swapXZ(aRest)});
    es::MeshLabels<es::Mesh> labels(m);
    labels.placement[4] = labels.placement[5] = es::Placement::Moved;
    es::VertexMoves<es::Mesh> moves(m, plan, labels, false);
    const es::IntersectionStats stats =
        es::revertSelfIntersections(m, moves, 1 * M_PI / 180, 2.0, retreatFirst);
    EXPECT_EQ(stats.intersectingPairs, 1u);
    EXPECT_TRUE(moves.isMoved(4) != moves.isMoved(5)) << "exactly one goes back";
    return moves.isMoved(4) ? std::size_t(5) : std::size_t(4);
  };
  const std::size_t unflagged = sentBack(nullptr);
  const std::size_t other = unflagged == 4 ? 5 : 4;
  std::vector<char> first(6, 0);
  first[other] = 1;
  EXPECT_EQ(sentBack(&first), other);
}

TEST(IntersectionGuard, BoxOverlapFindsFacesInTheLastPartialCell) {
  es::Mesh m;
  using Alloc = vcg::tri::Allocator<es::Mesh>;
  using Coord = es::Mesh::CoordType;
  const auto addTriangle = [&](Coord a, Coord b, Coord c) {
    auto v = Alloc::AddVertices(m, 3);
    v[0].P() = a, v[1].P() = b, v[2].P() = c;
    Alloc::AddFace(m, &*v, &*(v + 1), &*(v + 2));
  };
  addTriangle({2.2f, 0.5f, 0.5f}, {2.4f, 0.5f, 0.5f},
              {2.3f, 0.6f, 0.5f});  // in box 1, x cell 2.2-2.4 of 2.5
  addTriangle({0.2f, 0.2f, 0.2f}, {0.4f, 0.2f, 0.2f}, {0.3f, 0.4f, 0.2f});  // in box 0
  addTriangle({5.0f, 0.5f, 0.5f}, {5.2f, 0.5f, 0.5f}, {5.1f, 0.6f, 0.5f});  // far from both
  // Two unit boxes: grid cell 1, bounds 2.5 cells long in x.
  std::vector<es::detail::FaceBox> boxes(2);
  for (int c = 0; c < 3; ++c) boxes[0].lo[c] = 0, boxes[0].hi[c] = 1;
  boxes[1] = boxes[0];
  boxes[1].lo[0] = 1.5, boxes[1].hi[0] = 2.5;
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> expected{{0, 1}, {1, 0}};
  // With and without the vertex flags (every face spans at most 0.2).
  for (const double stillExtent : {0.2, std::numeric_limits<double>::infinity()}) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> hits;
    es::detail::forEachBoxOverlap(
        m, boxes, [&](std::size_t v) { return es::detail::FaceBox(es::positionOf(&m.vert[v])); },
        std::vector<char>(m.vert.size(), 0), stillExtent,
        [&](int, std::uint32_t box, std::uint32_t face) { hits.emplace_back(box, face); });
    std::sort(hits.begin(), hits.end());
    EXPECT_EQ(hits, expected) << "stillExtent " << stillExtent;
  }
}

// The broad phase finds exactly the face/box pairs whose boxes overlap, as
// a test of every pair does: boxes around some faces of a marching-cubes
// sphere, some vertices moving along a segment, the vertex flags on.
TEST(IntersectionGuard, BoxOverlapMatchesEveryPairTest) {
  es::Mesh m;
  es::test_meshes::marchingCubes(es::test_meshes::shapeByName("sphere"), 0.08, m);
  ASSERT_GT(m.fn, 1000);
  std::vector<char> moving(m.vert.size(), 0);
  for (std::size_t v = 0; v < m.vert.size(); v += 37) moving[v] = 1;
  const auto vertexBox = [&](std::size_t v) {
    es::detail::FaceBox b(es::positionOf(&m.vert[v]));
    if (moving[v]) b.unite(es::detail::FaceBox(es::positionOf(&m.vert[v]) * 0.9));
    return b;
  };
  const auto faceBox = [&](std::size_t f) {
    es::detail::FaceBox b = vertexBox(vcg::tri::Index(m, m.face[f].cV(0)));
    for (int k = 1; k < 3; ++k) b.unite(vertexBox(vcg::tri::Index(m, m.face[f].cV(k))));
    return b;
  };
  double stillExtent = 0;
  std::vector<es::detail::FaceBox> boxes;
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    const es::detail::FaceBox b = faceBox(f);
    bool still = true;
    for (int k = 0; k < 3; ++k) still &= !moving[vcg::tri::Index(m, m.face[f].cV(k))];
    if (still)
      for (int c = 0; c < 3; ++c) stillExtent = std::max(stillExtent, b.hi[c] - b.lo[c]);
    if (f % 11 == 0) boxes.push_back(b);
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> expected, hits;
  for (std::size_t q = 0; q < boxes.size(); ++q)
    for (std::size_t f = 0; f < m.face.size(); ++f)
      if (faceBox(f).overlaps(boxes[q])) expected.emplace_back(q, f);
  es::detail::forEachBoxOverlap(m, boxes, vertexBox, moving, stillExtent,
                                [&](int, std::uint32_t q, std::uint32_t f) {
#pragma omp critical
                                  hits.emplace_back(q, f);
                                });
  std::sort(hits.begin(), hits.end());
  EXPECT_GT(expected.size(), boxes.size());
  EXPECT_EQ(hits, expected);
}
