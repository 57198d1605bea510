// Test solids with sharp features and exact ground truth, and their marching-cubes
// (chamfered) versions: the inputs and the references of the edge-sharpening tests.
//
// Every shape has
//  - an exact signed Euclidean distance function (negative inside);
//  - an exact volume and surface area;
//  - a reference triangle mesh: polyhedra are triangulated exactly (the mesh *is* the
//    surface); curved surfaces are tessellated with a maximum distance from the exact
//    surface below 1e-4 of the bounding-box diagonal (`Shape::referenceMaxError` gives it);
//  - a tight bounding box, sizes 1-2 units.
// The shapes with curved sharp edges (cylinder_cut, cone_cut, torus_cut, two_cylinders) have
// their distance as the smallest one to their trimmed boundary patches (see below), and
// diagonals of 2.3 to 3 units.
// `marchingCubes()` samples the distance function on a regular grid whose planes are
// offset from every feature, so sharp edges and corners come out chamfered, as in
// real scanned-and-remeshed data.
#pragma once

#include <vcg/complex/complex.h>
// (vcglib's algorithm headers need complex.h first)
#include <vcg/complex/algorithms/clean.h>
// TrivialWalker::Exist leaves an index unset on a path that never runs.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <vcg/complex/algorithms/create/marching_cubes.h>
#include <vcg/complex/algorithms/create/mc_trivial_walker.h>
#pragma GCC diagnostic pop
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/space/distance3.h>
#include <vcg/space/triangle3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace edge_sharpener {
namespace test_meshes {

using Point2d = vcg::Point2d;
using Point3d = vcg::Point3d;

/// An indexed triangle mesh in double precision, independent of any vcg mesh type.
struct TriangleList {
  std::vector<Point3d> vertices;
  std::vector<std::array<int, 3>> triangles;

  int addVertex(const Point3d& p) {
    vertices.push_back(p);
    return static_cast<int>(vertices.size()) - 1;
  }
  void addTriangle(int a, int b, int c) { triangles.push_back({a, b, c}); }
  /// Planar convex quad a-b-c-d (counter-clockwise seen from outside).
  void addQuad(int a, int b, int c, int d) {
    addTriangle(a, b, c);
    addTriangle(a, c, d);
  }
  /// The side band between two rings of vertices (counter-clockwise seen from the top),
  /// closed by fans from `topCenter` and `bottomCenter` (negative: left open, a boss
  /// standing on another surface).
  void addCappedBand(const std::vector<int>& bottom, const std::vector<int>& top, int bottomCenter,
                     int topCenter) {
    const std::size_t n = top.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t next = (k + 1) % n;
      addTriangle(topCenter, top[k], top[next]);
      if (bottomCenter >= 0) addTriangle(bottomCenter, bottom[next], bottom[k]);
      addQuad(bottom[k], bottom[next], top[next], top[k]);
    }
  }
};

struct Shape {
  std::string name;
  std::string description;
  /// Tight bounding box of the exact solid.
  vcg::Box3d bbox;
  /// Exact volume and surface area of the solid (not of its tessellation).
  double volume = 0;
  double area = 0;
  /// False only for shapes without creases or corners (the sphere): the sharpener must
  /// leave their marching-cubes meshes alone.
  bool hasSharpFeatures = true;
  /// Genus of the surface (the number of handles): 1 for the cut torus, 0 for the others.
  int genus = 0;
  /// Largest distance between the reference mesh and the exact surface: 0 for polyhedra.
  double referenceMaxError = 0;
  /// Exact signed Euclidean distance to the surface, negative inside.
  std::function<double(const Point3d&)> signedDistance;
  /// Closed, outward-oriented, 2-manifold triangulation of the surface.
  std::function<TriangleList()> referenceTriangles;

  double diagonal() const { return bbox.Diag(); }
};

namespace detail {

inline double dot2(const Point2d& a, const Point2d& b) { return a.X() * b.X() + a.Y() * b.Y(); }

inline double segmentDistanceSquared2d(const Point2d& p, const Point2d& a, const Point2d& b) {
  const Point2d ab = b - a;
  const double t = std::clamp(dot2(p - a, ab) / dot2(ab, ab), 0.0, 1.0);
  const Point2d closest = a + ab * t;
  return dot2(p - closest, p - closest);
}

/// Exact signed distance to a simple polygon (inside by crossing number).
inline double polygonSignedDistance(const std::vector<Point2d>& polygon, const Point2d& p) {
  double best = std::numeric_limits<double>::infinity();
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Point2d& a = polygon[j];
    const Point2d& b = polygon[i];
    best = std::min(best, segmentDistanceSquared2d(p, a, b));
    if ((a.Y() > p.Y()) != (b.Y() > p.Y())) {
      const double xCross = a.X() + (p.Y() - a.Y()) * (b.X() - a.X()) / (b.Y() - a.Y());
      if (p.X() < xCross) inside = !inside;
    }
  }
  return inside ? -std::sqrt(best) : std::sqrt(best);
}

/// A polygon in the xy plane extruded along z over [zMin, zMax].
struct Prism {
  std::vector<Point2d> outline;  // counter-clockwise, simple
  Point2d fanCenter;             // strictly inside the polygon's kernel: caps are fans from it
  double zMin = 0, zMax = 0;

  double polygonArea() const {
    double twiceArea = 0;
    for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++)
      twiceArea += outline[j].X() * outline[i].Y() - outline[i].X() * outline[j].Y();
    return 0.5 * twiceArea;
  }
  double perimeter() const {
    double length = 0;
    for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++)
      length += (outline[i] - outline[j]).Norm();
    return length;
  }
  double height() const { return zMax - zMin; }

  /// Exact for an exact 2D distance: the distance to the extrusion combines the in-plane
  /// and the axial excess like a 2D box.
  double signedDistance(const Point3d& p) const {
    const double inPlane = polygonSignedDistance(outline, Point2d(p.X(), p.Y()));
    const double axial = std::abs(p.Z() - 0.5 * (zMin + zMax)) - 0.5 * height();
    return std::min(std::max(inPlane, axial), 0.0) +
           std::hypot(std::max(inPlane, 0.0), std::max(axial, 0.0));
  }

  TriangleList triangles() const {
    TriangleList mesh;
    const int n = static_cast<int>(outline.size());
    std::vector<int> bottom(n), top(n);
    for (int i = 0; i < n; ++i) {
      bottom[i] = mesh.addVertex(Point3d(outline[i].X(), outline[i].Y(), zMin));
      top[i] = mesh.addVertex(Point3d(outline[i].X(), outline[i].Y(), zMax));
    }
    const int bottomCenter = mesh.addVertex(Point3d(fanCenter.X(), fanCenter.Y(), zMin));
    const int topCenter = mesh.addVertex(Point3d(fanCenter.X(), fanCenter.Y(), zMax));
    mesh.addCappedBand(bottom, top, bottomCenter, topCenter);
    return mesh;
  }

  vcg::Box3d bbox() const {
    vcg::Box3d box;
    for (const Point2d& q : outline) {
      box.Add(Point3d(q.X(), q.Y(), zMin));
      box.Add(Point3d(q.X(), q.Y(), zMax));
    }
    return box;
  }
};

/// The prism over `outline` (counter-clockwise, simple; its caps are fans from `fanCenter`)
/// from zMin to zMax.
inline Shape prismShape(const std::string& name, const std::string& description,
                        std::vector<Point2d> outline, const Point2d& fanCenter, double zMin,
                        double zMax) {
  const Prism prism{std::move(outline), fanCenter, zMin, zMax};
  Shape shape;
  shape.name = name;
  shape.description = description;
  shape.bbox = prism.bbox();
  shape.volume = prism.polygonArea() * prism.height();
  shape.area = 2 * prism.polygonArea() + prism.perimeter() * prism.height();
  shape.signedDistance = [prism](const Point3d& p) { return prism.signedDistance(p); };
  shape.referenceTriangles = [prism]() { return prism.triangles(); };
  return shape;
}

