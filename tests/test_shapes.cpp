// The test shapes: exact distance functions, exact reference meshes, and marching-cubes
// meshes that are clean closed manifolds with the chamfers the sharpener has to remove.
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh_distance.h"
#include "edge_sharpener/util/mesh_types.h"
#include "test_meshes/shapes.h"
#include "closed_manifold.h"
#include "same_mesh.h"
// (keep after the mesh headers)
#include <vcg/complex/algorithms/closest.h>
#include <vcg/complex/algorithms/inertia.h>
#include <vcg/complex/algorithms/stat.h>
#include <vcg/space/index/grid_static_ptr.h>

namespace {

using edge_sharpener::Mesh;
using edge_sharpener::MeshD;
namespace shapes = edge_sharpener::test_meshes;
using shapes::Point3d;

/// A closed solid's mesh (expectClosedManifold), with every vertex referenced and no
/// zero-area face.
template <class M>
void expectClosedOrientedManifold(M& mesh, const std::string& what) {
  edge_sharpener::testing::expectClosedManifold(mesh, what);
  SCOPED_TRACE(what);
  EXPECT_EQ(vcg::tri::Clean<M>::CountUnreferencedVertex(mesh), 0);
  for (const auto& f : mesh.face) EXPECT_GT(vcg::DoubleArea(f), 0) << "zero-area face";
}

template <class M>
double meshArea(M& mesh) {
  return vcg::tri::Stat<M>::ComputeMeshArea(mesh);
}

template <class M>
double meshVolume(M& mesh) {
  vcg::tri::Inertia<M> inertia(mesh);
  return inertia.Mass();
}

class ShapeTest : public ::testing::TestWithParam<std::string> {
 protected:
  const shapes::Shape& shape() const { return shapes::shapeByName(GetParam()); }
};

TEST(MeshesShapeRegistry, HasTheRequiredShapesWithSensibleSizes) {
  const std::vector<std::string> names = shapes::shapeNames();
  const std::set<std::string> unique(names.begin(), names.end());
  EXPECT_EQ(unique.size(), names.size());
  for (const char* required :
       {"cube", "lblock", "wedge", "pyramid", "cross_prism", "cylinder_block", "sphere"})
    EXPECT_EQ(unique.count(required), 1u) << required;
  for (const std::string& name : names) {
    const shapes::Shape& shape = shapes::shapeByName(name);
    EXPECT_EQ(shape.name, name);
    EXPECT_FALSE(shape.description.empty());
    EXPECT_GE(shape.bbox.Dim()[shape.bbox.MaxDim()], 0.99) << name;
    // Tilting stretches the L-block's box a little beyond 2.
    EXPECT_LE(shape.bbox.Dim()[shape.bbox.MaxDim()], 2.4) << name;
    EXPECT_EQ(shape.hasSharpFeatures, name != "sphere");
  }
}

TEST(MeshesShapeRegistry, UnknownNameThrows) {
  EXPECT_THROW(shapes::shapeByName("dodecahedron"), std::invalid_argument);
}

TEST(MeshesShapeRegistry, CellSizeHelpers) {
  const shapes::Shape& cube = shapes::shapeByName("cube");
  EXPECT_DOUBLE_EQ(shapes::cellSizeForDiagonalFraction(cube, 0.02), 0.02 * std::sqrt(3.0));
  EXPECT_EQ(shapes::percentLabel(0.02), "2");
  EXPECT_EQ(shapes::percentLabel(0.01), "1");
  EXPECT_EQ(shapes::percentLabel(0.005), "0.5");
}

TEST(MeshesSignedDistance, KnownValues) {
  const auto sdf = [](const char* name, double x, double y, double z) {
    return shapes::shapeByName(name).signedDistance(Point3d(x, y, z));
  };
  EXPECT_NEAR(sdf("cube", 0, 0, 0), -0.5, 1e-12);
  EXPECT_NEAR(sdf("cube", 1.5, 0, 0), 1.0, 1e-12);
  EXPECT_NEAR(sdf("cube", 1, 1, 0), std::sqrt(0.5), 1e-12);   // nearest point: an edge
  EXPECT_NEAR(sdf("cube", 1, 1, 1), std::sqrt(0.75), 1e-12);  // nearest point: a corner
  EXPECT_NEAR(sdf("lblock", 0.5, 0.5, 0), 0.5, 1e-12);        // in the notch
  EXPECT_NEAR(sdf("lblock", 0.1, 0.1, 0), 0.1, 1e-12);        // near the concave edge
  EXPECT_NEAR(sdf("lblock", -0.4, -0.4, 0), -0.4, 1e-12);
  EXPECT_NEAR(sdf("pyramid", 0, 0, 1.0), 0.4, 1e-12);  // above the apex
  EXPECT_NEAR(sdf("pyramid", 0, 0, -0.4), -0.1, 1e-12);
  EXPECT_NEAR(sdf("pyramid", 0, 0, -0.6), 0.1, 1e-12);
  EXPECT_NEAR(sdf("cylinder_block", 0, 0, 0.7), 0.2, 1e-12);
  EXPECT_NEAR(sdf("cylinder_block", 0.6, 0, 0.1), 0.1, 1e-12);
  // Under the boss the box top is not surface: the nearest surface is the boss side.
  EXPECT_NEAR(sdf("cylinder_block", 0, 0, 0), -0.45, 1e-12);
  EXPECT_NEAR(sdf("sphere", 0, 0, 0), -0.75, 1e-12);
  EXPECT_NEAR(sdf("cross_prism", 0, 0, 0), -0.3, 1e-12);
  EXPECT_NEAR(sdf("cross_prism", 0.6, 0.6, 0), 0.3, 1e-12);                // between two arms
  EXPECT_NEAR(sdf("cross_prism", 1.0, 0.4, 0.4), std::sqrt(0.03), 1e-12);  // past a corner
}

TEST(MeshesSignedDistance, RotatedShapeRotatesTheDistanceField) {
  const shapes::Shape& lblock = shapes::shapeByName("lblock");
  const shapes::Shape tilted = shapes::rotated(lblock, Point3d(0, 0, 1), M_PI / 2, "turned");
  EXPECT_EQ(tilted.name, "turned");
  // A quarter turn about z maps (x, y) to (-y, x).
  for (const Point3d& p : {Point3d(0.5, 0.5, 0), Point3d(-0.3, 0.7, 0.2), Point3d(1, -1, 1)})
    EXPECT_NEAR(tilted.signedDistance(Point3d(-p.Y(), p.X(), p.Z())), lblock.signedDistance(p),
                1e-12);
  EXPECT_NEAR(tilted.bbox.min.X(), -0.8, 1e-12);
  EXPECT_NEAR(tilted.bbox.max.Y(), 0.8, 1e-12);
}

TEST_P(ShapeTest, ReferenceIsClosedOrientedManifoldWithExactVolumeAndArea) {
  MeshD reference;
  shapes::buildReference(shape(), reference);
  expectClosedOrientedManifold(reference, "reference " + shape().name);
  // Polyhedra are exact; curved surfaces are inscribed, within the stated error.
  const double error = shape().referenceMaxError;
  EXPECT_LT(error, 1e-4 * shape().diagonal());
  EXPECT_NEAR(meshVolume(reference), shape().volume, 1e-12 + 1.5 * error * shape().area);
  EXPECT_NEAR(meshArea(reference), shape().area, 1e-12 + 4 * error / 0.45 * shape().area);
  // The float mesh type works as well.
  Mesh referenceFloat;
  shapes::buildReference(shape(), referenceFloat);
  expectClosedOrientedManifold(referenceFloat, "float reference " + shape().name);
}

TEST_P(ShapeTest, ReferenceLiesOnTheZeroSetAndFacesPointOutward) {
  MeshD reference;
  shapes::buildReference(shape(), reference);
  const double error = shape().referenceMaxError;
  for (const auto& v : reference.vert)
    ASSERT_NEAR(shape().signedDistance(v.cP()), 0.0, 1e-12) << "vertex off the surface";
  // Stepping off a face centroid along the normal leaves or enters the solid.
  const double step = 2 * error + 1e-5 * shape().diagonal();
  for (const auto& f : reference.face) {
    const Point3d centroid = vcg::Barycenter(f);
    ASSERT_LE(std::abs(shape().signedDistance(centroid)), error + 1e-12) << "face off the surface";
    const Point3d normal = vcg::NormalizedTriangleNormal(f);
    ASSERT_GT(shape().signedDistance(centroid + normal * step), 0);
    ASSERT_LT(shape().signedDistance(centroid - normal * step), 0);
  }
}

TEST_P(ShapeTest, DistanceFunctionIsTheDistanceToTheReferenceSurface) {
  MeshD reference;
  shapes::buildReference(shape(), reference);
  vcg::GridStaticPtr<MeshD::FaceType, double> grid;
  grid.Set(reference.face.begin(), reference.face.end());
  vcg::Box3d box = shape().bbox;
  box.Offset(0.25 * shape().diagonal());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int i = 0; i < 300; ++i) {
    const Point3d p(box.min.X() + unit(random) * box.DimX(),
                    box.min.Y() + unit(random) * box.DimY(),
                    box.min.Z() + unit(random) * box.DimZ());
    double distance = 0;
    Point3d closest;
    ASSERT_NE(vcg::tri::GetClosestFaceBase(reference, grid, p, 10.0, distance, closest), nullptr);
    ASSERT_NEAR(std::abs(shape().signedDistance(p)), distance, 1e-9 + shape().referenceMaxError)
        << "at " << p.X() << " " << p.Y() << " " << p.Z();
  }
}

