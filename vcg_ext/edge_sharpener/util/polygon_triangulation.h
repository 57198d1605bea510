// Triangulation of a simple planar polygon (ear clipping): the pure geometry
// behind guards/planar_folds.h. No mesh here.
#pragma once

#include <vcg/space/point2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "geometry.h"

namespace edge_sharpener {

using Vec2 = vcg::Point2d;

namespace detail {

inline double cross2(const Vec2 &a, const Vec2 &b, const Vec2 &c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/// Whether closed segments pq and rs share a point.
inline bool segmentsTouch(const Vec2 &p, const Vec2 &q, const Vec2 &r, const Vec2 &s) {
  const double d1 = cross2(r, s, p), d2 = cross2(r, s, q), d3 = cross2(p, q, r),
               d4 = cross2(p, q, s);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  const auto onSegment = [](const Vec2 &a, const Vec2 &b, const Vec2 &x) {
    return std::min(a[0], b[0]) <= x[0] && x[0] <= std::max(a[0], b[0]) &&
           std::min(a[1], b[1]) <= x[1] && x[1] <= std::max(a[1], b[1]);
  };
  return (d1 == 0 && onSegment(r, s, p)) || (d2 == 0 && onSegment(r, s, q)) ||
         (d3 == 0 && onSegment(p, q, r)) || (d4 == 0 && onSegment(p, q, s));
}

/// The smallest angle (radians) of triangle abc; 0 when degenerate.
inline double minAngle2(const Vec2 &a, const Vec2 &b, const Vec2 &c) {
  return minTriangleAngle(Vec3(a[0], a[1], 0), Vec3(b[0], b[1], 0), Vec3(c[0], c[1], 0));
}

}  // namespace detail

/// Whether `polygon` (a closed outline, no point repeated) is simple: no two
/// of its edges meet except consecutive ones at their shared end. Pure.
inline bool isSimplePolygon(const std::vector<Vec2> &polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      const Vec2 &a = polygon[i], &b = polygon[(i + 1) % n];
      const Vec2 &c = polygon[j], &d = polygon[(j + 1) % n];
      if (!adjacent) {
        if (detail::segmentsTouch(a, b, c, d)) return false;
      } else if (polygon[i] == polygon[j]) {
        return false;
      }
    }
  return true;
}

/// Signed area of a closed outline: positive when counter-clockwise. Pure.
inline double signedArea(const std::vector<Vec2> &polygon) {
  double twice = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 &a = polygon[i], &b = polygon[(i + 1) % polygon.size()];
    twice += a[0] * b[1] - a[1] * b[0];
  }
  return twice / 2;
}

/// Triangles (indices into `polygon`, counter-clockwise) tiling a simple
/// counter-clockwise polygon, n - 2 of them, each with all its angles at
/// least `minAngleRad`: ear clipping, the ear with the largest smallest angle
/// first. Empty when the polygon is not simple, not counter-clockwise, or
/// has no such tiling by ears. Pure; quadratic in n per ear.
inline std::vector<std::array<int, 3>> triangulateSimplePolygon(const std::vector<Vec2> &polygon,
                                                                double minAngleRad) {
  std::vector<std::array<int, 3>> out;
  if (!isSimplePolygon(polygon) || !(signedArea(polygon) > 0)) return out;
  std::vector<int> left(polygon.size());
  for (std::size_t i = 0; i < left.size(); ++i) left[i] = int(i);
  while (left.size() > 3) {
    const std::size_t n = left.size();
    int best = -1;
    double bestAngle = minAngleRad;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 &a = polygon[left[(i + n - 1) % n]], &b = polygon[left[i]],
                 &c = polygon[left[(i + 1) % n]];
      if (!(detail::cross2(a, b, c) > 0)) continue;  // reflex or flat: not an ear
      bool empty = true;                             // no other outline point inside or on the ear
      for (std::size_t j = 0; j < n && empty; ++j) {
        if (j == i || j == (i + 1) % n || j == (i + n - 1) % n) continue;
        const Vec2 &p = polygon[left[j]];
        empty = !(detail::cross2(a, b, p) >= 0 && detail::cross2(b, c, p) >= 0 &&
                  detail::cross2(c, a, p) >= 0);
      }
      const double angle = detail::minAngle2(a, b, c);
      if (empty && angle >= bestAngle) bestAngle = angle, best = int(i);
    }
    if (best < 0) return {};
    out.push_back({left[(best + n - 1) % n], left[best], left[(best + 1) % n]});
    left.erase(left.begin() + best);
  }
  if (!(detail::cross2(polygon[left[0]], polygon[left[1]], polygon[left[2]]) > 0) ||
      detail::minAngle2(polygon[left[0]], polygon[left[1]], polygon[left[2]]) < minAngleRad)
    return {};
  out.push_back({left[0], left[1], left[2]});
  return out;
}

}  // namespace edge_sharpener