/// Convex polyhedron given by its exact triangulation: inside, the distance is the one to
/// the nearest face plane; outside, the one to the nearest triangle. Both are exact.
inline Shape convexPolyhedronShape(const std::string& name, const std::string& description,
                                   const TriangleList& mesh, double volume, double area) {
  std::vector<vcg::Triangle3<double>> triangles;
  std::vector<vcg::Plane3d> planes;
  for (const auto& t : mesh.triangles) {
    triangles.emplace_back(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    vcg::Plane3d plane;
    // Plane3::Init orients the normal as (p2-p0)^(p1-p0): swap to get the outward one.
    plane.Init(mesh.vertices[t[0]], mesh.vertices[t[2]], mesh.vertices[t[1]]);
    planes.push_back(plane);
  }
  Shape shape;
  shape.name = name;
  shape.description = description;
  for (const Point3d& v : mesh.vertices) shape.bbox.Add(v);
  shape.volume = volume;
  shape.area = area;
  shape.signedDistance = [triangles, planes](const Point3d& p) {
    double maxPlaneDistance = -std::numeric_limits<double>::infinity();
    for (const vcg::Plane3d& plane : planes)
      maxPlaneDistance = std::max(maxPlaneDistance, vcg::SignedDistancePlanePoint(plane, p));
    if (maxPlaneDistance <= 0) return maxPlaneDistance;
    double best = std::numeric_limits<double>::infinity();
    for (const auto& triangle : triangles) {
      double distance;
      Point3d closest;
      vcg::TrianglePointDistance(triangle, p, distance, closest);
      best = std::min(best, distance);
    }
    return best;
  };
  shape.referenceTriangles = [mesh]() { return mesh; };
  return shape;
}

inline Shape cube() {
  return prismShape("cube", "unit cube centred at the origin: 12 convex edges, 8 corners",
                    {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}, Point2d(0, 0), -0.5,
                    0.5);
}

inline Shape lblock() {
  return prismShape("lblock",
                    "L-shaped block 1.6 x 1.6 x 0.8: one concave edge along z at the inner "
                    "corner, convex edges, corners mixing both",
                    {{-0.8, -0.8}, {0.8, -0.8}, {0.8, 0.0}, {0.0, 0.0}, {0.0, 0.8}, {-0.8, 0.8}},
                    Point2d(-0.4, -0.4) /* sees the whole L */, -0.4, 0.4);
}

inline Shape wedge() {
  const double length = 1.6;
  const double acuteAngle = 35.0 * M_PI / 180.0;
  const double height = length * std::tan(acuteAngle);
  const Point2d shift(length / 2, height / 2);
  return prismShape("wedge",
                    "right triangular prism: dihedral angles 35 (acute edge), 55 and 90 "
                    "degrees along z, right-angled edges around the caps",
                    {Point2d(0, 0) - shift, Point2d(length, 0) - shift, Point2d(0, height) - shift},
                    Point2d(length / 3, height / 3) - shift, -0.4, 0.4);
}

inline Shape crossPrism() {
  const double w = 0.3;  // half width of the arms
  const double e = 0.9;  // half span
  return prismShape("cross_prism",
                    "plus-shaped prism 1.8 x 1.8 x 0.6: four concave edges along z, "
                    "corners mixing concave and convex edges",
                    {{-w, -e}, {w, -e}, {w, -w}, {e, -w}, {e, w}, {w, w}, {w, e}, {-w, e}, {-w, w},
                     {-e, w}, {-e, -w}, {-w, -w}},
                    Point2d(0, 0), -0.3, 0.3);
}

inline Shape pyramid() {
  const double a = 0.7;  // half side of the base
  const double baseZ = -0.5, apexZ = 0.6;
  TriangleList mesh;
  const int p0 = mesh.addVertex(Point3d(-a, -a, baseZ));
  const int p1 = mesh.addVertex(Point3d(a, -a, baseZ));
  const int p2 = mesh.addVertex(Point3d(a, a, baseZ));
  const int p3 = mesh.addVertex(Point3d(-a, a, baseZ));
  const int apex = mesh.addVertex(Point3d(0, 0, apexZ));
  mesh.addTriangle(p0, p2, p1);
  mesh.addTriangle(p0, p3, p2);
  mesh.addTriangle(p0, p1, apex);
  mesh.addTriangle(p1, p2, apex);
  mesh.addTriangle(p2, p3, apex);
  mesh.addTriangle(p3, p0, apex);
  const double h = apexZ - baseZ;
  const double side = 2 * a;
  const double slantHeight = std::hypot(h, a);
  return convexPolyhedronShape(
      "pyramid", "square pyramid, base 1.4, height 1.1: apex where four convex edges meet", mesh,
      side * side * h / 3, side * side + 2 * side * slantHeight);
}

/// Regular octahedron of circumradius 0.8: six corners where four convex edges meet.
inline Shape octahedron() {
  const double a = 0.8;
  TriangleList mesh;
  const int px = mesh.addVertex(Point3d(a, 0, 0)), nx = mesh.addVertex(Point3d(-a, 0, 0));
  const int py = mesh.addVertex(Point3d(0, a, 0)), ny = mesh.addVertex(Point3d(0, -a, 0));
  const int pz = mesh.addVertex(Point3d(0, 0, a)), nz = mesh.addVertex(Point3d(0, 0, -a));
  for (const int x : {px, nx})
    for (const int y : {py, ny})
      for (const int z : {pz, nz}) {
        // Outward when (x, y, z) is counter-clockwise seen from outside: an even number of
        // negative axes among the three.
        const bool even = ((x == nx) + (y == ny) + (z == nz)) % 2 == 0;
        if (even)
          mesh.addTriangle(x, y, z);
        else
          mesh.addTriangle(x, z, y);
      }
  return convexPolyhedronShape(
      "octahedron", "regular octahedron, circumradius 0.8: six corners where four convex edges meet",
      mesh, 4.0 / 3.0 * a * a * a, 4 * std::sqrt(3.0) * a * a);
}

/// Pyramid on a regular hexagon of circumradius 0.8, height 1.1: an apex where six convex
/// edges meet (their faces 50 degrees apart), six corners of three around the base.
inline Shape hexagonalPyramid() {
  const double r = 0.8, baseZ = -0.5, apexZ = 0.6;
  TriangleList mesh;
  std::vector<int> rim;
  for (int i = 0; i < 6; ++i)
    rim.push_back(mesh.addVertex(
        Point3d(r * std::cos(M_PI / 3 * i), r * std::sin(M_PI / 3 * i), baseZ)));
  const int apex = mesh.addVertex(Point3d(0, 0, apexZ));
  const int centre = mesh.addVertex(Point3d(0, 0, baseZ));
  for (int i = 0; i < 6; ++i) {
    mesh.addTriangle(rim[i], rim[(i + 1) % 6], apex);
    mesh.addTriangle(rim[(i + 1) % 6], rim[i], centre);
  }
  const double h = apexZ - baseZ, apothem = r * std::sqrt(3.0) / 2;
  const double baseArea = 3 * std::sqrt(3.0) / 2 * r * r;
  return convexPolyhedronShape("hexagonal_pyramid",
                               "pyramid on a regular hexagon (circumradius 0.8), height 1.1: an "
                               "apex where six convex edges meet",
                               mesh, baseArea * h / 3, baseArea + 3 * r * std::hypot(h, apothem));
}

/// Box [-a,a]^2 x [-c,0] with a cylinder of radius R, height H standing on its top face.
inline Shape cylinderBlock() {
  const double a = 0.8, c = 0.5, R = 0.45, H = 0.5;
  // Segments of the circles; a multiple of 8 so that the square's corners lie on the rays
  // that also carry circle vertices.
  const int N = 256;

  auto boxDistanceSquared = [](const Point3d& p, const Point3d& lo, const Point3d& hi) {
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
      const double excess = p[i] - std::clamp(p[i], lo[i], hi[i]);
      sum += excess * excess;
    }
    return sum;
  };
  Shape shape;
  shape.name = "cylinder_block";
  shape.description =
      "box 1.6 x 1.6 x 0.5 with a cylinder boss (radius 0.45, height 0.5) on top: convex "
      "circular edge round the boss top, concave circular edge at its foot, straight "
      "convex box edges";
  shape.bbox = vcg::Box3d(Point3d(-a, -a, -c), Point3d(a, a, H));
  shape.volume = 4 * a * a * c + M_PI * R * R * H;
  shape.area = 8 * a * a + 8 * a * c + 2 * M_PI * R * H;
  // The inscribed polygons deviate from the circles by the sagitta of one segment.
  shape.referenceMaxError = R * (1 - std::cos(M_PI / N));
  // The boundary is the union of the patches below, so the smallest patch distance is the
  // exact distance to the surface.
  shape.signedDistance = [=](const Point3d& p) {
    const double radial = std::hypot(p.X(), p.Y());
    double best = boxDistanceSquared(p, Point3d(-a, -a, -c), Point3d(a, a, -c));  // bottom
    best = std::min(best, boxDistanceSquared(p, Point3d(a, -a, -c), Point3d(a, a, 0)));
    best = std::min(best, boxDistanceSquared(p, Point3d(-a, -a, -c), Point3d(-a, a, 0)));
    best = std::min(best, boxDistanceSquared(p, Point3d(-a, a, -c), Point3d(a, a, 0)));
    best = std::min(best, boxDistanceSquared(p, Point3d(-a, -a, -c), Point3d(a, -a, 0)));
    // Top of the box: the square minus the foot of the cylinder.
    const bool inSquare = std::abs(p.X()) <= a && std::abs(p.Y()) <= a;
    const double inPlaneSquared =
        inSquare
            ? (radial < R ? (R - radial) * (R - radial) : 0.0)
            : boxDistanceSquared(Point3d(p.X(), p.Y(), 0), Point3d(-a, -a, 0), Point3d(a, a, 0));
    best = std::min(best, inPlaneSquared + p.Z() * p.Z());
    // Lateral surface and top disk of the cylinder.
    const double axialExcess = p.Z() - std::clamp(p.Z(), 0.0, H);
    best = std::min(best, (radial - R) * (radial - R) + axialExcess * axialExcess);
    const double outsideDisk = std::max(radial - R, 0.0);
    best = std::min(best, (p.Z() - H) * (p.Z() - H) + outsideDisk * outsideDisk);

    const bool inBox = inSquare && p.Z() >= -c && p.Z() <= 0;
    const bool inCylinder = radial <= R && p.Z() >= 0 && p.Z() <= H;
    return (inBox || inCylinder) ? -std::sqrt(best) : std::sqrt(best);
  };
  shape.referenceTriangles = [=]() {
    TriangleList mesh;
    std::vector<int> foot(N), rim(N), squareTop(N);
    for (int k = 0; k < N; ++k) {
      const double phi = 2 * M_PI * k / N;
      const double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
      foot[k] = mesh.addVertex(Point3d(R * cosPhi, R * sinPhi, 0));
      rim[k] = mesh.addVertex(Point3d(R * cosPhi, R * sinPhi, H));
      // Where the ray at phi leaves the square, with the coordinate on the edge set exactly.
      Point3d onSquare;
      if (k % (N / 4) == N / 8) {
        onSquare = Point3d(cosPhi > 0 ? a : -a, sinPhi > 0 ? a : -a, 0);
      } else if (std::abs(cosPhi) > std::abs(sinPhi)) {
        onSquare = Point3d(cosPhi > 0 ? a : -a, a * sinPhi / std::abs(cosPhi), 0);
      } else {
        onSquare = Point3d(a * cosPhi / std::abs(sinPhi), sinPhi > 0 ? a : -a, 0);
      }
      squareTop[k] = mesh.addVertex(onSquare);
    }
    const int rimCenter = mesh.addVertex(Point3d(0, 0, H));
    for (int k = 0; k < N; ++k) {
      const int next = (k + 1) % N;
      mesh.addTriangle(rimCenter, rim[k], rim[next]);
      mesh.addQuad(foot[k], foot[next], rim[next], rim[k]);
      mesh.addQuad(foot[k], squareTop[k], squareTop[next], foot[next]);
    }
    // Walls: wall w spans the rays k0..k1 between two corners; each is a convex polygon
    // (two bottom corners, then the top points backwards) triangulated as a fan.
    std::array<int, 4> bottomCorner;
    for (int q = 0; q < 4; ++q) {
      const Point3d& top = mesh.vertices[squareTop[(2 * q + 1) * N / 8]];
      bottomCorner[q] = mesh.addVertex(Point3d(top.X(), top.Y(), -c));
    }
    for (int w = 0; w < 4; ++w) {
      const int k0 = (2 * w - 1) * N / 8;  // may be negative: indices are taken mod N
      const int k1 = (2 * w + 1) * N / 8;
      const int bottomStart = bottomCorner[(w + 3) % 4];
      const int bottomEnd = bottomCorner[w];
      mesh.addTriangle(bottomStart, bottomEnd, squareTop[k1 % N]);
      for (int k = k1; k > k0; --k)
        mesh.addTriangle(bottomStart, squareTop[(k + N) % N], squareTop[(k - 1 + N) % N]);
    }
    mesh.addTriangle(bottomCorner[0], bottomCorner[2], bottomCorner[1]);
    mesh.addTriangle(bottomCorner[0], bottomCorner[3], bottomCorner[2]);
    return mesh;
  };
  return shape;
}