TEST_P(ShapeTest, MarchingCubesIsACleanClosedManifoldCloseToTheShape) {
  const double cell = shapes::cellSizeForDiagonalFraction(shape(), 0.02);
  Mesh mc;
  shapes::marchingCubes(shape(), cell, mc);
  expectClosedOrientedManifold(mc, "marching cubes " + shape().name);
  for (const auto& v : mc.vert)
    ASSERT_LT(std::abs(shape().signedDistance(Point3d::Construct(v.cP()))), 0.5 * cell);
  // Chamfers cut sharp edges and fill concave ones: with cells of 2% of the diagonal they
  // take at most ~1.1% of the volume and ~6% of the area (measured), never add area. The
  // sphere's error is only the interpolation one.
  const bool sharp = shape().hasSharpFeatures;
  EXPECT_NEAR(meshVolume(mc), shape().volume, (sharp ? 0.02 : 0.005) * shape().volume);
  EXPECT_NEAR(meshArea(mc), shape().area, (sharp ? 0.08 : 0.005) * shape().area);
  EXPECT_LT(meshArea(mc), shape().area * (1 + 1e-3));
}

TEST_P(ShapeTest, MarchingCubesChamfersTheSharpFeaturesOnly) {
  const double cell = shapes::cellSizeForDiagonalFraction(shape(), 0.02);
  Mesh mc, reference;
  shapes::marchingCubes(shape(), cell, mc);
  shapes::buildReference(shape(), reference);
  edge_sharpener::DistanceOptions options;
  options.faceSamples = 50000;
  const edge_sharpener::DistanceReport distance =
      edge_sharpener::measureDistance(mc, reference, options);
  if (shape().hasSharpFeatures) {
    // Measured: 0.77 to 1.5 cells, at corners and along edges.
    EXPECT_GT(distance.max(), 0.4 * cell);
  } else {
    // Measured: 0.025 cells.
    EXPECT_LT(distance.max(), 0.05 * cell);
  }
  // Flat regions are reproduced exactly, so the RMS stays far below the worst case.
  EXPECT_LT(distance.rms(), 0.3 * cell);
}

