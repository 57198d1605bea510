// A flank as a curved surface (Sharpen&Bend, Attene et al. 2005, in its
// simplest form): the plane fitted next to a feature, bent by the curvature
// its fitted faces show. Each fit records how the faces' normals deviate
// with their position (placement.h: SupportFit's scatters); the regression
// of one on the other is the shape operator K of the flank, and the flank is
// the quadric height field over the plane that turns its normals so. Pure.
#pragma once

#include <cmath>
#include <optional>

#include "geometry.h"

namespace edge_sharpener {

/// A flank near a feature: a height field over `plane`, in its in-plane
/// basis (u, v): height = offset - (x K x) / 2 for x = (u, v), K symmetric.
struct CurvedFlank {
  Plane plane;
  Vec3 u{0, 0, 0}, v{0, 0, 0};
  double kuu = 0, kuv = 0, kvv = 0;
  /// The fitted faces' position scatter in the plane (u u, u v, v v).
  double cuu = 0, cuv = 0, cvv = 0;

  /// The height of the surface at the plane's point: the plane through the
  /// fitted faces' centroids lies inside a convex flank by the mean of
  /// (x K x) / 2 over them.
  double offset() const { return 0.5 * (kuu * cuu + 2 * kuv * cuv + kvv * cvv); }

  bool curved() const { return kuu != 0 || kuv != 0 || kvv != 0; }
  /// Signed distance-like residual of x: its height over the plane minus
  /// the flank's there (zero on the flank, positive outside).
  double residual(const Vec3 &x) const {
    const Vec3 d = x - plane.point;
    const double a = d * u, b = d * v;
    return d * plane.normal - offset() + 0.5 * (kuu * a * a + 2 * kuv * a * b + kvv * b * b);
  }
  /// The residual's gradient at x.
  Vec3 gradient(const Vec3 &x) const {
    const Vec3 d = x - plane.point;
    const double a = d * u, b = d * v;
    return plane.normal + u * (kuu * a + kuv * b) + v * (kuv * a + kvv * b);
  }
};

/// Two unit vectors spanning the plane orthogonal to unit `n`.
inline void inPlaneBasis(const Vec3 &n, Vec3 &u, Vec3 &v) {
  const Vec3 helper = std::abs(n[0]) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  u = (helper ^ n).Normalize();
  v = n ^ u;
}

/// The flank of `plane` whose fitted faces' normal deviations and positions
/// (relative to the plane's normal and point, area-weighted means) have
/// cross-scatter `normalPosition` and scatter `positionScatter`
/// (geometry.h: CrossScatter3): K = N C^-1 in the plane, symmetrised. A flat
/// flank (K = 0) where the positions span no area in the plane.
/// `along`: the basis' first direction (projected into the plane; any when
/// it has none there).
inline CurvedFlank curvedFlank(const Plane &plane, const CrossScatter3 &normalPosition,
                               const CrossScatter3 &positionScatter,
                               const Vec3 &along = Vec3(0, 0, 0)) {
  CurvedFlank f;
  f.plane = plane;
  inPlaneBasis(plane.normal, f.u, f.v);
  const Vec3 inPlane = along - plane.normal * (plane.normal * along);
  if (inPlane.Norm() > 1e-9) {
    f.u = inPlane / inPlane.Norm();
    f.v = plane.normal ^ f.u;
  }
  const auto bilinear = [](const CrossScatter3 &s, const Vec3 &a, const Vec3 &b) {
    double sum = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) sum += a[i] * s.a[3 * i + j] * b[j];
    return sum;
  };
  // Scatters: C (positions), N (normal deviation against position).
  const double cuu = bilinear(positionScatter, f.u, f.u), cuv = bilinear(positionScatter, f.u, f.v),
               cvv = bilinear(positionScatter, f.v, f.v);
  f.cuu = cuu, f.cuv = cuv, f.cvv = cvv;
  const double nuu = bilinear(normalPosition, f.u, f.u), nuv = bilinear(normalPosition, f.u, f.v),
               nvu = bilinear(normalPosition, f.v, f.u), nvv = bilinear(normalPosition, f.v, f.v);
  const double det = cuu * cvv - cuv * cuv;
  if (!(det > 1e-12 * (cuu + cvv) * (cuu + cvv))) return f;
  // The normal turns by K along position: [n_u n_v] = K [x_u x_v], so the
  // height bends by -K/2 (a convex flank's normals turn outward).
  const double iuu = cvv / det, iuv = -cuv / det, ivv = cuu / det;
  const double k11 = nuu * iuu + nuv * iuv, k12 = nuu * iuv + nuv * ivv;
  const double k21 = nvu * iuu + nvv * iuv, k22 = nvu * iuv + nvv * ivv;
  f.kuu = k11;
  f.kuv = 0.5 * (k12 + k21);
  f.kvv = k22;
  return f;
}

/// The point on both flanks nearest `start` (Gauss-Newton, each step the
/// least-norm one onto the two surfaces' tangent planes), or none when the
/// flanks meet nowhere near: their gradients turn parallel, or the
/// iteration does not settle within `tolerance`.
inline std::optional<Vec3> onBothFlanks(const CurvedFlank &a, const CurvedFlank &b,
                                        const Vec3 &start, double tolerance, int iterations = 20) {
  Vec3 x = start;
  for (int it = 0; it < iterations; ++it) {
    const double fa = a.residual(x), fb = b.residual(x);
    if (std::abs(fa) <= tolerance && std::abs(fb) <= tolerance) return x;
    const Vec3 ga = a.gradient(x), gb = b.gradient(x);
    const double aa = ga * ga, ab = ga * gb, bb = gb * gb;
    const double det = aa * bb - ab * ab;
    if (!(det > 1e-12 * aa * bb)) return std::nullopt;
    // Least-norm step s = J^T (J J^T)^-1 F.
    const double la = (bb * fa - ab * fb) / det, lb = (aa * fb - ab * fa) / det;
    x -= ga * la + gb * lb;
  }
  if (std::abs(a.residual(x)) <= tolerance && std::abs(b.residual(x)) <= tolerance) return x;
  return std::nullopt;
}

}  // namespace edge_sharpener