/// How a corner of a prism's outline is finished: left sharp, cut by a flat bevel
/// `size` wide, or rounded by a fillet of radius `size` (16 facets): designed features a
/// sharpener must keep, beside the sharp edges it must restore.
struct CornerFinish {
  enum Kind { Sharp, Bevel, Fillet } kind = Sharp;
  double size = 0;
};

/// The outline points of each corner of a convex polygon (counter-clockwise) finished as
/// `finish` says: a sharp corner's one point, a bevel's two ends, a fillet's 17 arc points
/// (16 facets), from the side before the corner to the side after it.
inline std::vector<std::vector<Point2d>> finishedCorners(const std::vector<Point2d>& corners,
                                                         const std::vector<CornerFinish>& finish) {
  constexpr int kFilletFacets = 16;
  std::vector<std::vector<Point2d>> out;
  const std::size_t n = corners.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2d& p = corners[i];
    Point2d toPrev = corners[(i + n - 1) % n] - p, toNext = corners[(i + 1) % n] - p;
    toPrev /= toPrev.Norm();
    toNext /= toNext.Norm();
    const double interior = std::acos(std::clamp(dot2(toPrev, toNext), -1.0, 1.0));
    const CornerFinish& f = finish[i];
    std::vector<Point2d>& points = out.emplace_back();
    if (f.kind == CornerFinish::Sharp) {
      points.push_back(p);
    } else if (f.kind == CornerFinish::Bevel) {
      const double cut = f.size / (2 * std::sin(interior / 2));  // along each side
      points.push_back(p + toPrev * cut);
      points.push_back(p + toNext * cut);
    } else {
      const double tangent = f.size / std::tan(interior / 2);
      Point2d bisector = toPrev + toNext;
      bisector /= bisector.Norm();
      const Point2d centre = p + bisector * (f.size / std::sin(interior / 2));
      const Point2d from = p + toPrev * tangent - centre, to = p + toNext * tangent - centre;
      const double a0 = std::atan2(from.Y(), from.X());
      double sweep = std::atan2(to.Y(), to.X()) - a0;
      while (sweep < 0) sweep += 2 * M_PI;  // counter-clockwise, the short way round
      for (int k = 0; k <= kFilletFacets; ++k) {
        const double a = a0 + sweep * k / kFilletFacets;
        points.push_back(centre + Point2d(std::cos(a), std::sin(a)) * f.size);
      }
    }
  }
  return out;
}

/// A convex polygon (counter-clockwise) with each corner finished as `finish` says.
inline std::vector<Point2d> finishedOutline(const std::vector<Point2d>& corners,
                                            const std::vector<CornerFinish>& finish) {
  std::vector<Point2d> outline;
  for (const std::vector<Point2d>& points : finishedCorners(corners, finish))
    outline.insert(outline.end(), points.begin(), points.end());
  return outline;
}

/// A prism whose outline's corners are finished (the shapes bevelled_block and
/// finished_hexprism): its outline, height and the turn that makes it oblique to the grid.
/// What it is made from is what its designed features are (designed_faces.h).
struct FinishedPrism {
  std::string name, description;
  std::vector<Point2d> corners;  ///< counter-clockwise
  std::vector<CornerFinish> finish;
  double zMin = 0, zMax = 0;
  Point3d axis;  ///< the shape is the prism turned by `angle` (radians) about `axis`
  double angle = 0;
};

/// Box 1.6 x 1.0 x 0.6 whose vertical edges are two bevels (0.03 and 0.07 wide) and two
/// fillets (radii 0.03 and 0.07): one to three and a half cells at 1% of the diagonal.
inline const FinishedPrism& bevelledBlockPrism() {
  static const FinishedPrism prism{
      "bevelled_block",
      "box 1.6 x 1.0 x 0.6, vertical edges finished by designed bevels 0.03 and 0.07 wide and "
      "fillets of radii 0.03 and 0.07; sharp edges round the caps",
      {{-0.8, -0.5}, {0.8, -0.5}, {0.8, 0.5}, {-0.8, 0.5}},
      {{CornerFinish::Bevel, 0.03},
       {CornerFinish::Fillet, 0.03},
       {CornerFinish::Bevel, 0.07},
       {CornerFinish::Fillet, 0.07}},
      -0.3,
      0.3,
      Point3d(3, 1, 2),
      0.5};
  return prism;
}

/// A hexagonal prism whose corners are finished by bevels and fillets of other sizes,
/// one left sharp, and whose sides meet at other angles than bevelledBlock's.
inline const FinishedPrism& finishedHexPrismPrism() {
  static const FinishedPrism prism{
      "finished_hexprism",
      "hexagonal prism 1.75 x 1.35 x 0.7, vertical edges finished by designed bevels (0.05, "
      "0.1 wide) and fillets (radii 0.02, 0.05, 0.1), one sharp",
      {{-0.85, -0.35}, {-0.2, -0.7}, {0.7, -0.55}, {0.9, 0.1}, {0.35, 0.65}, {-0.6, 0.5}},
      {{CornerFinish::Fillet, 0.05},
       {CornerFinish::Bevel, 0.05},
       {CornerFinish::Sharp, 0},
       {CornerFinish::Fillet, 0.1},
       {CornerFinish::Bevel, 0.1},
       {CornerFinish::Fillet, 0.02}},
      -0.35,
      0.35,
      Point3d(-1, 2, 2),
      0.7};
  return prism;
}

/// Every finished prism among the shapes.
inline std::vector<const FinishedPrism*> finishedPrisms() {
  return {&bevelledBlockPrism(), &finishedHexPrismPrism()};
}

/// The finished prism, unturned.
inline Shape finishedPrismShape(const FinishedPrism& p) {
  return prismShape(p.name, p.description, finishedOutline(p.corners, p.finish), Point2d(0, 0),
                    p.zMin, p.zMax);
}

