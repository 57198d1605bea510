// The faces of a sampled test shape that lie on one of its designed features:
// what a user who knows the part deselects before sharpening (issue 61).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "test_meshes/shapes.h"

namespace edge_sharpener::test_meshes {

/// One of bevelled_block's designed bevels (bevelledBlock()): the corner of
/// the box's outline it cuts, and its width.
struct BlockBevel {
  double cornerX, cornerY, width;
};
inline const BlockBevel kNarrowBevel{-0.8, -0.5, 0.03};
inline const BlockBevel kWideBevel{0.8, 0.5, 0.07};

namespace detail {
inline double segmentDistance2d(const Point2d &p, const Point2d &a, const Point2d &b) {
  const Point2d d = b - a;
  const double t = std::clamp(dot2(p - a, d) / dot2(d, d), 0.0, 1.0);
  const Point2d q = p - a - d * t;
  return std::sqrt(dot2(q, q));
}
}  // namespace detail

/// Per face of `m`, a sampling of the shape bevelled_block (as shapeByName
/// gives it) at cells `cellSize` wide: whether it lies on `bevel`, i.e. its
/// centroid, in the unturned block's frame, lies within one cell of the
/// bevel's strip (seen along the block's vertical axis, at any height).
template <class M>
std::vector<char> bevelledBlockBevelFaces(const M &m, double cellSize, const BlockBevel &bevel) {
  // The bevel's ends: its corner moved along both sides (a right angle).
  const double cut = bevel.width / (2 * std::sin(M_PI / 4));
  const Point2d corner(bevel.cornerX, bevel.cornerY);
  const Point2d a = corner + Point2d(bevel.cornerX > 0 ? -cut : cut, 0);
  const Point2d b = corner + Point2d(0, bevel.cornerY > 0 ? -cut : cut);
  const Point3d axis = kBevelledBlockAxis / kBevelledBlockAxis.Norm();
  std::vector<char> on(m.face.size(), 0);
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    Point3d c(0, 0, 0);
    for (int i = 0; i < 3; ++i) c += Point3d::Construct(m.face[f].cP(i)) / 3.0;
    const Point3d u = detail::rotateRodrigues(c, axis, -kBevelledBlockAngle);
    on[f] = detail::segmentDistance2d(Point2d(u.X(), u.Y()), a, b) < cellSize;
  }
  return on;
}

}  // namespace edge_sharpener::test_meshes
