// Pure geometry of Edge-Sharpener: plane intersections and the tests of the
// paper's degenerate cases. No mesh here; everything in double precision.
//
// Notation (paper, section 3): a chamfer edge AB; P is the plane through A
// with unit normal N, Q the plane through B with unit normal M; a corner
// triangle ABC adds the plane R through C with unit normal L.
#pragma once

#include <vcg/space/distance3.h>
#include <vcg/space/point3.h>
#include <vcg/space/triangle3.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace edge_sharpener {

using Vec3 = vcg::Point3d;

/// A plane {X : normal . X = normal . point}; `normal` has unit length.
struct Plane {
  Vec3 point;
  Vec3 normal;
};

/// Region r's plane in `regionPlanes` (one per region, a zero normal where
/// the region is no plane: planar_regions.h, planarRegionPlanes), or nullptr
/// where r is no region or its region no plane.
inline const Plane *regionPlaneOf(const std::vector<Plane> &regionPlanes, int r) {
  if (r < 0 || std::size_t(r) >= regionPlanes.size()) return nullptr;
  const Plane &p = regionPlanes[std::size_t(r)];
  return p.normal.SquaredNorm() > 0 ? &p : nullptr;
}

/// Angle between two vectors in [0, pi]; 0 when either is zero.
inline double angleBetween(const Vec3 &u, const Vec3 &v) {
  return std::atan2((u ^ v).Norm(), u * v);
}

/// The angle (radians, in [0, pi/2]) between the line where planes of unit
/// normals `a` and `b` meet and a surface of unit normal `surface`: 0 when
/// the line runs along the surface (a sharp edge along its chamfer), pi/2
/// when it pierces it. pi/2 when the planes are parallel or `surface` is
/// zero. Pure.
inline double lineAngleToSurface(const Vec3 &a, const Vec3 &b, const Vec3 &surface) {
  const Vec3 line = a ^ b;
  const double scale = line.Norm() * surface.Norm();
  if (!(scale > 0)) return M_PI / 2;
  return std::asin(std::min(std::abs(line * surface) / scale, 1.0));
}

/// The point of the line P∩Q closest to `target`, or nothing when the planes
/// are parallel within `parallelAngleRad`.
///
/// Derivation: the closest point is X = target + a N + b M (the correction is
/// orthogonal to the line direction N x M). Imposing N.X = N.A and M.X = M.B
/// with c = N.M gives  [1 c; c 1] [a b]^T = [hN hM]^T,  hN = N.(A - target),
/// hM = M.(B - target), whose determinant 1 - c^2 = |N x M|^2 vanishes
/// exactly for parallel planes. (The paper's printed closed form is damaged;
/// this solves the same problem directly.)
inline std::optional<Vec3> closestPointOnPlanePairLine(const Plane &p, const Plane &q,
                                                       const Vec3 &target,
                                                       double parallelAngleRad) {
  const double sinTol = std::sin(parallelAngleRad);
  const double det = (p.normal ^ q.normal).SquaredNorm();  // = 1 - c^2
  if (!(det > sinTol * sinTol)) return std::nullopt;       // also rejects NaN
  const double c = p.normal * q.normal;
  const double hN = p.normal * (p.point - target);
  const double hM = q.normal * (q.point - target);
  const double a = (hN - c * hM) / det;
  const double b = (hM - c * hN) / det;
  return target + p.normal * a + q.normal * b;
}

/// The common point of three planes (Cramer's rule), or nothing when their
/// normals are coplanar: |N . (M x L)| below sin(parallelAngleRad).
inline std::optional<Vec3> intersectThreePlanes(const Plane &p, const Plane &q, const Plane &r,
                                                double parallelAngleRad) {
  const Vec3 &n = p.normal, &m = q.normal, &l = r.normal;
  const double triple = n * (m ^ l);
  if (!(std::abs(triple) > std::sin(parallelAngleRad))) return std::nullopt;
  const double dn = n * p.point, dm = m * q.point, dl = l * r.point;
  return ((m ^ l) * dn + (l ^ n) * dm + (n ^ m) * dl) / triple;
}