inline TriangleList uvSphere(double radius, int rings, int segments) {
  TriangleList mesh;
  const int north = mesh.addVertex(Point3d(0, 0, radius));
  std::vector<std::vector<int>> ring(rings - 1, std::vector<int>(segments));
  for (int i = 1; i < rings; ++i) {
    const double theta = M_PI * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * M_PI * j / segments;
      ring[i - 1][j] = mesh.addVertex(Point3d(radius * std::sin(theta) * std::cos(phi),
                                              radius * std::sin(theta) * std::sin(phi),
                                              radius * std::cos(theta)));
    }
  }
  const int south = mesh.addVertex(Point3d(0, 0, -radius));
  for (int j = 0; j < segments; ++j) {
    const int next = (j + 1) % segments;
    mesh.addTriangle(north, ring.front()[j], ring.front()[next]);
    for (int i = 0; i + 1 < rings - 1; ++i)
      mesh.addQuad(ring[i][j], ring[i + 1][j], ring[i + 1][next], ring[i][next]);
    mesh.addTriangle(south, ring.back()[next], ring.back()[j]);
  }
  return mesh;
}

/// Largest distance of the flat triangles from a sphere centred at the origin: the vertices
/// lie on the sphere, so it is the radius minus the distance of the nearest triangle point.
inline double sphereTessellationError(const TriangleList& mesh, double radius) {
  double worst = 0;
  for (const auto& t : mesh.triangles) {
    const vcg::Triangle3<double> triangle(mesh.vertices[t[0]], mesh.vertices[t[1]],
                                          mesh.vertices[t[2]]);
    double distance;
    Point3d closest;
    vcg::TrianglePointDistance(triangle, Point3d(0, 0, 0), distance, closest);
    worst = std::max(worst, radius - distance);
  }
  return worst;
}

inline Shape sphere() {
  const double radius = 0.75;
  // 96 x 192 keeps the tessellation error near 7.7e-5 of the diagonal (bound < 1e-4).
  const int rings = 96, segments = 192;
  Shape shape;
  shape.name = "sphere";
  shape.description = "sphere of radius 0.75: no features, the sharpener must leave it alone";
  shape.bbox = vcg::Box3d(Point3d(-radius, -radius, -radius), Point3d(radius, radius, radius));
  shape.volume = 4.0 / 3.0 * M_PI * radius * radius * radius;
  shape.area = 4 * M_PI * radius * radius;
  shape.hasSharpFeatures = false;
  shape.referenceMaxError = sphereTessellationError(uvSphere(radius, rings, segments), radius);
  shape.signedDistance = [radius](const Point3d& p) { return p.Norm() - radius; };
  shape.referenceTriangles = [=]() { return uvSphere(radius, rings, segments); };
  return shape;
}

inline Point3d rotateRodrigues(const Point3d& v, const Point3d& unitAxis, double angle) {
  return v * std::cos(angle) + (unitAxis ^ v) * std::sin(angle) +
         unitAxis * ((unitAxis * v) * (1 - std::cos(angle)));
}

// Shapes with curved sharp edges (issue 60, point 3). Their distance is the smallest distance
// to their boundary patches, each patch taken with its trimming: where the nearest point of a
// patch's whole surface (cylinder, cone, torus) lies outside the patch, the patch's nearest
// point lies on the patch's boundary curve, which another patch holds (or, for the
// intersection curve of twoCylinders(), which is measured on its own), so that patch can be
// left out. Sign: inside the solid by its defining inequalities.

/// Distance from (y0, y1) to the ellipse (x0 / e0)^2 + (x1 / e1)^2 = 1 (e0, e1 > 0), to the
/// last bits: D. Eberly, "Distance from a point to an ellipse, an ellipsoid, or a
/// hyperellipsoid" (Geometric Tools, 2013): bisection for the root of a monotone function that
/// gives the nearest point.
inline double ellipseDistance(double e0, double e1, double y0, double y1) {
  y0 = std::abs(y0);
  y1 = std::abs(y1);
  if (e0 < e1) {
    std::swap(e0, e1);
    std::swap(y0, y1);
  }
  if (y1 > 0) {
    if (y0 == 0) return std::abs(y1 - e1);
    const double z0 = y0 / e0, z1 = y1 / e1;
    double g = z0 * z0 + z1 * z1 - 1;
    if (g == 0) return 0;
    const double r0 = (e0 / e1) * (e0 / e1), n0 = r0 * z0;
    double s0 = z1 - 1, s1 = g < 0 ? 0 : std::hypot(n0, z1) - 1, s = 0;
    // Each step halves [s0, s1]; it ends when the midpoint rounds to an end.
    for (int i = 0; i < 2200; ++i) {
      s = 0.5 * (s0 + s1);
      if (s == s0 || s == s1) break;
      const double ratio0 = n0 / (s + r0), ratio1 = z1 / (s + 1);
      g = ratio0 * ratio0 + ratio1 * ratio1 - 1;
      if (g > 0) {
        s0 = s;
      } else if (g < 0) {
        s1 = s;
      } else {
        break;
      }
    }
    return std::hypot(r0 * y0 / (s + r0) - y0, y1 / (s + 1) - y1);
  }
  const double numer0 = e0 * y0, denom0 = e0 * e0 - e1 * e1;
  if (numer0 < denom0) {
    const double xde0 = numer0 / denom0;
    return std::hypot(e0 * xde0 - y0, e1 * std::sqrt(1 - xde0 * xde0));
  }
  return std::abs(y0 - e0);
}

/// The surface of revolution about z of a profile polygon in the (rho, z) half-plane, turning
/// counter-clockwise (rho to the right, z up) so that its faces point outward, with `segments`
/// meridians. A profile point on the axis (rho == 0) is a pole; a closed profile's last point
/// joins its first. Every quad between two meridians and two parallels is a planar trapezoid.
inline TriangleList revolvedTriangles(const std::vector<Point2d> &profile, bool closed,
                                      int segments) {
  TriangleList mesh;
  const int n = static_cast<int>(profile.size());
  std::vector<std::vector<int>> ring(n);
  for (int j = 0; j < n; ++j) {
    const Point2d &q = profile[j];
    if (q.X() == 0) {
      ring[j].assign(segments, mesh.addVertex(Point3d(0, 0, q.Y())));
      continue;
    }
    for (int k = 0; k < segments; ++k) {
      const double phi = 2 * M_PI * k / segments;
      ring[j].push_back(
          mesh.addVertex(Point3d(q.X() * std::cos(phi), q.X() * std::sin(phi), q.Y())));
    }
  }
  for (int j = 0; j < (closed ? n : n - 1); ++j) {
    const int next = (j + 1) % n;
    const bool fromPole = profile[j].X() == 0, toPole = profile[next].X() == 0;
    if (fromPole && toPole) continue;
    for (int k = 0; k < segments; ++k) {
      const int k1 = (k + 1) % segments;
      const int a = ring[j][k], b = ring[j][k1], c = ring[next][k1], d = ring[next][k];
      if (fromPole) {
        mesh.addTriangle(a, c, d);
      } else if (toPole) {
        mesh.addTriangle(a, b, c);
      } else {
        mesh.addQuad(a, b, c, d);
      }
    }
  }
  return mesh;
}

/// A solid circular cylinder about the z axis cut below by the plane
/// z = bottomZ + bottomSlope * x and above by z = topZ + topSlope * x (they do not meet inside
/// the cylinder). An oblique plane makes an elliptic rim, along which the dihedral angle between
/// the side and the cap varies.
struct CutCylinder {
  double radius, bottomZ, bottomSlope, topZ, topSlope;

  double bottomAt(double x) const { return bottomZ + bottomSlope * x; }
  double topAt(double x) const { return topZ + topSlope * x; }
  /// Whether the side's generator in the direction (cosPhi, sinPhi) holds height z.
  bool sideHolds(double cosPhi, double z) const {
    return bottomAt(radius * cosPhi) <= z && z <= topAt(radius * cosPhi);
  }

  /// Distance to the cap in the plane z = z0 + slope * x: the plane's part inside the cylinder,
  /// an elliptic disk with semi-axes radius * sqrt(1 + slope^2) (along (1, 0, slope)) and
  /// radius (along y). Exact: the height over the plane and the in-plane distance to the disk.
  double capDistance(const Point3d &p, double z0, double slope) const {
    const double stretch = std::sqrt(1 + slope * slope);
    const double dz = p.Z() - z0;
    const double height = (dz - slope * p.X()) / stretch;
    const double u = (p.X() + slope * dz) / stretch, v = p.Y();
    const double a = radius * stretch, b = radius;
    const double inPlane =
        (u / a) * (u / a) + (v / b) * (v / b) <= 1 ? 0.0 : ellipseDistance(a, b, u, v);
    return std::hypot(height, inPlane);
  }