TEST_P(ShapeTest, MarchingCubesIsDeterministic) {
  const double cell = shapes::cellSizeForDiagonalFraction(shape(), 0.02);
  Mesh first, second;
  shapes::marchingCubes(shape(), cell, first);
  shapes::marchingCubes(shape(), cell, second);
  ASSERT_EQ(first.vn, second.vn);
  ASSERT_EQ(first.fn, second.fn);
  ASSERT_TRUE(edge_sharpener::testing::sameMesh(first, second));
}

INSTANTIATE_TEST_SUITE_P(Meshes, ShapeTest, ::testing::ValuesIn(shapes::shapeNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

TEST(MeshesMarchingCubes, ChamfersShrinkWithTheCellSize) {
  const shapes::Shape& cube = shapes::shapeByName("cube");
  Mesh reference, coarse, fine;
  shapes::buildReference(cube, reference);
  shapes::marchingCubes(cube, shapes::cellSizeForDiagonalFraction(cube, 0.02), coarse);
  shapes::marchingCubes(cube, shapes::cellSizeForDiagonalFraction(cube, 0.01), fine);
  EXPECT_GT(fine.fn, 3 * coarse.fn);
  edge_sharpener::DistanceOptions options;
  options.faceSamples = 50000;
  const double coarseMax = edge_sharpener::measureDistance(coarse, reference, options).max();
  const double fineMax = edge_sharpener::measureDistance(fine, reference, options).max();
  EXPECT_LT(fineMax, 0.75 * coarseMax);
  EXPECT_GT(fineMax, 0.25 * coarseMax);
}

TEST(MeshesMarchingCubes, WorksInDoublePrecisionAndRejectsBadCellSizes) {
  const shapes::Shape& lblock = shapes::shapeByName("lblock");
  MeshD mc;
  shapes::marchingCubes(lblock, shapes::cellSizeForDiagonalFraction(lblock, 0.02), mc);
  expectClosedOrientedManifold(mc, "double lblock");
  EXPECT_NEAR(meshVolume(mc), lblock.volume, 0.02 * lblock.volume);
  EXPECT_THROW(shapes::marchingCubes(lblock, 0.0, mc), std::invalid_argument);
  EXPECT_THROW(shapes::marchingCubes(lblock, -1.0, mc), std::invalid_argument);
}

}  // namespace