/// A point `onLine` of the line where the planes P and Q meet, kept on the
/// side of a third plane L where the points `p` of P and `q` of Q lie: the
/// line of an edge ends at the corner where it meets the face L, and a point
/// beyond L moves to that corner. \return the point, the corner, or nothing
/// when `p` and `q` lie on different sides of L (or on it) or the three
/// normals are coplanar within `parallelAngleRad`.
inline std::optional<Vec3> keepBeforeEndPlane(const Plane &p, const Plane &q, const Plane &l,
                                              const Vec3 &onLine, double parallelAngleRad) {
  const double side = l.normal * (p.point - l.point);
  if (!(side * (l.normal * (q.point - l.point)) > 0)) return std::nullopt;
  if ((l.normal * (onLine - l.point)) * side >= 0) return onLine;
  return intersectThreePlanes(p, q, l, parallelAngleRad);
}

/// How a chamfer edge AB sits between the planes P (through A) and Q (through B).
enum class EdgeConvexity { Convex, Concave, Mixed, Flat };

/// Classifies the chamfer edge AB by where each endpoint lies relative to the
/// other endpoint's plane. Across a convex sharp edge B lies below P and A
/// below Q; across a concave one both lie above. One above and one below
/// means the chamfer strip is bordered by a concave edge on one side and a
/// convex edge on the other (paper, section 3): its plane intersection does
/// not describe a sharp edge. Offsets below `flatTolerance` x |AB| count as 0.
inline EdgeConvexity classifyChamferEdge(const Plane &p, const Plane &q, double flatTolerance) {
  const Vec3 ab = q.point - p.point;
  const double tol = flatTolerance * ab.Norm();
  const double sB = p.normal * ab;     // B relative to P
  const double sA = -(q.normal * ab);  // A relative to Q
  const auto sign = [tol](double s) { return s > tol ? 1 : (s < -tol ? -1 : 0); };
  const int b = sign(sB), a = sign(sA);
  if (a == 0 || b == 0)
    return a + b < 0   ? EdgeConvexity::Convex
           : a + b > 0 ? EdgeConvexity::Concave
                       : EdgeConvexity::Flat;
  if (a != b) return EdgeConvexity::Mixed;
  return a < 0 ? EdgeConvexity::Convex : EdgeConvexity::Concave;
}

/// How far the sharp edge X (a point of the line P∩Q) stands above the
/// chamfer AB (A = p.point, B = q.point), relative to the most the angle
/// between the planes allows. In the cross-section orthogonal to the line,
/// A', B' and X' form a triangle whose angle at X' is pi - theta (theta: the
/// angle between the normals), so the height of X' over A'B' is at most
/// |A'B'|/2 tan(theta/2), reached when the chamfer is symmetric. A ratio well
/// above 1 means P and Q do not meet across this chamfer: another surface
/// lies between them (e.g. a facet narrower than the sampling).
/// \return the ratio, or +infinity when the cross-section degenerates.
inline double chamferApexHeightRatio(const Plane &p, const Plane &q, const Vec3 &x) {
  Vec3 u = p.normal ^ q.normal;
  const double len = u.Norm();
  if (!(len > 0)) return std::numeric_limits<double>::infinity();
  u /= len;
  const auto project = [&u](const Vec3 &v) { return v - u * (u * v); };
  const Vec3 a = project(p.point), b = project(q.point), apex = project(x);
  const Vec3 base = b - a;
  const double baseLen = base.Norm();
  const double theta = angleBetween(p.normal, q.normal);
  const double bound = 0.5 * baseLen * std::tan(0.5 * theta);
  if (!(bound > 0)) return std::numeric_limits<double>::infinity();
  const double height = ((apex - a) ^ base).Norm() / baseLen;
  return height / bound;
}

/// Whether the normal of a third plane L lies on the way from P's normal to
/// Q's: within `slackRad` of the shortest arc between them. Such a plane is an
/// intermediate facet or a strip of a blend between the two flanks.
inline bool normalBetween(const Vec3 &np, const Vec3 &nq, const Vec3 &nl, double slackRad) {
  return angleBetween(np, nl) + angleBetween(nl, nq) <= angleBetween(np, nq) + slackRad;
}

/// How far the sharp point x, reached from `rest` on the chamfer, passes
/// through plane L: measured along L's normal, positive when x lies outside
/// L at a convex feature (x moved outward, along `flankNormalSum`, the sum
/// of the flanks' normals) or inside L at a concave one. A point beyond an
/// intermediate plane cuts through the surface that plane samples.
inline double passageBeyondPlane(const Vec3 &flankNormalSum, const Plane &l, const Vec3 &rest,
                                 const Vec3 &x) {
  const double outward = (x - rest) * flankNormalSum;
  const double side = l.normal * (x - l.point);
  return outward >= 0 ? side : -side;
}