  double signedDistance(const Point3d &p) const {
    const double r = std::hypot(p.X(), p.Y());
    double best = std::min(capDistance(p, topZ, topSlope), capDistance(p, bottomZ, bottomSlope));
    // The side: the nearest point of the whole cylinder keeps the height and the direction
    // from the axis (its only local minimum of the distance); when the side does not hold it,
    // the side's nearest point is on a rim, which a cap holds. On the axis every direction is
    // as near: the side holds the height in some direction iff it does in the best one, and
    // both bounds are linear in cos(phi), so the best is cos(phi) = -1, 1 or where they cross.
    bool onSide = false;
    if (r > 0) {
      onSide = sideHolds(p.X() / r, p.Z());
    } else {
      // z - bottomAt(R c) = topAt(R c) - z at c = (2 z - bottomZ - topZ) / (R * slopes).
      const double slopes = topSlope + bottomSlope;
      const double crossing =
          slopes != 0 ? std::clamp((2 * p.Z() - bottomZ - topZ) / (radius * slopes), -1.0, 1.0)
                      : 1.0;
      for (double cosPhi : {-1.0, 1.0, crossing}) onSide = onSide || sideHolds(cosPhi, p.Z());
    }
    if (onSide) best = std::min(best, std::abs(r - radius));
    const bool inside = r <= radius && p.Z() >= bottomAt(p.X()) && p.Z() <= topAt(p.X());
    return inside ? -best : best;
  }

  /// `segments` generators; both rims' vertices lie on them, the caps are fans from the axis.
  /// Every face is planar.
  TriangleList triangles(int segments) const {
    TriangleList mesh;
    std::vector<int> bottom(segments), top(segments);
    for (int k = 0; k < segments; ++k) {
      const double phi = 2 * M_PI * k / segments;
      const double x = radius * std::cos(phi), y = radius * std::sin(phi);
      bottom[k] = mesh.addVertex(Point3d(x, y, bottomAt(x)));
      top[k] = mesh.addVertex(Point3d(x, y, topAt(x)));
    }
    const int bottomCenter = mesh.addVertex(Point3d(0, 0, bottomZ));
    const int topCenter = mesh.addVertex(Point3d(0, 0, topZ));
    mesh.addCappedBand(bottom, top, bottomCenter, topCenter);
    return mesh;
  }
};

/// Radius 0.6, height 1 on the axis; the top plane tilted 30 degrees, the bottom one 20 degrees
/// the other way (both about y).
inline const CutCylinder &cylinderCutParameters() {
  static const CutCylinder cylinder{0.6, -0.55, -std::tan(20 * M_PI / 180), 0.45,
                                    std::tan(30 * M_PI / 180)};
  return cylinder;
}

inline Shape cylinderCut() {
  const CutCylinder c = cylinderCutParameters();
  const double R = c.radius;
  const int N = 256;
  const double topStretch = std::hypot(1.0, c.topSlope);
  const double bottomStretch = std::hypot(1.0, c.bottomSlope);
  Shape shape;
  shape.name = "cylinder_cut";
  shape.description =
      "cylinder of radius 0.6 about z cut by two oblique planes (30 degrees at the top, 20 "
      "the other way at the bottom, both about y; height 1 on the axis): two elliptic convex "
      "rims whose dihedral angle runs from 60 to 120 and from 70 to 110 degrees";
  shape.bbox = vcg::Box3d(Point3d(-R, -R, std::min(c.bottomAt(-R), c.bottomAt(R))),
                          Point3d(R, R, std::max(c.topAt(-R), c.topAt(R))));
  // The planes' terms linear in x cancel over the disk.
  shape.volume = M_PI * R * R * (c.topZ - c.bottomZ);
  shape.area = 2 * M_PI * R * (c.topZ - c.bottomZ) + M_PI * R * R * (topStretch + bottomStretch);
  // The side's chords are a sagitta s inside the cylinder; a point of the surface between a
  // chord and its arc (on the side below a rim, or on a cap outside its polygon) is within
  // s * sqrt(1 + slope^2) of the mesh: the cap plane stretches the xy offset by that much.
  shape.referenceMaxError = R * (1 - std::cos(M_PI / N)) * std::max(topStretch, bottomStretch);
  shape.signedDistance = [c](const Point3d &p) { return c.signedDistance(p); };
  shape.referenceTriangles = [c, N]() { return c.triangles(N); };
  return shape;
}

/// A frustum of a cone about the z axis, radius bottomRadius at bottomZ and topRadius at topZ,
/// with flat caps: a solid of revolution whose meridian section is a trapezoid, so its distance
/// is the 2D distance in the meridian half-plane to the section's three edges off the axis.
struct Frustum {
  double bottomRadius, topRadius, bottomZ, topZ;
  Point3d axis;  ///< allShapes() turns it by `angle` (radians) about `axis`
  double angle = 0;

  std::vector<Point2d> profile() const {
    return {{0, bottomZ}, {bottomRadius, bottomZ}, {topRadius, topZ}, {0, topZ}};
  }
  double height() const { return topZ - bottomZ; }
  double slantHeight() const { return std::hypot(bottomRadius - topRadius, height()); }

  double signedDistance(const Point3d &p) const {
    const Point2d q(std::hypot(p.X(), p.Y()), p.Z());
    const Point2d corners[4] = {
        {0, bottomZ}, {bottomRadius, bottomZ}, {topRadius, topZ}, {0, topZ}};
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i)
      best = std::min(best, segmentDistanceSquared2d(q, corners[i], corners[i + 1]));
    const double t = (q.Y() - bottomZ) / height();
    const bool inside = t >= 0 && t <= 1 && q.X() <= bottomRadius + t * (topRadius - bottomRadius);
    return inside ? -std::sqrt(best) : std::sqrt(best);
  }
};

/// Radii 0.75 and 0.35, height 1.1: flanks about 20 degrees off the axis.
inline const Frustum &coneCutParameters() {
  static const Frustum frustum{0.75, 0.35, -0.55, 0.55, Point3d(1, -2, 1), 0.5};
  return frustum;
}

/// The frustum, unturned.
inline Shape coneCut() {
  const Frustum f = coneCutParameters();
  const int N = 256;
  const double Rb = f.bottomRadius, Rt = f.topRadius;
  Shape shape;
  shape.name = "cone_cut";
  shape.description =
      "frustum of a cone, radii 0.75 (base) and 0.35 (top), height 1.1: convex circular rims "
      "of 70 degrees round the base and 110 degrees round the top";
  shape.bbox = vcg::Box3d(Point3d(-Rb, -Rb, f.bottomZ), Point3d(Rb, Rb, f.topZ));
  shape.volume = M_PI * f.height() * (Rb * Rb + Rb * Rt + Rt * Rt) / 3;
  shape.area = M_PI * (Rb * Rb + Rt * Rt) + M_PI * (Rb + Rt) * f.slantHeight();
  // Each face is a planar trapezoid (or a cap's triangle) between two meridians: its chords of
  // the parallels are at most the sagitta of the widest one from the surface.
  shape.referenceMaxError = Rb * (1 - std::cos(M_PI / N));
  shape.signedDistance = [f](const Point3d &p) { return f.signedDistance(p); };
  shape.referenceTriangles = [f, N]() { return revolvedTriangles(f.profile(), false, N); };
  return shape;
}

/// A torus about the z axis (tube of radius minorRadius round the circle of radius majorRadius
/// in the plane z = 0) with everything above the plane z = cutZ removed (0 < cutZ < minorRadius):
/// a flat annular cap meets the tube along two circles at a dihedral angle of
/// 180 - acos(cutZ / minorRadius) degrees. A solid of revolution: its meridian section is a disk
/// cut by a line (an arc and a chord).
struct CutTorus {
  double majorRadius, minorRadius, cutZ;
  Point3d axis;  ///< allShapes() turns it by `angle` (radians) about `axis`
  double angle = 0;

  /// Half the chord: the rims are at rho = majorRadius -/+ halfChord().
  double halfChord() const { return std::sqrt(minorRadius * minorRadius - cutZ * cutZ); }
  /// The part of the tube below the cut spans pi - asin(cutZ / r) to 2 pi + asin(cutZ / r).
  double arcAngle() const { return M_PI + 2 * std::asin(cutZ / minorRadius); }

  double signedDistance(const Point3d &p) const {
    const double dr = std::hypot(p.X(), p.Y()) - majorRadius, dz = p.Z();
    const double len = std::hypot(dr, dz);
    // The chord (the cap): rho in [R - w, R + w] at z = cutZ.
    double best = std::hypot(std::max(std::abs(dr) - halfChord(), 0.0), dz - cutZ);
    // The arc: the nearest point of the whole circle is along (dr, dz) (the only local minimum
    // of the distance); when the arc does not hold it, the arc's nearest point is an end of it,
    // which the chord holds. At the centre every point of the circle is as near.
    if (len == 0) {
      best = std::min(best, minorRadius);
    } else if (minorRadius * dz / len <= cutZ) {
      best = std::min(best, std::abs(len - minorRadius));
    }
    const bool inside = len <= minorRadius && dz <= cutZ;
    return inside ? -best : best;
  }

