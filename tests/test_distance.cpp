// measureDistance: the project's Metro, checked on configurations whose distances are known.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mesh_distance.h"
#include "edge_sharpener/util/mesh_types.h"
#include "test_meshes/shapes.h"
// (keep after the mesh headers)
#include <vcg/complex/algorithms/update/position.h>
#include <vcg/complex/append.h>

namespace {

using edge_sharpener::DistanceOptions;
using edge_sharpener::DistanceReport;
using edge_sharpener::measureDistance;
using edge_sharpener::Mesh;
using edge_sharpener::MeshD;
namespace shapes = edge_sharpener::test_meshes;
using shapes::Point3d;

template <class M>
void translate(M& mesh, const Point3d& offset) {
  for (auto& v : mesh.vert) v.P() += M::CoordType::Construct(offset);
  vcg::tri::UpdateBounding<M>::Box(mesh);
}

/// Unit square [0,1]^2 with vertex heights z = slope * x + height (two triangles).
void tiltedSquare(MeshD& mesh, double slope, double height) {
  mesh.Clear();
  auto v = vcg::tri::Allocator<MeshD>::AddVertices(mesh, 4);
  const double xs[4] = {0, 1, 1, 0}, ys[4] = {0, 0, 1, 1};
  for (int i = 0; i < 4; ++i) v[i].P() = Point3d(xs[i], ys[i], slope * xs[i] + height);
  vcg::tri::Allocator<MeshD>::AddFace(mesh, &mesh.vert[0], &mesh.vert[1], &mesh.vert[2]);
  vcg::tri::Allocator<MeshD>::AddFace(mesh, &mesh.vert[0], &mesh.vert[2], &mesh.vert[3]);
}

/// A square much larger than the unit square, on the plane z = slope * x + height.
void largeTiltedSquare(MeshD& mesh, double slope, double height) {
  tiltedSquare(mesh, slope, height);
  for (auto& v : mesh.vert) {
    v.P().X() = 4 * v.P().X() - 1.5;
    v.P().Y() = 4 * v.P().Y() - 1.5;
    v.P().Z() = slope * v.P().X() + height;
  }
  vcg::tri::UpdateBounding<MeshD>::Box(mesh);
}

DistanceOptions fastOptions() {
  DistanceOptions options;
  options.faceSamples = 50000;
  return options;
}

/// `name`'s exact shape in `reference` and, in `mc`, sampled by marching cubes at 2% of its
/// diagonal.
const shapes::Shape& sampledAndExact(const char* name, Mesh& mc, Mesh& reference) {
  const shapes::Shape& shape = shapes::shapeByName(name);
  shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, 0.02), mc);
  shapes::buildReference(shape, reference);
  return shape;
}

TEST(MeshesDistance, MeshToItselfIsZero) {
  Mesh mc, copy;
  const shapes::Shape& lblock = shapes::shapeByName("lblock");
  shapes::marchingCubes(lblock, shapes::cellSizeForDiagonalFraction(lblock, 0.02), mc);
  vcg::tri::Append<Mesh, Mesh>::MeshCopy(copy, mc);
  for (Mesh* other : {&copy, &mc}) {
    const DistanceReport report = measureDistance(mc, *other, fastOptions());
    EXPECT_LT(report.max(), 1e-6);
    EXPECT_LT(report.rms(), 1e-7);
    EXPECT_GT(report.forward.samples, 50000u);
    EXPECT_GT(report.backward.samples, 50000u);
  }
}

TEST(MeshesDistance, TranslatedCubeIsAtTheTranslationDistance) {
  const shapes::Shape& cube = shapes::shapeByName("cube");
  for (double d : {0.01, 0.05, 0.2}) {
    Mesh reference, moved;
    shapes::buildReference(cube, reference);
    shapes::buildReference(cube, moved);
    translate(moved, Point3d(d, 0, 0));
    const DistanceReport report = measureDistance(moved, reference, fastOptions());
    // The moved +x face is d outside the reference, the reference's -x face d outside the
    // moved cube; nothing is farther.
    EXPECT_NEAR(report.forward.max, d, 1e-6) << d;
    EXPECT_NEAR(report.backward.max, d, 1e-6) << d;
    EXPECT_NEAR(report.max(), d, 1e-6);
    EXPECT_LT(report.forward.min, 1e-6);
    EXPECT_LT(report.mean(), d);
    // The configuration is symmetric.
    EXPECT_NEAR(report.forward.mean, report.backward.mean, 0.05 * report.forward.mean);
    EXPECT_NEAR(report.referenceDiagonal, std::sqrt(3.0), 1e-6);  // float bounding box
    EXPECT_NEAR(report.maxPercent(), 100 * d / std::sqrt(3.0), 1e-4);
  }
}