/// A 3x3 matrix in single precision accumulating weighted outer products
/// u v^T (a cross-covariance), row-major.
struct CrossScatter3 {
  std::array<float, 9> a{};
  /// Adds weight * u v^T.
  void add(const Vec3 &u, const Vec3 &v, double weight) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) a[3 * i + j] += float(weight * u[i] * v[j]);
  }
  void scale(double s) {
    for (float &x : a) x = float(x * s);
  }
  /// w^T M w.
  double along(const Vec3 &w) const {
    double sum = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) sum += w[i] * a[3 * i + j] * w[j];
    return sum;
  }
};

/// How far a surface bends away from its fitted plane over `distance` along
/// unit direction w. The curvature along w is the regression slope of the
/// fitted faces' normal deviations on their positions along w: the
/// normal-position cross-scatter over the position scatter (normals of a
/// cylinder turn in proportion to position across its axis; the staircase
/// noise of marching cubes does not correlate with position). A curve of
/// curvature k leaves its tangent by k d^2 / 2.
inline double extrapolationBend(const CrossScatter3 &normalPosition,
                                const CrossScatter3 &positionScatter, const Vec3 &w,
                                double distance) {
  const double turn = std::abs(normalPosition.along(w)), extent = positionScatter.along(w);
  if (!(turn > 0)) return 0.0;
  if (!(extent > 0)) return std::numeric_limits<double>::infinity();
  return 0.5 * (turn / extent) * distance * distance;
}

/// How much of the normals' turning along unit direction w the linear model
/// of extrapolationBend() explains: the squared correlation of the fitted
/// faces' normal deviation along w with their position along w, in [0, 1]
/// (near 1: a cleanly sampled curve; near 0: staircase noise). 0 when not
/// measurable.
inline double curveFitQuality(const CrossScatter3 &normalPosition,
                              const CrossScatter3 &positionScatter, const CrossScatter3 &normalSelf,
                              const Vec3 &w) {
  const double turn = normalPosition.along(w), extent = positionScatter.along(w),
               spread = normalSelf.along(w);
  if (!(extent > 0) || !(spread > 0)) return 0.0;
  return std::min(1.0, turn * turn / (extent * spread));
}

/// Smallest interior angle of triangle abc in radians (0 for a degenerate one).
inline double minTriangleAngle(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  const double ta = angleBetween(b - a, c - a);
  const double tb = angleBetween(c - b, a - b);
  const double tc = angleBetween(a - c, b - c);
  const double m = std::min({ta, tb, tc});
  return std::isfinite(m) ? m : 0.0;
}

/// Normal of triangle abc, scaled by twice its area (zero when degenerate).
inline Vec3 triangleNormal(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  return (b - a) ^ (c - a);
}

/// The distance from `p` to the nearest of `triangles` (infinite if none).
inline double distanceToTriangles(const Vec3 &p,
                                  const std::vector<vcg::Triangle3<double>> &triangles) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto &t : triangles) {
    double d;
    Vec3 closest;
    vcg::TrianglePointDistance(t, p, d, closest);
    nearest = std::min(nearest, d);
  }
  return nearest;
}

/// Largest interior angle of triangle abc in radians.
inline double maxTriangleAngle(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  return std::max(
      {angleBetween(b - a, c - a), angleBetween(c - b, a - b), angleBetween(a - c, b - c)});
}

/// Whether two corners of triangle a b c lie at one point: an edge shorter
/// than a float's rounding of the longest (1e-5 of it). Pure.
inline bool hasCoincidentCorners(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  const double ab = (b - a).Norm(), bc = (c - b).Norm(), ca = (a - c).Norm();
  return std::min({ab, bc, ca}) <= 1e-5 * std::max({ab, bc, ca});
}

/// Whether `p` lies on `plane` or on the side of it where `reference` lies.
/// Where two planes meet, the part of one plane that is the surface lies on
/// the other plane's side where that face's own samples lie, convex edge or
/// concave.
inline bool onSideOf(const Plane &plane, const Vec3 &p, const Vec3 &reference) {
  const double side = plane.normal * (p - plane.point);
  return side == 0 || side * (plane.normal * (reference - plane.point)) > 0;
}

/// The foot of the perpendicular from `p` onto `plane`. Pure.
inline Vec3 projectOntoPlane(const Plane &plane, const Vec3 &p) {
  return p - plane.normal * (plane.normal * (p - plane.point));
}

