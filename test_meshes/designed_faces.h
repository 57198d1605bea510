// The designed features of the generated test shapes made as finished prisms
// (bevelled_block, finished_hexprism: shapes.h), and the faces of a sampling
// that lie on them: what a user who knows the part deselects before
// sharpening (issue 61).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "test_meshes/shapes.h"

namespace edge_sharpener::test_meshes {

/// One designed finish of a finished prism's vertical edge: a bevel or a
/// fillet, with its outline points in the unturned prism's frame (from where
/// it leaves the side before the corner to where it meets the side after it).
struct DesignedFinish {
  detail::CornerFinish::Kind kind = detail::CornerFinish::Bevel;
  double size = 0;  ///< a bevel's width, a fillet's radius
  std::vector<Point2d> strip;
  /// Its width across: from one end of its strip to the other.
  double width() const { return (strip.back() - strip.front()).Norm(); }
  const char *kindName() const { return kind == detail::CornerFinish::Bevel ? "bevel" : "fillet"; }
};

/// The finished prism the shape `name` is made from; null for the other shapes.
inline const detail::FinishedPrism *finishedPrism(const std::string &name) {
  for (const detail::FinishedPrism *p : detail::finishedPrisms())
    if (p->name == name) return p;
  return nullptr;
}

/// The prism's designed finishes, in corner order (sharp corners left out).
inline std::vector<DesignedFinish> designedFinishes(const detail::FinishedPrism &p) {
  std::vector<DesignedFinish> out;
  const std::vector<std::vector<Point2d>> corners = detail::finishedCorners(p.corners, p.finish);
  for (std::size_t i = 0; i < corners.size(); ++i)
    if (p.finish[i].kind != detail::CornerFinish::Sharp)
      out.push_back({p.finish[i].kind, p.finish[i].size, corners[i]});
  return out;
}

/// bevelled_block's two designed bevels, as indices into its designedFinishes().
inline constexpr std::size_t kNarrowBevel = 0;  // 0.03 wide
inline constexpr std::size_t kWideBevel = 2;    // 0.07 wide

namespace detail {
inline double segmentDistance2d(const Point2d &p, const Point2d &a, const Point2d &b) {
  const Point2d d = b - a;
  const double t = std::clamp(dot2(p - a, d) / dot2(d, d), 0.0, 1.0);
  const Point2d q = p - a - d * t;
  return std::sqrt(dot2(q, q));
}

inline double stripDistance2d(const Point2d &p, const std::vector<Point2d> &strip) {
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < strip.size(); ++i)
    nearest = std::min(nearest, segmentDistance2d(p, strip[i], strip[i + 1]));
  return nearest;
}
}  // namespace detail

/// Per face of `m`, a sampling of the prism's shape (as shapeByName gives it,
/// turned): whether it lies on one of `finishes`, i.e. its centroid, in the
/// unturned prism's frame seen along its axis, lies within `within` of the
/// finish's strip (at any height).
template <class M>
std::vector<char> designedFaces(const M &m, const detail::FinishedPrism &p,
                                const std::vector<DesignedFinish> &finishes, double within) {
  const Point3d axis = p.axis / p.axis.Norm();
  std::vector<char> on(m.face.size(), 0);
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    Point3d c(0, 0, 0);
    for (int i = 0; i < 3; ++i) c += Point3d::Construct(m.face[f].cP(i)) / 3.0;
    const Point3d u = detail::rotateRodrigues(c, axis, -p.angle);
    for (const DesignedFinish &finish : finishes)
      if (detail::stripDistance2d(Point2d(u.X(), u.Y()), finish.strip) < within) on[f] = 1;
  }
  return on;
}

}  // namespace edge_sharpener::test_meshes