TEST(MeshesDistance, ParallelSquaresAreAtConstantDistance) {
  MeshD a, b;
  tiltedSquare(a, 0, 0);
  tiltedSquare(b, 0, 0.3);
  const DistanceReport report = measureDistance(a, b, fastOptions());
  for (const auto& side : {report.forward, report.backward}) {
    EXPECT_NEAR(side.min, 0.3, 1e-12);
    EXPECT_NEAR(side.max, 0.3, 1e-12);
    EXPECT_NEAR(side.mean, 0.3, 1e-12);
    EXPECT_NEAR(side.rms, 0.3, 1e-12) << "RMS is the root of the mean square";
  }
}

TEST(MeshesDistance, MeanAndRmsOfALinearlyGrowingDistance) {
  // Points of the unit square at z = 0 are at (height + slope x) / sqrt(1 + slope^2) from
  // the plane z = slope x + height; x is uniform on the square.
  const double slope = 0.1, height = 0.1;
  MeshD a, b;
  tiltedSquare(a, 0, 0);
  largeTiltedSquare(b, slope, height);
  DistanceOptions faceOnly = fastOptions();
  faceOnly.sampleVertices = false;
  faceOnly.sampleEdges = false;
  const DistanceReport report = measureDistance(a, b, faceOnly);
  const double norm = std::sqrt(1 + slope * slope);
  const double mean = (height + slope / 2) / norm;
  const double meanSquare = (height * height + height * slope + slope * slope / 3) / norm / norm;
  EXPECT_NEAR(report.forward.min, height / norm, 1e-3);
  EXPECT_NEAR(report.forward.max, (height + slope) / norm, 1e-3);
  EXPECT_NEAR(report.forward.mean, mean, 1e-3 * mean);
  EXPECT_NEAR(report.forward.rms, std::sqrt(meanSquare), 1e-3 * mean);
  EXPECT_EQ(report.forward.samples, 50000u);
}

TEST(MeshesDistance, SymmetricValuesCombineBothSides) {
  Mesh mc, reference;
  const shapes::Shape& wedge = sampledAndExact("wedge", mc, reference);
  const DistanceReport report = measureDistance(mc, reference, fastOptions());
  const auto& f = report.forward;
  const auto& b = report.backward;
  EXPECT_LE(f.min, f.mean);
  EXPECT_LE(f.mean, f.rms);
  EXPECT_LE(f.rms, f.max);
  EXPECT_LE(b.mean, b.rms);
  EXPECT_LE(b.rms, b.max);
  EXPECT_DOUBLE_EQ(report.max(), std::max(f.max, b.max));
  EXPECT_DOUBLE_EQ(report.mean(), (f.mean + b.mean) / 2);
  EXPECT_DOUBLE_EQ(report.rms(), std::sqrt((f.rms * f.rms + b.rms * b.rms) / 2));
  // The diagonal is the one of the reference mesh's (float) bounding box.
  const double diagonal = report.referenceDiagonal;
  EXPECT_NEAR(diagonal, wedge.diagonal(), 1e-6);
  EXPECT_DOUBLE_EQ(report.maxPercent(), 100 * report.max() / diagonal);
  EXPECT_DOUBLE_EQ(report.meanPercent(), 100 * report.mean() / diagonal);
  EXPECT_DOUBLE_EQ(report.rmsPercent(), 100 * report.rms() / diagonal);
  EXPECT_DOUBLE_EQ(report.percentOfDiagonal(diagonal), 100);

  // Swapping the meshes swaps the sides (each side reseeds the generator).
  const DistanceReport swapped = measureDistance(reference, mc, fastOptions());
  EXPECT_EQ(swapped.forward.samples, b.samples);
  EXPECT_DOUBLE_EQ(swapped.forward.max, b.max);
  EXPECT_DOUBLE_EQ(swapped.forward.mean, b.mean);
  EXPECT_DOUBLE_EQ(swapped.backward.rms, f.rms);
}

TEST(MeshesDistance, DeterministicForASeedAndSampleCountsFollowTheOptions) {
  Mesh mc, reference;
  sampledAndExact("pyramid", mc, reference);
  const DistanceReport first = measureDistance(mc, reference, fastOptions());
  const DistanceReport again = measureDistance(mc, reference, fastOptions());
  EXPECT_EQ(first.forward.samples, again.forward.samples);
  EXPECT_EQ(first.forward.mean, again.forward.mean);
  EXPECT_EQ(first.forward.max, again.forward.max);
  EXPECT_EQ(first.backward.rms, again.backward.rms);

  DistanceOptions otherSeed = fastOptions();
  otherSeed.seed = 12345;
  const DistanceReport other = measureDistance(mc, reference, otherSeed);
  EXPECT_NE(first.forward.mean, other.forward.mean);
  EXPECT_NEAR(first.forward.mean, other.forward.mean, 0.05 * first.forward.mean);

  // Vertices, a quarter of the face samples on edges, the face samples over the area
  // (FaceSubdivision can miss a few to rounding).
  const std::size_t expected = mc.vn + 50000 / 4 + 50000;
  EXPECT_NEAR(double(first.forward.samples), double(expected), 0.002 * expected);
  DistanceOptions verticesOnly = fastOptions();
  verticesOnly.sampleEdges = verticesOnly.sampleFaces = false;
  EXPECT_EQ(measureDistance(mc, reference, verticesOnly).forward.samples, std::size_t(mc.vn));
}