/// The point nearest `p` of the convex set that lies behind every plane of
/// `planes` (opposite their normals), `p` itself when it lies there. The
/// nearest point lies on one of the set's faces, edges or corners, each the
/// meet of one, two or three of the planes: of those candidates, the nearest
/// one behind every plane, within `slack`. Nothing when none is (pairs or
/// triples of planes within `parallelAngleRad` of parallel span no edge or
/// corner). Pure.
inline std::optional<Vec3> nearestPointBehindPlanes(const Vec3 &p, const std::vector<Plane> &planes,
                                                    double slack, double parallelAngleRad) {
  const auto behindAll = [&](const Vec3 &x) {
    for (const Plane &plane : planes)
      if (!(plane.normal * (x - plane.point) <= slack)) return false;
    return true;
  };
  if (behindAll(p)) return p;
  std::optional<Vec3> nearest;
  double nearestSquared = std::numeric_limits<double>::infinity();
  const auto consider = [&](const std::optional<Vec3> &x) {
    if (!x || !behindAll(*x)) return;
    const double squared = (*x - p).SquaredNorm();
    if (squared < nearestSquared) nearestSquared = squared, nearest = x;
  };
  const std::size_t n = planes.size();
  for (std::size_t i = 0; i < n; ++i) consider(projectOntoPlane(planes[i], p));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      consider(closestPointOnPlanePairLine(planes[i], planes[j], p, parallelAngleRad));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = j + 1; k < n; ++k)
        consider(intersectThreePlanes(planes[i], planes[j], planes[k], parallelAngleRad));
  return nearest;
}

/// The plane through `points` by weighted least squares: through their
/// weighted centroid, its normal the direction in which they spread least,
/// turned to the side of `towards`. A zero normal where the weights sum to
/// zero. (vcglib's WeightedFitPlaneToPointSet squares the weights in its
/// covariance.) \pre weights.size() == points.size(), no weight negative.
/// Pure.
inline Plane fitPlaneLeastSquares(const std::vector<Vec3> &points,
                                  const std::vector<double> &weights, const Vec3 &towards) {
  Vec3 centre(0, 0, 0);
  double total = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    centre += points[i] * weights[i], total += weights[i];
  if (!(total > 0)) return Plane{Vec3(0, 0, 0), Vec3(0, 0, 0)};
  centre /= total;
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 d = points[i] - centre;
    const Eigen::Vector3d e(d[0], d[1], d[2]);
    spread += weights[i] * e * e.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(spread);
  const Eigen::Vector3d least = solver.eigenvectors().col(0);  // eigenvalues ascend
  Vec3 normal(least[0], least[1], least[2]);
  normal.Normalize();
  return Plane{centre, normal * towards < 0 ? -normal : normal};
}

/// fitPlaneLeastSquares, then again without the points farther from that
/// plane than `trimFactor` times their weighted RMS distance to it: a few
/// points off a plane (the bulge a fused scan leaves along a face's rim)
/// tilt a least-squares fit. At most 1 / trimFactor^2 of the weight is
/// dropped (Chebyshev), so the second fit keeps most points. Pure.
inline Plane fitPlaneTrimmed(const std::vector<Vec3> &points, const std::vector<double> &weights,
                             const Vec3 &towards, double trimFactor) {
  const Plane first = fitPlaneLeastSquares(points, weights, towards);
  if (first.normal.SquaredNorm() == 0) return first;
  double squares = 0, total = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double h = first.normal * (points[i] - first.point);
    squares += weights[i] * h * h, total += weights[i];
  }
  const double bound = trimFactor * std::sqrt(squares / total);
  std::vector<double> kept(weights);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (std::abs(first.normal * (points[i] - first.point)) > bound) kept[i] = 0;
  const Plane second = fitPlaneLeastSquares(points, kept, towards);
  return second.normal.SquaredNorm() > 0 ? second : first;
}

/// Interior angle at vertex `a` of triangle abc (the paper's weight).
inline double cornerAngle(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
  return angleBetween(b - a, c - a);
}

/// Whether p lies on the segment ab, up to the rounding of single-precision
/// coordinates (a mesh stores floats): then the triangles (a, p, x) and
/// (p, b, x) cover exactly the triangle (a, b, x).
inline bool liesOnSegment(const Vec3 &p, const Vec3 &a, const Vec3 &b) {
  const Vec3 ab = b - a;
  const double length2 = ab.SquaredNorm();
  if (!(length2 > 0)) return false;
  const double t = ((p - a) * ab) / length2;
  double scale = std::sqrt(length2);
  for (int i = 0; i < 3; ++i)
    scale = std::max({scale, std::abs(a[i]), std::abs(b[i]), std::abs(p[i])});
  const double tolerance = 4 * std::numeric_limits<float>::epsilon() * scale;
  return t >= 0 && t <= 1 && (p - (a + ab * t)).Norm() <= tolerance;
}

