// The intersection guard's narrow phase: whether two faces of the mesh meet,
// and whether they cross rather than only touch, at positions the caller
// chooses (as placed, or at rest).
#pragma once

#include <vcg/complex/complex.h>

#include <array>
// (vcglib's algorithm headers need complex.h first)
#include <vcg/complex/algorithms/clean.h>

#include "../util/attributes.h"
#include "../util/geometry.h"

namespace edge_sharpener {
namespace detail {

/// Whether two triangles sharing no vertex meet (touching included):
/// Moeller's test, unless trianglesApart() finds a gap between them.
inline bool trianglesMeet(const std::array<Vec3, 3> &p, const std::array<Vec3, 3> &q) {
  return !trianglesApart(p, q) && vcg::NoDivTriTriIsect(p[0], p[1], p[2], q[0], q[1], q[2]);
}

/// Whether two distinct faces intersect: vcglib's test (the one
/// tri::Clean::SelfIntersections() applies: TestFaceFaceIntersection), on
/// the coordinates in double precision, with corners at the same position
/// counted as shared. Faces sharing an edge are not tested;
/// faces sharing one vertex intersect when the edge opposite the shared
/// vertex in one, pulled halfway towards it, crosses the other (vcglib's
/// segment test made scale-free: segmentThroughTriangle()); other faces
/// by Moeller's triangle-triangle test, touching included, unless
/// trianglesApart() finds a gap between them. (In float,
/// Moeller's test reports nearly coplanar faces millimetres apart as
/// intersecting: its interval arithmetic divides by the tiny distances to
/// the other face's plane.) `position(vertex pointer)` gives the
/// coordinates to test at.
template <class MeshType, class FaceType = typename MeshType::FaceType, class Position>
bool facesIntersect(FaceType *f, FaceType *g, Position &&position) {
  std::array<Vec3, 3> p, q;
  for (int k = 0; k < 3; ++k) p[k] = position(f->cV(k)), q[k] = position(g->cV(k));
  // Corners shared by position count as shared vertices: a marching-cubes
  // mesh has distinct vertices at one point where the surface passes through
  // a grid node, and faces that meet there only touch.
  int shared = 0, i0 = 0, i1 = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (f->cV(i) == g->cV(j) || p[i] == q[j]) ++shared, i0 = i, i1 = j;
  if (shared == 2) return false;
  if (shared >= 3) return true;
  if (shared == 0) return trianglesMeet(p, q);
  // As vcglib: the first segment that meets the other face decides.
  const Vec3 half = p[i0] * 0.5;
  for (int side = 0; side < 2; ++side) {
    const std::array<Vec3, 3> &a = side == 0 ? p : q, &b = side == 0 ? q : p;
    const int ia = side == 0 ? i0 : i1;
    if (const auto uv =
            segmentThroughTriangle(a[(ia + 1) % 3] * 0.5 + half, a[(ia + 2) % 3] * 0.5 + half, b)) {
      constexpr double kEps = 1e-6;  // vcglib's EPSIL, on barycentric coordinates
      const auto [u, v] = *uv;
      return !(u + v >= 1 || u <= kEps || v <= kEps);
    }
  }
  return false;
}

/// Whether two faces cross rather than only touch: they still meet when
/// each shrinks towards its centroid by 1e-6 of its size (faces sharing a
/// vertex then share none).
template <class MeshType, class FaceType = typename MeshType::FaceType, class Position>
bool facesCross(FaceType *f, FaceType *g, Position &&position) {
  std::array<Vec3, 3> p, q;
  const auto shrink = [&](FaceType *face, std::array<Vec3, 3> &t) {
    for (int k = 0; k < 3; ++k) t[k] = position(face->cV(k));
    const Vec3 centroid = (t[0] + t[1] + t[2]) / 3.0;
    for (Vec3 &x : t) x = centroid + (x - centroid) * (1 - 1e-6);
  };
  shrink(f, p);
  shrink(g, q);
  return trianglesMeet(p, q);
}

}  // namespace detail
}  // namespace edge_sharpener
