// The test shapes: exact distance functions, exact reference meshes, and marching-cubes
// meshes that are clean closed manifolds with the chamfers the sharpener has to remove.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
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
void expectClosedOrientedManifold(M &mesh, const std::string &what, int genus = 0) {
  edge_sharpener::testing::expectClosedManifold(mesh, what, genus);
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
  for (const char *required :
       {"cube", "lblock", "wedge", "pyramid", "cross_prism", "cylinder_block", "sphere",
        "cylinder_cut", "cone_cut", "torus_cut", "two_cylinders"})
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
  expectClosedOrientedManifold(reference, "reference " + shape().name, shape().genus);
  // Polyhedra are exact; curved surfaces are inscribed, within the stated error.
  const double error = shape().referenceMaxError;
  EXPECT_LT(error, 1e-4 * shape().diagonal());
  EXPECT_NEAR(meshVolume(reference), shape().volume, 1e-12 + 1.5 * error * shape().area);
  EXPECT_NEAR(meshArea(reference), shape().area, 1e-12 + 4 * error / 0.45 * shape().area);
  // The float mesh type works as well.
  Mesh referenceFloat;
  shapes::buildReference(shape(), referenceFloat);
  expectClosedOrientedManifold(referenceFloat, "float reference " + shape().name, shape().genus);
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
  expectClosedOrientedManifold(mc, "marching cubes " + shape().name, shape().genus);
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

// The shapes with curved sharp edges (issue 60): a point of an edge with the unit outward
// normals of its two faces there, in the frame of the shape as allShapes() has it.
struct EdgePoint {
  Point3d point, normal1, normal2;
  bool convex;
};

std::vector<EdgePoint> curvedEdgePoints(const std::string &name) {
  namespace detail = shapes::detail;
  std::vector<EdgePoint> points;
  Point3d axis(1, 0, 0);
  double angle = 0;
  // 97 generic angles round each edge.
  const auto around = [](int i) { return 2 * M_PI * (i + 0.37) / 97; };
  if (name == "cylinder_cut") {
    const detail::CutCylinder &c = detail::cylinderCutParameters();
    const Point3d top = Point3d(-c.topSlope, 0, 1).Normalize();
    const Point3d bottom = Point3d(c.bottomSlope, 0, -1).Normalize();
    for (int i = 0; i < 97; ++i) {
      const double x = c.radius * std::cos(around(i)), y = c.radius * std::sin(around(i));
      const Point3d side(std::cos(around(i)), std::sin(around(i)), 0);
      points.push_back({Point3d(x, y, c.topAt(x)), side, top, true});
      points.push_back({Point3d(x, y, c.bottomAt(x)), side, bottom, true});
    }
  } else if (name == "cone_cut") {
    const detail::Frustum &f = detail::coneCutParameters();
    axis = f.axis;
    angle = f.angle;
    for (int i = 0; i < 97; ++i) {
      const double cosPhi = std::cos(around(i)), sinPhi = std::sin(around(i));
      // The flank's normal: the meridian's edge (Rt - Rb, h) turned clockwise.
      const Point3d flank =
          Point3d(f.height() * cosPhi, f.height() * sinPhi, f.bottomRadius - f.topRadius) /
          f.slantHeight();
      points.push_back({Point3d(f.bottomRadius * cosPhi, f.bottomRadius * sinPhi, f.bottomZ), flank,
                        Point3d(0, 0, -1), true});
      points.push_back({Point3d(f.topRadius * cosPhi, f.topRadius * sinPhi, f.topZ), flank,
                        Point3d(0, 0, 1), true});
    }
  } else if (name == "torus_cut") {
    const detail::CutTorus &t = detail::torusCutParameters();
    axis = t.axis;
    angle = t.angle;
    const double w = t.halfChord();
    for (int i = 0; i < 97; ++i) {
      const double cosPhi = std::cos(around(i)), sinPhi = std::sin(around(i));
      for (const double side : {1.0, -1.0}) {  // outer and inner rim
        const double rho = t.majorRadius + side * w;
        const Point3d tube = Point3d(side * w * cosPhi, side * w * sinPhi, t.cutZ) / t.minorRadius;
        points.push_back(
            {Point3d(rho * cosPhi, rho * sinPhi, t.cutZ), tube, Point3d(0, 0, 1), true});
      }
    }
  } else if (name == "two_cylinders") {
    const detail::TeeCylinders &c = detail::twoCylindersParameters();
    axis = c.axis;
    angle = c.angle;
    for (int i = 0; i < 97; ++i) {
      const double t = around(i);
      const Point3d boss(std::cos(t), std::sin(t), 0);
      const Point3d foot = c.curvePoint(t);
      points.push_back({foot, boss, Point3d(0, foot.Y(), foot.Z()) / c.mainRadius, false});
      points.push_back({Point3d(c.bossRadius * boss.X(), c.bossRadius * boss.Y(), c.bossTop), boss,
                        Point3d(0, 0, 1), true});
      const Point3d main(0, std::sin(t), std::cos(t));
      for (const double end : {-1.0, 1.0})
        points.push_back({Point3d(end * c.halfLength, 0, 0) + main * c.mainRadius, main,
                          Point3d(end, 0, 0), true});
    }
  }
  const Point3d unitAxis = axis / axis.Norm();
  for (EdgePoint &e : points) {
    e.point = shapes::detail::rotateRodrigues(e.point, unitAxis, angle);
    e.normal1 = shapes::detail::rotateRodrigues(e.normal1, unitAxis, angle);
    e.normal2 = shapes::detail::rotateRodrigues(e.normal2, unitAxis, angle);
  }
  return points;
}

/// vcglib's PointDistanceBase (GetClosestFaceBase) measures a point whose projection falls
/// outside a triangle against the first edge it finds outside of: on long thin triangles
/// (the curved shapes' strips) it can miss the nearer one. This functor for the grid's
/// GetClosest measures every triangle exactly.
struct ExactTriangleDistance {
  using QueryType = Point3d;
  static const Point3d &Pos(const Point3d &p) { return p; }
  template <class F>
  bool operator()(const F &f, const Point3d &p, double &minDist, Point3d &closest) const {
    const vcg::Triangle3<double> triangle(f.cP(0), f.cP(1), f.cP(2));
    double distance;
    Point3d nearest;
    vcg::TrianglePointDistance(triangle, p, distance, nearest);
    if (!(distance < minDist)) return false;
    minDist = distance;
    closest = nearest;
    return true;
  }
};

const char *const kCurvedEdgeShapes[] = {"cylinder_cut", "cone_cut", "torus_cut", "two_cylinders"};

// On each edge the distance is 0. A step d along the outward bisector b of the two normals
// leaves the edge point nearest on one side (outside a convex edge, inside a concave one): the
// distance is d. On the other side the faces are nearest, at d cos(beta) (beta: half the angle
// between the normals) from their tangent planes, up to their curvature: within d^2 / rho of
// it, rho = 0.3 being below every radius of curvature near the edges. Near the edges, where the
// patches' trimming decides, the distance is the one to the reference mesh.
TEST(MeshesCurvedEdgeShapes, SignedDistanceIsExactAtTheirEdges) {
  const double d = 1e-3, curvatureTolerance = d * d / 0.3;
  for (const char *name : kCurvedEdgeShapes) {
    SCOPED_TRACE(name);
    const shapes::Shape &shape = shapes::shapeByName(name);
    const std::vector<EdgePoint> edges = curvedEdgePoints(name);
    ASSERT_GE(edges.size(), 194u);
    MeshD reference;
    shapes::buildReference(shape, reference);
    vcg::GridStaticPtr<MeshD::FaceType, double> grid;
    grid.Set(reference.face.begin(), reference.face.end());
    std::mt19937 random(11);
    std::uniform_real_distribution<double> offset(-0.05, 0.05);
    double worstOnEdge = 0, worstNear = 0;
    for (const EdgePoint &e : edges) {
      ASSERT_NEAR(e.normal1.Norm(), 1.0, 1e-12);
      ASSERT_NEAR(e.normal2.Norm(), 1.0, 1e-12);
      const double onEdge = shape.signedDistance(e.point);
      worstOnEdge = std::max(worstOnEdge, std::abs(onEdge));
      ASSERT_LT(std::abs(onEdge), 1e-12)
          << "edge point " << e.point.X() << " " << e.point.Y() << " " << e.point.Z();
      const Point3d bisector = (e.normal1 + e.normal2).Normalize();
      const double cosBeta = bisector * e.normal1;
      ASSERT_GT(cosBeta, 0.3);  // a sharp edge, not a tangent contact
      const double outside = shape.signedDistance(e.point + bisector * d);
      const double inside = shape.signedDistance(e.point - bisector * d);
      if (e.convex) {
        EXPECT_NEAR(outside, d, 1e-12);
        EXPECT_LT(inside, 0);
        EXPECT_NEAR(inside, -d * cosBeta, curvatureTolerance);
      } else {
        EXPECT_NEAR(inside, -d, curvatureTolerance);
        EXPECT_GT(outside, 0);
        EXPECT_NEAR(outside, d * cosBeta, curvatureTolerance);
      }
      for (int k = 0; k < 3; ++k) {
        const Point3d p = e.point + Point3d(offset(random), offset(random), offset(random));
        double distance = 10;
        Point3d closest;
        vcg::tri::FaceTmark<MeshD> marker;
        marker.SetMesh(&reference);
        ExactTriangleDistance exact;
        ASSERT_NE(grid.GetClosest(exact, marker, p, 10.0, distance, closest), nullptr);
        const double error = std::abs(std::abs(shape.signedDistance(p)) - distance);
        worstNear = std::max(worstNear, error);
        ASSERT_LE(error, 1e-9 + shape.referenceMaxError)
            << "at " << p.X() << " " << p.Y() << " " << p.Z();
      }
    }
    std::printf(
        "%s: %zu edge points, max |sdf| on them %.2g; near them |sdf| - distance to the "
        "reference within %.2g (reference error %.2g)\n",
        name, edges.size(), worstOnEdge, worstNear, shape.referenceMaxError);
  }
}

// The reference meshes' vertices lie on the surface, and their faces within
// referenceMaxError of it (sampled at their centroids and near their corners).
TEST(MeshesCurvedEdgeShapes, ReferenceLiesWithinItsStatedError) {
  for (const char *name : kCurvedEdgeShapes) {
    SCOPED_TRACE(name);
    const shapes::Shape &shape = shapes::shapeByName(name);
    const shapes::TriangleList mesh = shape.referenceTriangles();
    for (const Point3d &v : mesh.vertices)
      ASSERT_LE(std::abs(shape.signedDistance(v)), shape.referenceMaxError + 1e-9);
    double worst = 0;
    for (const auto &t : mesh.triangles) {
      const Point3d &a = mesh.vertices[t[0]];
      const Point3d &b = mesh.vertices[t[1]];
      const Point3d &c = mesh.vertices[t[2]];
      for (const Point3d &weights :
           {Point3d(1, 1, 1) / 3, Point3d(0.6, 0.2, 0.2), Point3d(0.2, 0.6, 0.2),
            Point3d(0.2, 0.2, 0.6), Point3d(0.5, 0.5, 0), Point3d(0, 0.5, 0.5),
            Point3d(0.5, 0, 0.5)})
        worst = std::max(worst, std::abs(shape.signedDistance(a * weights[0] + b * weights[1] +
                                                              c * weights[2])));
    }
    std::printf(
        "%s: %zu faces, max |sdf| on them %.3g, stated bound %.3g (%.2g of the "
        "diagonal)\n",
        name, mesh.triangles.size(), worst, shape.referenceMaxError,
        shape.referenceMaxError / shape.diagonal());
    EXPECT_LE(worst, shape.referenceMaxError + 1e-12);
    EXPECT_GT(worst, 0.1 * shape.referenceMaxError);  // the bound is not far off either
  }
}

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