TEST(MeshesDistance, LeavesPositionsUntouched) {
  Mesh mc, reference;
  sampledAndExact("cylinder_block", mc, reference);
  std::vector<Mesh::CoordType> before;
  for (const auto& v : mc.vert) before.push_back(v.cP());
  for (const auto& v : reference.vert) before.push_back(v.cP());
  std::vector<float> qualityBefore;
  for (const auto& v : mc.vert) qualityBefore.push_back(v.cQ());
  measureDistance(mc, reference, fastOptions());
  std::size_t i = 0;
  for (const auto& v : mc.vert) ASSERT_EQ(v.cP(), before[i++]);
  for (const auto& v : reference.vert) ASSERT_EQ(v.cP(), before[i++]);
  for (std::size_t k = 0; k < mc.vert.size(); ++k) ASSERT_EQ(mc.vert[k].cQ(), qualityBefore[k]);
}

}  // namespace

// Found by the quality benchmark: MeshLab's isotropic remeshing can collapse a
// shape to coincident vertices, and vcglib's area-proportional sampling never
// ends on a mesh without area. Refused, on either side.
TEST(MeshesDistance, MeshWithoutAreaIsRefused) {
  MeshD collapsed, square;
  tiltedSquare(square, 0.0, 0.0);
  collapsed.Clear();
  auto v = vcg::tri::Allocator<MeshD>::AddVertices(collapsed, 4);
  for (int i = 0; i < 4; ++i) v[i].P() = Point3d(0.5, 0.5, 0.25);
  auto& cv = collapsed.vert;
  vcg::tri::Allocator<MeshD>::AddFace(collapsed, &cv[2], &cv[1], &cv[0]);
  vcg::tri::Allocator<MeshD>::AddFace(collapsed, &cv[2], &cv[3], &cv[1]);
  vcg::tri::Allocator<MeshD>::AddFace(collapsed, &cv[3], &cv[2], &cv[0]);
  vcg::tri::Allocator<MeshD>::AddFace(collapsed, &cv[1], &cv[3], &cv[0]);
  EXPECT_THROW(measureDistance(collapsed, square), std::invalid_argument);
  EXPECT_THROW(measureDistance(square, collapsed), std::invalid_argument);
  EXPECT_NO_THROW(measureDistance(square, square));
}

// Found by the quality benchmark (block, Screened Poisson): vcglib's closest-face grid spans
// the reference alone, and a sample point just inside its far border was rounded into a cell
// past the grid's end (a crash).
TEST(MeshesDistance, SamplePointOnTheFarBorderOfTheSearchGrid) {
  using Coord = Mesh::CoordType;
  Mesh reference, sampled;
  auto v = vcg::tri::Allocator<Mesh>::AddVertices(reference, 4);
  const float xs[4] = {0, 10, 10, 0}, ys[4] = {0, 0, 10, 10};
  for (int i = 0; i < 4; ++i) v[i].P() = Coord(xs[i], ys[i], 0);
  auto &rv = reference.vert;
  vcg::tri::Allocator<Mesh>::AddFace(reference, &rv[0], &rv[1], &rv[2]);
  vcg::tri::Allocator<Mesh>::AddFace(reference, &rv[0], &rv[2], &rv[3]);

  // The grid vcglib builds on the reference alone, and a point above the square, inside
  // that grid, which its cell lookup rounds past the grid's top.
  vcg::GridStaticPtr<Mesh::FaceType, float> grid;
  grid.Set(reference.face.begin(), reference.face.end());
  Coord top(5, 5, grid.bbox.max[2]);
  vcg::Point3i cell(0, 0, 0);
  for (int step = 0; step < 64 && cell[2] != grid.siz[2]; ++step) {
    top[2] = std::nextafter(top[2], 0.0f);
    grid.PToIP(top, cell);
  }
  ASSERT_TRUE(grid.bbox.IsInEx(top));
  ASSERT_EQ(cell[2], grid.siz[2]) << "no float rounds onto the border: the test sees no risk";

  auto s = vcg::tri::Allocator<Mesh>::AddVertices(sampled, 3);
  s[0].P() = top;
  s[1].P() = top - Coord(1, 0, 0);
  s[2].P() = top - Coord(1, 1, 0);
  vcg::tri::Allocator<Mesh>::AddFace(sampled, &sampled.vert[0], &sampled.vert[1], &sampled.vert[2]);
  const DistanceReport report = measureDistance(sampled, reference, fastOptions());
  EXPECT_NEAR(report.forward.max, top[2], 1e-4);
  EXPECT_NEAR(report.forward.min, top[2], 1e-4);
}