  /// The meridian section's boundary, counter-clockwise: the chord from the outer rim to the
  /// inner one, then `arcSegments` chords of the arc back.
  std::vector<Point2d> profile(int arcSegments) const {
    const double R = majorRadius, r = minorRadius, w = halfChord();
    std::vector<Point2d> points = {{R + w, cutZ}, {R - w, cutZ}};
    const double start = M_PI - std::asin(cutZ / r);
    for (int j = 1; j < arcSegments; ++j) {
      const double theta = start + arcAngle() * j / arcSegments;
      points.emplace_back(R + r * std::cos(theta), r * std::sin(theta));
    }
    return points;
  }
};

/// Radii 0.65 and 0.35, cut 0.1 above the centre plane: rims at radii 0.985 and 0.315,
/// dihedral angles of 106.6 degrees.
inline const CutTorus &torusCutParameters() {
  static const CutTorus torus{0.65, 0.35, 0.1, Point3d(2, 1, 0.5), 0.45};
  return torus;
}

/// The cut torus, unturned.
inline Shape torusCut() {
  const CutTorus t = torusCutParameters();
  const int N = 256, arcSegments = 128;
  const double R = t.majorRadius, r = t.minorRadius, w = t.halfChord();
  Shape shape;
  shape.name = "torus_cut";
  shape.genus = 1;
  shape.description =
      "torus (radii 0.65 and 0.35) with everything above a plane 0.1 over its centre plane cut "
      "off: a flat annular cap meets the torus along two convex circular rims (radii 0.985 and "
      "0.315) of 106.6 degrees";
  shape.bbox = vcg::Box3d(Point3d(-R - r, -R - r, -r), Point3d(R + r, R + r, t.cutZ));
  // Pappus: the section and its boundary are symmetric about rho = R.
  const double sectionArea = r * r * (M_PI - std::acos(t.cutZ / r)) + t.cutZ * w;
  shape.volume = 2 * M_PI * R * sectionArea;
  shape.area = 2 * M_PI * R * r * t.arcAngle() + 4 * M_PI * R * w;
  // The faces are planar trapezoids between two meridians: within the sagitta of the widest
  // parallel of the revolved polygon, which is within the arc's sagitta of the section.
  shape.referenceMaxError =
      (R + r) * (1 - std::cos(M_PI / N)) + r * (1 - std::cos(t.arcAngle() / arcSegments / 2));
  shape.signedDistance = [t](const Point3d &p) { return t.signedDistance(p); };
  shape.referenceTriangles = [t, N, arcSegments]() {
    return revolvedTriangles(t.profile(arcSegments), true, N);
  };
  return shape;
}

/// A T joint of two solid cylinders: the main one about the x axis (mainRadius, |x| <=
/// halfLength, flat ends) and a boss about the z axis (bossRadius < mainRadius, from z = 0 to
/// its flat top at bossTop > mainRadius), unioned. The boss side meets the main side along the
/// saddle-shaped curve (r cos t, r sin t, sqrt(R^2 - r^2 sin^2 t)): a concave edge.
struct TeeCylinders {
  double mainRadius, halfLength, bossRadius, bossTop;
  Point3d axis;  ///< allShapes() turns it by `angle` (radians) about `axis`
  double angle = 0;

  /// Height of the main side over the boss side at y (|y| <= bossRadius).
  double footHeight(double y) const { return std::sqrt(mainRadius * mainRadius - y * y); }
  double lowestFoot() const { return footHeight(bossRadius); }
  /// The intersection curve at boss angle t, and its first two derivatives.
  Point3d curvePoint(double t) const {
    const double y = bossRadius * std::sin(t);
    return Point3d(bossRadius * std::cos(t), y, footHeight(y));
  }
  Point3d curveTangent(double t) const {
    const double c = std::cos(t), s = std::sin(t), r = bossRadius;
    return Point3d(-r * s, r * c, -r * r * s * c / footHeight(r * s));
  }
  Point3d curveSecondDerivative(double t) const {
    const double c = std::cos(t), s = std::sin(t), r = bossRadius, z = footHeight(r * s);
    return Point3d(-r * c, -r * s,
                   -r * r * ((c * c - s * s) / z + r * r * s * s * c * c / (z * z * z)));
  }
  /// Bounds over t of |dz/dt|, |curve''| and |curve'|^2.
  double footSlopeBound() const { return bossRadius * bossRadius / (2 * lowestFoot()); }
  double curveSecondDerivativeBound() const {
    const double r2 = bossRadius * bossRadius, z = lowestFoot();
    return std::hypot(bossRadius, r2 / z + r2 * r2 / (4 * z * z * z));
  }
  double curveSpeedSquaredBound() const {
    return bossRadius * bossRadius + footSlopeBound() * footSlopeBound();
  }

  /// Distance from p to the intersection curve, or `bound` when the curve is no nearer: branch
  /// and bound over t on the squared distance g (|g''| <= K, so g >= min(g(a), g(b)) - K h^2 / 8
  /// on [a, b], h = b - a) down to intervals of 1e-12, then Newton steps on g' = 0.
  double curveDistance(const Point3d &p, double bound) const {
    const double K =
        2 * curveSpeedSquaredBound() +
        2 * (p.Norm() + std::hypot(mainRadius, bossRadius)) * curveSecondDerivativeBound();
    const auto g = [&](double t) { return (p - curvePoint(t)).SquaredNorm(); };
    constexpr int kSamples = 128;
    const double h0 = 2 * M_PI / kSamples;
    double bestG = bound * bound, bestT = std::numeric_limits<double>::quiet_NaN();
    struct Interval {
      double a, b, ga, gb;
    };
    std::vector<Interval> open;
    double previous = g(0);
    if (previous < bestG) bestG = previous, bestT = 0;
    for (int i = 0; i < kSamples; ++i) {
      const double b = i + 1 == kSamples ? 2 * M_PI : (i + 1) * h0;
      const double gb = i + 1 == kSamples ? g(0) : g(b);
      if (gb < bestG) bestG = gb, bestT = b;
      open.push_back({i * h0, b, previous, gb});
      previous = gb;
    }
    while (!open.empty()) {
      const Interval v = open.back();
      open.pop_back();
      const double h = v.b - v.a;
      if (std::min(v.ga, v.gb) - K * h * h / 8 >= bestG || h < 1e-12) continue;
      const double m = 0.5 * (v.a + v.b), gm = g(m);
      if (gm < bestG) bestG = gm, bestT = m;
      open.push_back({v.a, m, v.ga, gm});
      open.push_back({m, v.b, gm, v.gb});
    }
    if (std::isnan(bestT)) return bound;
    for (int i = 0; i < 8; ++i) {
      const Point3d d = p - curvePoint(bestT), tangent = curveTangent(bestT);
      const double slope = -2 * (d * tangent);
      const double curvature = 2 * tangent.SquaredNorm() - 2 * (d * curveSecondDerivative(bestT));
      if (!(curvature > 0)) break;
      const double t = bestT - slope / curvature, gt = g(t);
      if (!(gt < bestG)) break;
      bestG = gt;
      bestT = t;
    }
    return std::sqrt(bestG);
  }

  double signedDistance(const Point3d &p) const {
    const double R = mainRadius, L = halfLength, r = bossRadius, H = bossTop;
    const double x = p.X(), y = p.Y(), z = p.Z();
    const double rhoMain = std::hypot(y, z), rhoBoss = std::hypot(x, y);
    // The main cylinder's ends and the boss top: disks.
    const double outsideMain = std::max(rhoMain - R, 0.0);
    double best = std::min(std::hypot(x - L, outsideMain), std::hypot(x + L, outsideMain));
    best = std::min(best, std::hypot(z - H, std::max(rhoBoss - r, 0.0)));
    // The main side without the boss's opening. The nearest point of the whole cylinder keeps
    // x and the direction from the axis; when it falls in the opening (or past an end), the
    // side's nearest point is on the intersection curve (or an end's rim). On the axis every
    // direction is as near, straight down among them, never in the opening.
    if (std::abs(x) <= L) {
      const double qy = rhoMain > 0 ? R * y / rhoMain : 0.0;
      const double qz = rhoMain > 0 ? R * z / rhoMain : -R;
      if (!(qz > 0 && x * x + qy * qy < r * r)) best = std::min(best, std::abs(rhoMain - R));
    }
    // The boss side above the curve, likewise; on its axis the lowest point of the curve, at
    // y = +-r, is the best direction.
    const double qy = rhoBoss > 0 ? r * y / rhoBoss : r;
    if (z <= H && z >= footHeight(qy)) best = std::min(best, std::abs(rhoBoss - r));
    // The intersection curve lies on both cylinders: no nearer than either.
    if (best > std::max(std::abs(rhoMain - R), std::abs(rhoBoss - r)))
      best = std::min(best, curveDistance(p, best));
    const bool inside = (rhoMain <= R && std::abs(x) <= L) || (rhoBoss <= r && z >= 0 && z <= H);
    return inside ? -best : best;
  }