/// Where the segment ab passes through the plane of triangle t, when it
/// does so between its ends and within the triangle (edges included): the
/// barycentric coordinates (u, v) of that point along t's edges from t[0]
/// (Moeller and Trumbore). A segment within kGrazingSine (0.01, about half a
/// degree) of parallel to the plane lies in it: nearly coplanar faces graze
/// rather than cross. The bound is an angle, so the answer does not depend
/// on the model's unit. (vcglib's IntersectionSegmentTriangle bounds a
/// determinant in squared units by 1e-6: on the benchmark's models of about
/// unit size that is 0.03-0.4 degrees, and on a model a hundredth of a unit
/// in size every segment lay in the plane.) Pure.
inline std::optional<std::array<double, 2>> segmentThroughTriangle(const Vec3 &a, const Vec3 &b,
                                                                   const std::array<Vec3, 3> &t) {
  const Vec3 d = b - a, e1 = t[1] - t[0], e2 = t[2] - t[0];
  const Vec3 pvec = d ^ e2;
  const double det = e1 * pvec;
  constexpr double kGrazingSine = 0.01;
  if (!(std::abs(det) > kGrazingSine * d.Norm() * (e1 ^ e2).Norm())) return std::nullopt;
  const Vec3 tvec = a - t[0], qvec = tvec ^ e1;
  const double u = (tvec * pvec) / det, v = (d * qvec) / det, along = (e2 * qvec) / det;
  if (u < 0 || v < 0 || u + v > 1 || !(along > 0 && along < 1)) return std::nullopt;
  return std::array<double, 2>{u, v};
}

/// Whether triangles p and q are apart by a visible gap along one of the
/// separating-axis theorem's axes: the two normals, the nine cross products
/// of their edges, each normal crossed with the edges of its own triangle
/// (for coplanar triangles) and the coordinate axes (for degenerate ones). A gap must exceed 1e-9
/// of the pair's size, so triangles that touch are never called apart. (vcglib's Moeller test can
/// report two coplanar triangles a tenth of their size apart as intersecting; this test lets them
/// go first.)
inline bool trianglesApart(const std::array<Vec3, 3> &p, const std::array<Vec3, 3> &q) {
  // The largest of nine lengths, with one square root (it preserves order).
  double size2 = 0;
  for (const auto *t : {&p, &q})
    for (int k = 0; k < 3; ++k)
      size2 = std::max(size2, ((*t)[k] - (*t)[(k + 1) % 3]).SquaredNorm());
  for (int k = 0; k < 3; ++k) size2 = std::max(size2, (p[k] - q[k]).SquaredNorm());
  const double size = std::sqrt(size2);
  const auto apartAlong = [&](const Vec3 &axis) {
    const double gap = 1e-9 * size * axis.Norm();
    double pLo = p[0] * axis, pHi = pLo, qLo = q[0] * axis, qHi = qLo;
    for (int k = 1; k < 3; ++k) {
      pLo = std::min(pLo, p[k] * axis), pHi = std::max(pHi, p[k] * axis);
      qLo = std::min(qLo, q[k] * axis), qHi = std::max(qHi, q[k] * axis);
    }
    return pHi + gap < qLo || qHi + gap < pLo;
  };
  std::array<Vec3, 3> pe, qe;
  for (int k = 0; k < 3; ++k) pe[k] = p[(k + 1) % 3] - p[k], qe[k] = q[(k + 1) % 3] - q[k];
  const Vec3 pn = pe[0] ^ pe[1], qn = qe[0] ^ qe[1];
  if (apartAlong(Vec3(1, 0, 0)) || apartAlong(Vec3(0, 1, 0)) || apartAlong(Vec3(0, 0, 1)))
    return true;
  if (apartAlong(pn) || apartAlong(qn)) return true;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (apartAlong(pe[i] ^ qe[j])) return true;
  for (int k = 0; k < 3; ++k)
    if (apartAlong(pn ^ pe[k]) || apartAlong(qn ^ qe[k])) return true;
  return false;
}

}  // namespace edge_sharpener
