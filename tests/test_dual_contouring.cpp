// Dual contouring with exact Hermite data (test_meshes/dual_contouring.h): the QEF solve, exact
// corners and vertices on the surface of the sharp shapes, the grid of marchingCubes(), and the
// Metro distance far below marching cubes'.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "edge_sharpener/util/mesh_types.h"
#include "mesh_distance.h"
#include "test_meshes/dual_contouring.h"
#include "test_meshes/shapes.h"
#include "closed_manifold.h"
// (keep after the mesh headers)
#include <vcg/complex/algorithms/inertia.h>
#include <vcg/complex/algorithms/stat.h>

namespace {

using edge_sharpener::MeshD;
namespace shapes = edge_sharpener::test_meshes;
using shapes::Point3d;

using CellSet = std::set<std::tuple<int, int, int>>;

double maxAbsDistance(const shapes::Shape &shape, const shapes::TriangleList &mesh) {
  double worst = 0;
  for (const Point3d &p : mesh.vertices) worst = std::max(worst, std::abs(shape.signedDistance(p)));
  return worst;
}

using edge_sharpener::testing::expectClosedManifold;

TEST(MeshesDualContouring, QefKeepsOneTwoOrThreePlanes) {
  int rank = 0;
  // One plane z = 0.3: the mass point, which lies on it.
  std::vector<Point3d> points = {{0, 0, 0.3}, {1, 0, 0.3}, {0, 1, 0.3}};
  std::vector<Point3d> normals(3, Point3d(0, 0, 1));
  Point3d x = shapes::solveQef(points, normals, 0.1, &rank);
  EXPECT_EQ(rank, 1);
  EXPECT_LT((x - Point3d(1.0 / 3, 1.0 / 3, 0.3)).Norm(), 1e-15);
  // Two planes x = 0.2 and y = -0.1: their line's point nearest the mass point (z = 0.35).
  points = {{0.2, 0, 0}, {0.2, 1, 1}, {0.5, -0.1, 0.4}, {1, -0.1, 0}};
  normals = {{1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}};
  x = shapes::solveQef(points, normals, 0.1, &rank);
  EXPECT_EQ(rank, 2);
  EXPECT_LT((x - Point3d(0.2, -0.1, 0.35)).Norm(), 1e-15);
  // A third plane z = 0.7: the corner.
  points.push_back({0, 0, 0.7});
  normals.push_back({0, 0, 1});
  x = shapes::solveQef(points, normals, 0.1, &rank);
  EXPECT_EQ(rank, 3);
  EXPECT_LT((x - Point3d(0.2, -0.1, 0.7)).Norm(), 1e-15);
  // Two planes 2 degrees apart: truncated to one (near the mass point); without truncation
  // their line, far away.
  const double a = 2 * M_PI / 180;
  points = {{0, 0, 0}, {0, 0.1, 0}, {0.05, 0, 0.01}, {0.05, 0.1, 0.01}};
  normals = {{0, 0, 1}, {0, 0, 1}, {-std::sin(a), 0, std::cos(a)}, {-std::sin(a), 0, std::cos(a)}};
  x = shapes::solveQef(points, normals, 0.1, &rank);
  EXPECT_EQ(rank, 1);
  EXPECT_LT((x - Point3d(0.025, 0.05, 0.005)).Norm(), 0.01);
  x = shapes::solveQef(points, normals, 0, &rank);
  EXPECT_EQ(rank, 2);
  EXPECT_GT((x - Point3d(0.025, 0.05, 0.005)).Norm(), 0.1);
}

TEST(MeshesDualContouring, CubeCornersAreExactAndTheMeshIsAClosedManifold) {
  const shapes::Shape &cube = shapes::shapeByName("cube");
  const double diagonal = cube.diagonal();
  for (double fraction : {0.02, 0.01}) {
    SCOPED_TRACE(fraction);
    const shapes::DualContouringResult dc =
        shapes::dualContour(cube, shapes::cellSizeForDiagonalFraction(cube, fraction));
    double worstCorner = 0;
    for (int corner = 0; corner < 8; ++corner) {
      const Point3d exact((corner & 1) ? 0.5 : -0.5, (corner & 2) ? 0.5 : -0.5,
                          (corner & 4) ? 0.5 : -0.5);
      double nearest = std::numeric_limits<double>::infinity();
      for (const Point3d &p : dc.mesh.vertices) nearest = std::min(nearest, (p - exact).Norm());
      EXPECT_LT(nearest, 1e-9 * diagonal) << "corner " << corner;
      worstCorner = std::max(worstCorner, nearest);
    }
    std::printf("cube at %g%%: worst corner error %.3g of the diagonal\n", 100 * fraction,
                worstCorner / diagonal);
    EXPECT_EQ(std::count(dc.vertexRank.begin(), dc.vertexRank.end(), 3), 8);
    MeshD mesh;
    shapes::toVcgMesh(dc.mesh, mesh);
    expectClosedManifold(mesh, "cube");
    // The exact cube: unit volume and area 6.
    vcg::tri::Inertia<MeshD> inertia(mesh);
    EXPECT_NEAR(inertia.Mass(), 1.0, 1e-9);
    EXPECT_NEAR(vcg::tri::Stat<MeshD>::ComputeMeshArea(mesh), 6.0, 1e-9);
  }
}

class DualContouringSharpShape : public ::testing::TestWithParam<std::string> {};

TEST_P(DualContouringSharpShape, VerticesLieOnTheExactSurface) {
  const shapes::Shape &shape = shapes::shapeByName(GetParam());
  for (double fraction : {0.02, 0.01}) {
    SCOPED_TRACE(fraction);
    const shapes::DualContouringResult dc =
        shapes::dualContour(shape, shapes::cellSizeForDiagonalFraction(shape, fraction));
    const double worst = maxAbsDistance(shape, dc.mesh);
    std::printf("%s at %g%%: max |sdf| at the vertices %.3g of the diagonal\n", shape.name.c_str(),
                100 * fraction, worst / shape.diagonal());
    EXPECT_LT(worst, 1e-6 * shape.diagonal());
    // The features are there: vertices on edges and at corners.
    EXPECT_GT(std::count(dc.vertexRank.begin(), dc.vertexRank.end(), 2), 20);
    EXPECT_GE(std::count(dc.vertexRank.begin(), dc.vertexRank.end(), 3), 4);
    MeshD mesh;
    shapes::toVcgMesh(dc.mesh, mesh);
    expectClosedManifold(mesh, shape.name);
    vcg::tri::Inertia<MeshD> inertia(mesh);
    EXPECT_NEAR(inertia.Mass(), shape.volume, 1e-9 * shape.volume);
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, DualContouringSharpShape,
                         ::testing::Values("cube", "lblock", "wedge", "pyramid"));

TEST(MeshesDualContouring, ClampingPullsVerticesOffTheSurface) {
  // On the pyramid some minimisers (on its edges' lines, at its corners) lie outside their
  // cells; clamped into them, they leave the surface. (On the wedge they only slide along a
  // cap: its edges outside their cells lie in the caps' planes.)
  const shapes::Shape &pyramid = shapes::shapeByName("pyramid");
  const double h = shapes::cellSizeForDiagonalFraction(pyramid, 0.01);
  shapes::DualContouringOptions clamped;
  clamped.clampToCell = true;
  const shapes::DualContouringResult free = shapes::dualContour(pyramid, h);
  const shapes::DualContouringResult dc = shapes::dualContour(pyramid, h, clamped);
  EXPECT_GT(free.verticesOutsideCell, 0u);
  EXPECT_EQ(dc.verticesOutsideCell, free.verticesOutsideCell);
  const shapes::SamplingGrid grid = shapes::marchingCubesGrid(pyramid, h);
  for (std::size_t v = 0; v < dc.mesh.vertices.size(); ++v) {
    const vcg::Point3i &cell = dc.vertexCell[v];
    const Point3d lo = grid.node(cell[0], cell[1], cell[2]);
    for (int i = 0; i < 3; ++i) {
      ASSERT_GE(dc.mesh.vertices[v][i], lo[i]);
      ASSERT_LE(dc.mesh.vertices[v][i], lo[i] + h * (1 + 1e-12));
    }
  }
  const double freeError = maxAbsDistance(pyramid, free.mesh);
  const double clampedError = maxAbsDistance(pyramid, dc.mesh);
  std::printf(
      "pyramid at 1%%: %zu minimisers outside their cell (up to %.3g cells); max |sdf| "
      "%.3g free, %.3g clamped (of the diagonal)\n",
      free.verticesOutsideCell, free.maxOutsideDistance, freeError / pyramid.diagonal(),
      clampedError / pyramid.diagonal());
  EXPECT_LT(freeError, 1e-6 * pyramid.diagonal());
  EXPECT_GT(clampedError, 1e-4 * pyramid.diagonal());
}

TEST(MeshesDualContouring, SphereVerticesLieWithinASmallFractionOfACell) {
  const shapes::Shape &sphere = shapes::shapeByName("sphere");
  for (double fraction : {0.02, 0.01}) {
    SCOPED_TRACE(fraction);
    const double h = shapes::cellSizeForDiagonalFraction(sphere, fraction);
    const shapes::DualContouringResult dc = shapes::dualContour(sphere, h);
    const double worst = maxAbsDistance(sphere, dc.mesh);
    std::printf("sphere at %g%%: max |sdf| at the vertices %.3g cells\n", 100 * fraction,
                worst / h);
    EXPECT_LT(worst, 0.05 * h);
    // Only smooth surface: no vertex is taken for an edge or a corner.
    EXPECT_EQ(std::count(dc.vertexRank.begin(), dc.vertexRank.end(), 1),
              static_cast<long>(dc.vertexRank.size()));
    MeshD mesh;
    shapes::toVcgMesh(dc.mesh, mesh);
    expectClosedManifold(mesh, "sphere");
  }
}

/// The cells (minimum nodes on `grid`) that hold the centroids of `mesh`'s faces.
template <class M>
CellSet cellsOfFaces(const M &mesh, const shapes::SamplingGrid &grid) {
  CellSet cells;
  for (const auto &f : mesh.face) {
    const Point3d c =
        (Point3d::Construct(f.cP(0)) + Point3d::Construct(f.cP(1)) + Point3d::Construct(f.cP(2))) /
        3;
    const Point3d g = (c - grid.origin) / grid.cellSize;
    cells.emplace(int(std::floor(g[0])), int(std::floor(g[1])), int(std::floor(g[2])));
  }
  return cells;
}

CellSet cellsOfVertices(const shapes::DualContouringResult &dc) {
  CellSet cells;
  for (const vcg::Point3i &c : dc.vertexCell) cells.emplace(c[0], c[1], c[2]);
  return cells;
}

TEST(MeshesDualContouring, SameGridAsMarchingCubes) {
  for (const char *name : {"cube", "lblock_tilted", "sphere"}) {
    SCOPED_TRACE(name);
    const shapes::Shape &shape = shapes::shapeByName(name);
    const double h = shapes::cellSizeForDiagonalFraction(shape, 0.02);
    const shapes::SamplingGrid grid = shapes::marchingCubesGrid(shape, h);
    MeshD mc;
    shapes::marchingCubes(shape, h, mc);
    // Every marching-cubes vertex lies on an edge of the grid: two coordinates on grid planes
    // (up to marching cubes' float arithmetic).
    for (const auto &v : mc.vert) {
      const Point3d g = (Point3d::Construct(v.cP()) - grid.origin) / h;
      int onPlanes = 0;
      for (int i = 0; i < 3; ++i)
        if (std::abs(g[i] - std::round(g[i])) < 1e-4) ++onPlanes;
      ASSERT_GE(onPlanes, 2) << g[0] << " " << g[1] << " " << g[2];
    }
    // DC has a vertex in exactly the cells marching cubes' faces pass through.
    const shapes::DualContouringResult dc = shapes::dualContour(shape, h);
    const CellSet mcCells = cellsOfFaces(mc, grid);
    const CellSet dcCells = cellsOfVertices(dc);
    EXPECT_EQ(dc.mesh.vertices.size(), dcCells.size());
    EXPECT_EQ(dcCells.size(), mcCells.size());
    EXPECT_TRUE(dcCells == mcCells);
    // (the check can fail: on a grid shifted by half a cell the cells differ)
    shapes::SamplingGrid shifted = grid;
    shifted.origin += Point3d(0.5, 0.5, 0.5) * h;
    const CellSet shiftedCells =
        cellsOfVertices(shapes::dualContour(shape.signedDistance, {}, shifted));
    EXPECT_FALSE(shiftedCells == mcCells);
  }
}

TEST(MeshesDualContouring, MetroErrorIsFarBelowMarchingCubes) {
  for (const char *name : {"cube", "lblock"}) {
    SCOPED_TRACE(name);
    const shapes::Shape &shape = shapes::shapeByName(name);
    const double h = shapes::cellSizeForDiagonalFraction(shape, 0.01);
    MeshD reference, mc, dcMesh;
    shapes::buildReference(shape, reference);
    shapes::marchingCubes(shape, h, mc);
    shapes::toVcgMesh(shapes::dualContour(shape, h).mesh, dcMesh);
    const edge_sharpener::DistanceReport mcReport = edge_sharpener::measureDistance(mc, reference);
    const edge_sharpener::DistanceReport dcReport =
        edge_sharpener::measureDistance(dcMesh, reference);
    std::printf(
        "%s at 1%%: Metro max %.3g%% of the diagonal for marching cubes, %.3g%% for dual "
        "contouring\n",
        name, mcReport.maxPercent(), dcReport.maxPercent());
    EXPECT_GT(mcReport.maxPercent(), 0.1);
    EXPECT_LT(dcReport.max(), 0.01 * mcReport.max());
  }
}

}  // namespace