  /// `segments` (a multiple of 4) columns round the boss, from the curve to its top. The main
  /// side is cut into strips between lines parallel to x: one through each pair of curve
  /// vertices with the same y (the left and right side of the opening), and evenly spaced ones
  /// round the rest, no wider; each strip (or each half of one beside the opening) is a planar
  /// polygon with its vertices on the surface. The ends and the boss top are fans.
  TriangleList triangles(int segments) const {
    const double R = mainRadius, L = halfLength, r = bossRadius, H = bossTop;
    const int N = segments, quarter = N / 4;
    TriangleList mesh;
    // The curve: the half x >= 0 computed, the other half mirrored (the same y and z).
    std::vector<Point3d> curve(N);
    for (int j = -quarter; j <= quarter; ++j) {
      const double t = 2 * M_PI * j / N;
      const double c = std::abs(j) == quarter ? 0.0 : std::cos(t);
      const double s = j == quarter ? 1.0 : j == -quarter ? -1.0 : std::sin(t);
      const Point3d point(r * c, r * s, footHeight(r * s));
      curve[(j + N) % N] = point;
      curve[(N / 2 - j + N) % N] = Point3d(-point.X(), point.Y(), point.Z());
    }
    std::vector<int> foot(N), rim(N);
    for (int k = 0; k < N; ++k) {
      foot[k] = mesh.addVertex(curve[k]);
      rim[k] = mesh.addVertex(Point3d(curve[k].X(), curve[k].Y(), H));
    }
    const int topCenter = mesh.addVertex(Point3d(0, 0, H));
    mesh.addCappedBand(foot, rim, /*bottomCenter=*/-1, topCenter);
    // Lines on the main side in the order of psi = atan2(y, z): the opening's from -asin(r / R)
    // to asin(r / R), then the rest round the bottom.
    struct Line {
      double y, z;
      int left = -1, right = -1;  // the curve vertices on it (x < 0, x > 0), if any
    };
    std::vector<Line> lines;
    for (int j = -quarter; j <= quarter; ++j) {
      const Point3d &q = curve[(j + N) % N];
      lines.push_back({q.Y(), q.Z(), foot[(N / 2 - j + N) % N], foot[(j + N) % N]});
    }
    const double opening = std::asin(r / R);
    const double rest = 2 * M_PI - 2 * opening;
    const int restSegments = static_cast<int>(std::ceil(rest / widestMainStep(N)));
    for (int i = 1; i < restSegments; ++i) {
      const double psi = opening + rest * i / restSegments;
      lines.push_back({R * std::sin(psi), R * std::cos(psi)});
    }
    const int lineCount = static_cast<int>(lines.size());
    std::vector<int> minus(lineCount), plus(lineCount);
    for (int i = 0; i < lineCount; ++i) {
      minus[i] = mesh.addVertex(Point3d(-L, lines[i].y, lines[i].z));
      plus[i] = mesh.addVertex(Point3d(L, lines[i].y, lines[i].z));
    }
    // Counter-clockwise seen from outside: along a line towards +x, then back along the next.
    for (int i = 0; i < lineCount; ++i) {
      const int n = (i + 1) % lineCount;
      const Line &a = lines[i], &b = lines[n];
      if (a.right >= 0 && b.right >= 0) {  // beside the opening: two quads
        mesh.addQuad(minus[i], a.left, b.left, minus[n]);
        mesh.addQuad(a.right, plus[i], plus[n], b.right);
      } else if (a.right >= 0) {  // from the opening's last line (its tip): a pentagon
        mesh.addTriangle(minus[n], minus[i], a.right);
        mesh.addTriangle(minus[n], a.right, plus[i]);
        mesh.addTriangle(minus[n], plus[i], plus[n]);
      } else if (b.right >= 0) {  // to the opening's first line (its other tip)
        mesh.addTriangle(minus[i], plus[i], plus[n]);
        mesh.addTriangle(minus[i], plus[n], b.right);
        mesh.addTriangle(minus[i], b.right, minus[n]);
      } else {
        mesh.addQuad(minus[i], plus[i], plus[n], minus[n]);
      }
    }
    const int minusCenter = mesh.addVertex(Point3d(-L, 0, 0));
    const int plusCenter = mesh.addVertex(Point3d(L, 0, 0));
    for (int i = 0; i < lineCount; ++i) {
      const int n = (i + 1) % lineCount;
      mesh.addTriangle(plusCenter, plus[n], plus[i]);
      mesh.addTriangle(minusCenter, minus[i], minus[n]);
    }
    return mesh;
  }

  /// The largest angle about the x axis between two neighbouring lines of triangles() beside
  /// the opening; the lines round the rest are no farther apart.
  double widestMainStep(int segments) const {
    double widest = 0;
    for (int j = -segments / 4; j < segments / 4; ++j) {
      const double y0 = bossRadius * std::sin(2 * M_PI * j / segments);
      const double y1 = bossRadius * std::sin(2 * M_PI * (j + 1) / segments);
      widest = std::max(widest, std::atan2(y1, footHeight(y1)) - std::atan2(y0, footHeight(y0)));
    }
    return widest;
  }
};

/// Main cylinder radius 0.5, length 2; boss radius 0.35, top 0.95 above the main axis.
inline const TeeCylinders &twoCylindersParameters() {
  static const TeeCylinders tee{0.5, 1.0, 0.35, 0.95, Point3d(3, 1, 1), 0.4};
  return tee;
}

/// The T joint, unturned.
inline Shape twoCylinders() {
  const TeeCylinders c = twoCylindersParameters();
  const int N = 256;
  const double R = c.mainRadius, L = c.halfLength, r = c.bossRadius, H = c.bossTop;
  // Complete elliptic integrals of the modulus k = r / R: the curve's height integrates to them.
  const double k = r / R, K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
  Shape shape;
  shape.name = "two_cylinders";
  shape.description =
      "cylinder (radius 0.5, length 2) with a perpendicular cylinder boss (radius 0.35, top 0.95 "
      "above the axis) unioned in, flat ends: a concave saddle-shaped intersection edge "
      "(dihedral angle 270 to 226 degrees), convex circular rims round the ends and the boss top";
  shape.bbox = vcg::Box3d(Point3d(-L, -R, -R), Point3d(L, R, H));
  // The boss above the main side: pi r^2 H minus the integral of the side's height over the
  // disk, (4/3) R^3 ((1 + k^2) E - (1 - k^2) K); the opening in the main side has area
  // 4 R^2 (E - (1 - k^2) K); the boss side is 2 pi r H minus r times the curve's height
  // integrated over t, 4 R E.
  shape.volume = 2 * M_PI * R * R * L + M_PI * r * r * H -
                 4.0 / 3 * R * R * R * ((1 + k * k) * E - (1 - k * k) * K);
  shape.area = 4 * M_PI * R * L - 4 * R * R * (E - (1 - k * k) * K) + 2 * M_PI * R * R +
               2 * M_PI * r * H - 4 * R * r * E + M_PI * r * r;
  // Faces on the sides are within their chords' sagittas (s_main, s_boss) of their cylinders;
  // next to the curve a point of a face, or of the surface, between a chord of the curve and
  // the curve is within the chord's sagitta (|curve''| dt^2 / 8) plus 2 s_main (the main
  // faces), or plus s_boss and the boss chord's height error (|dz/dt| tan^3(dt / 2) / 4, from
  // the angle a chord point sits at), of the curve.
  const double dt = 2 * M_PI / N;
  const double mainSagitta = R * (1 - std::cos(c.widestMainStep(N) / 2));
  const double bossSagitta = r * (1 - std::cos(dt / 2));
  shape.referenceMaxError = 2 * mainSagitta + bossSagitta +
                            c.curveSecondDerivativeBound() * dt * dt / 8 +
                            c.footSlopeBound() * std::pow(std::tan(dt / 2), 3) / 4;
  shape.signedDistance = [c](const Point3d &p) { return c.signedDistance(p); };
  shape.referenceTriangles = [c, N]() { return c.triangles(N); };
  return shape;
}

}  // namespace detail

/// The shape rotated about `axis` through the origin: its features are then oblique to
/// any axis-aligned grid. The bounding box is the one of the rotated reference mesh grown
/// by the reference error (tight for polyhedra).
inline Shape rotated(const Shape& shape, const Point3d& axis, double angleRadians,
                     const std::string& name) {
  const Point3d unitAxis = axis / axis.Norm();
  Shape result = shape;
  result.name = name;
  result.description = shape.description + " (rotated)";
  const std::function<double(const Point3d&)> original = shape.signedDistance;
  result.signedDistance = [original, unitAxis, angleRadians](const Point3d& p) {
    return original(detail::rotateRodrigues(p, unitAxis, -angleRadians));
  };
  const std::function<TriangleList()> originalTriangles = shape.referenceTriangles;
  result.referenceTriangles = [originalTriangles, unitAxis, angleRadians]() {
    TriangleList mesh = originalTriangles();
    for (Point3d& v : mesh.vertices) v = detail::rotateRodrigues(v, unitAxis, angleRadians);
    return mesh;
  };
  result.bbox.SetNull();
  for (const Point3d& v : result.referenceTriangles().vertices) result.bbox.Add(v);
  result.bbox.Offset(shape.referenceMaxError);
  return result;
}


/// All shapes, built once.
inline const std::vector<Shape>& allShapes() {
  static const std::vector<Shape> shapes = [] {
    std::vector<Shape> list = {detail::cube(),    detail::lblock(),     detail::wedge(),
                               detail::pyramid(), detail::crossPrism(), detail::cylinderBlock(),
                               detail::sphere()};
    // The L-block tilted so that no face, edge or corner is aligned with the grid.
    list.push_back(rotated(list[1], Point3d(1, 2, 3), 0.6, "lblock_tilted"));
    // Designed bevels and fillets beside sharp edges, oblique to the grid.
    for (const detail::FinishedPrism* p : detail::finishedPrisms())
      list.push_back(rotated(detail::finishedPrismShape(*p), p->axis, p->angle, p->name));
    // Curved sharp edges (issue 60): the cut cylinder's caps are oblique to the grid already,
    // the others are turned so that no rim lies in a grid plane.
    list.push_back(detail::cylinderCut());
    const detail::Frustum &cone = detail::coneCutParameters();
    list.push_back(rotated(detail::coneCut(), cone.axis, cone.angle, "cone_cut"));
    const detail::CutTorus &torus = detail::torusCutParameters();
    list.push_back(rotated(detail::torusCut(), torus.axis, torus.angle, "torus_cut"));
    const detail::TeeCylinders &tee = detail::twoCylindersParameters();
    list.push_back(rotated(detail::twoCylinders(), tee.axis, tee.angle, "two_cylinders"));
    // Corners of more than three faces (issue 60), turned off the grid.
    list.push_back(rotated(detail::octahedron(), Point3d(2, 1, 3), 0.5, "octahedron"));
    list.push_back(
        rotated(detail::hexagonalPyramid(), Point3d(3, 1, 2), 0.4, "hexagonal_pyramid"));
    return list;
  }();
  return shapes;
}

inline std::vector<std::string> shapeNames() {
  std::vector<std::string> names;
  for (const Shape& shape : allShapes()) names.push_back(shape.name);
  return names;
}

/// Throws std::invalid_argument for an unknown name.
inline const Shape& shapeByName(const std::string& name) {
  for (const Shape& shape : allShapes())
    if (shape.name == name) return shape;
  std::string known;
  for (const Shape& shape : allShapes()) known += (known.empty() ? "" : ", ") + shape.name;
  throw std::invalid_argument("unknown test shape '" + name + "' (known: " + known + ")");
}

/// Marching-cubes cell size that is `fraction` of the shape's bounding-box diagonal
/// (0.02 gives the "2%" meshes).
inline double cellSizeForDiagonalFraction(const Shape& shape, double fraction) {
  return fraction * shape.diagonal();
}

/// "2" for 0.02, "0.5" for 0.005: the percent used in generated file names.
inline std::string percentLabel(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", fraction * 100);
  return text;
}

/// Volume enclosed by a closed mesh (divergence theorem): positive when outward-oriented.
template <class M>
double signedVolume(const M& mesh) {
  double sixTimesVolume = 0;
  for (const auto& f : mesh.face) {
    if (f.IsD()) continue;
    const Point3d p0 = Point3d::Construct(f.cP(0));
    const Point3d p1 = Point3d::Construct(f.cP(1));
    const Point3d p2 = Point3d::Construct(f.cP(2));
    sixTimesVolume += p0 * (p1 ^ p2);
  }
  return sixTimesVolume / 6;
}

namespace detail {

template <class M>
void finishClosedMesh(M& mesh) {
  vcg::tri::UpdateTopology<M>::FaceFace(mesh);
  vcg::tri::UpdateNormal<M>::PerVertexNormalizedPerFaceNormalized(mesh);
  vcg::tri::UpdateBounding<M>::Box(mesh);
}

using McVolume = vcg::SimpleVolume<vcg::SimpleVoxel<float>>;

/// vcglib's TrivialWalker allocates its slice caches with new[] and never frees them.
template <class M>
class OwningWalker : public vcg::tri::TrivialWalker<M, McVolume> {
 public:
  OwningWalker() = default;
  OwningWalker(const OwningWalker&) = delete;
  OwningWalker& operator=(const OwningWalker&) = delete;
  ~OwningWalker() {
    if (this->_slice_dimension == 0) return;
    delete[] this->_x_cs;
    delete[] this->_y_cs;
    delete[] this->_z_cs;
    delete[] this->_x_ns;
    delete[] this->_z_ns;
  }
};

}  // namespace detail

/// The exact reference mesh: closed, outward-oriented, 2-manifold; FF adjacency, normals
/// and bounding box updated.
template <class M>
void buildReference(const Shape& shape, M& mesh) {
  vcg::tri::RequireFFAdjacency(mesh);
  const TriangleList triangles = shape.referenceTriangles();
  mesh.Clear();
  auto vertex = vcg::tri::Allocator<M>::AddVertices(mesh, triangles.vertices.size());
  for (const Point3d& p : triangles.vertices) (vertex++)->P().Import(p);
  auto face = vcg::tri::Allocator<M>::AddFaces(mesh, triangles.triangles.size());
  for (const auto& t : triangles.triangles) {
    for (int i = 0; i < 3; ++i) face->V(i) = &mesh.vert[t[i]];
    ++face;
  }
  detail::finishClosedMesh(mesh);
}

/// The regular grid marchingCubes() samples the distance function on: node (x, y, z), with
/// 0 <= x < nodes[0] etc., is at origin + (x, y, z) * cellSize (computed in exactly that way).
/// dual_contouring.h samples the same grid.
struct SamplingGrid {
  Point3d origin;
  double cellSize = 0;
  vcg::Point3i nodes;

  Point3d node(int x, int y, int z) const { return origin + Point3d(x, y, z) * cellSize; }
};

/// The grid of marchingCubes(shape, cellSize): two node layers of padding outside the
/// bounding box, and planes shifted by fixed fractions of a cell (not multiples of any
/// feature coordinate), so grid planes cut the features at generic positions.
inline SamplingGrid marchingCubesGrid(const Shape& shape, double cellSize) {
  if (!(cellSize > 0) || !std::isfinite(cellSize))
    throw std::invalid_argument("marchingCubes: cell size must be positive");
  const double h = cellSize;
  // At least one node layer outside the box on each side keeps the surface closed.
  const int padding = 2;
  const Point3d offset = Point3d(0.3183099, 0.2718282, 0.1414214) * h;
  SamplingGrid grid;
  grid.cellSize = h;
  grid.origin = shape.bbox.min - Point3d(padding, padding, padding) * h - offset;
  for (int i = 0; i < 3; ++i)
    grid.nodes[i] =
        static_cast<int>(std::ceil((shape.bbox.max[i] - grid.origin[i]) / h)) + padding + 2;
  const double nodes = double(grid.nodes[0]) * grid.nodes[1] * grid.nodes[2];
  if (nodes > 2e9) throw std::invalid_argument("marchingCubes: cell size too small");
  return grid;
}

/// Marching cubes of the shape's distance function on a grid of cubic cells of side
/// `cellSize`, marchingCubesGrid(): grid planes cut the features at generic positions, so sharp
/// edges/corners come out chamfered. The output is deterministic, closed, outward-oriented
/// and 2-manifold, without duplicate or unreferenced vertices or zero-area faces; FF
/// adjacency, normals and bounding box are updated. Memory: one float per grid node.
template <class M>
void marchingCubes(const Shape& shape, double cellSize, M& mesh) {
  vcg::tri::RequireFFAdjacency(mesh);
  const SamplingGrid grid = marchingCubesGrid(shape, cellSize);
  const double h = grid.cellSize;
  const Point3d& origin = grid.origin;
  const vcg::Point3i& size = grid.nodes;

  detail::McVolume volume;
  const Point3d extent = Point3d(size[0], size[1], size[2]) * h;
  volume.Init(
      size, vcg::Box3f(vcg::Point3f::Construct(origin), vcg::Point3f::Construct(origin + extent)));
  // A node exactly on the surface would put a vertex on several cell edges at once and
  // leave degenerate triangles: nudge it outward by a negligible amount.
  const float onSurfaceNudge = static_cast<float>(1e-4 * h);
  for (int z = 0; z < size[2]; ++z)
    for (int y = 0; y < size[1]; ++y)
      for (int x = 0; x < size[0]; ++x) {
        const float value = static_cast<float>(shape.signedDistance(grid.node(x, y, z)));
        volume.Val(x, y, z) = value == 0.0f ? onSurfaceNudge : value;
      }

  detail::OwningWalker<M> walker;
  vcg::tri::MarchingCubes<M, detail::OwningWalker<M>> extractor(mesh, walker);
  walker.BuildMesh(mesh, volume, extractor, 0.0f);

  vcg::tri::Clean<M>::RemoveDuplicateVertex(mesh);
  vcg::tri::Clean<M>::RemoveZeroAreaFace(mesh);
  vcg::tri::Clean<M>::RemoveUnreferencedVertex(mesh);
  vcg::tri::Allocator<M>::CompactEveryVector(mesh);
  if (signedVolume(mesh) < 0) vcg::tri::Clean<M>::FlipMesh(mesh);
  detail::finishClosedMesh(mesh);
}

}  // namespace test_meshes
}  // namespace edge_sharpener
