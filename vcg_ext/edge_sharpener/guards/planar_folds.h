// Auto method, after the cleanup: a flat patch folded over itself is tiled
// again. At a saddle corner (a concave edge meeting convex ones) an input face
// of the flat side can join a sample of one arm to a sample of the other
// across the notch; once the corner and edge vertices reach the sharp lines,
// that face juts past the corner and a child of the chamfer beside it folds
// back over it, and the raised walls pierce both (the intersection guard
// would send the corner back). All of them lie on one plane, so the same
// outline tiled again without the fold is the same flat surface, now ending
// at the corner.
#pragma once

#include <vcg/complex/complex.h>
#include <vcg/simplex/face/pos.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "../report.h"
#include "../rulebook.h"
#include "../util/attributes.h"
#include "../util/fast_topology.h"
#include "../util/geometry.h"
#include "../util/parallel.h"
#include "../util/polygon_triangulation.h"

namespace edge_sharpener {


namespace detail {

/// Faces around vertex `z` of face `f` (closed 2-manifold).
template <class FaceType>
void facesAround(FaceType *f, int z, std::vector<FaceType *> &out) {
  vcg::face::Pos<FaceType> start(f, z, f->V(z)), p = start;
  int guard = 0;
  do {
    out.push_back(p.F());
    p.FlipE();
    p.FlipF();
  } while (p != start && ++guard < 256);
}

template <class FaceType>
Vec3 faceNormal(const FaceType &f) {
  return triangleNormal(positionOf(f.cV(0)), positionOf(f.cV(1)), positionOf(f.cV(2)));
}

/// Whether face f is in `patch` (sorted).
template <class FaceType>
bool inSortedPatch(const std::vector<FaceType *> &patch, const FaceType *f) {
  return std::binary_search(patch.begin(), patch.end(), f);
}

/// The outline of a patch of faces: its half-edges whose other face is
/// outside, by start vertex, each with its end and the face and edge across;
/// and, once walked, its vertices in order.
template <class MeshType>
struct PatchOutline {
  using FaceType = typename MeshType::FaceType;
  using VertexType = typename MeshType::VertexType;
  struct HalfEdge {
    VertexType *to;
    FaceType *outside;
    int outsideEdge;
  };
  std::map<VertexType *, HalfEdge> next;
  std::vector<VertexType *> loop;

  bool contains(VertexType *a, const VertexType *b) const {
    const auto it = next.find(a);
    return it != next.end() && it->second.to == b;
  }
};

/// Collects the outline's half-edges of `patch` (sorted). \return false
/// where there are none, or the outline touches itself (a vertex starts two).
template <class MeshType>
bool collectOutline(const std::vector<typename MeshType::FaceType *> &patch,
                    PatchOutline<MeshType> &outline) {
  using HalfEdge = typename PatchOutline<MeshType>::HalfEdge;
  for (auto *f : patch)
    for (int j = 0; j < 3; ++j) {
      if (inSortedPatch(patch, f->FFp(j))) continue;
      if (!outline.next.emplace(f->V(j), HalfEdge{f->V((j + 1) % 3), f->FFp(j), f->FFi(j)}).second)
        return false;
    }
  return !outline.next.empty();
}

/// Walks the outline from its first vertex into outline.loop. \return false
/// where it breaks off.
template <class MeshType>
bool walkOutline(PatchOutline<MeshType> &outline) {
  auto &loop = outline.loop;
  loop = {outline.next.begin()->first};
  while (loop.size() <= outline.next.size()) {
    const auto it = outline.next.find(loop.back());
    if (it == outline.next.end()) return false;
    if (it->second.to == loop.front()) break;
    loop.push_back(it->second.to);
  }
  return true;
}

/// How many vertices the faces of `patch` have.
template <class FaceType>
std::size_t vertexCount(const std::vector<FaceType *> &patch) {
  std::vector<typename FaceType::VertexType *> vertices;
  for (FaceType *f : patch)
    for (int j = 0; j < 3; ++j) vertices.push_back(f->V(j));
  std::sort(vertices.begin(), vertices.end());
  return std::size_t(std::unique(vertices.begin(), vertices.end()) - vertices.begin());
}

/// The outline of `patch` (sorted), walked, when it is one loop holding all
/// its vertices; false otherwise.
template <class MeshType>
bool diskOutline(const std::vector<typename MeshType::FaceType *> &patch,
                 PatchOutline<MeshType> &outline) {
  if (!collectOutline(patch, outline) || !walkOutline(outline)) return false;
  const std::size_t n = outline.loop.size();
  // A disk whose vertices are all on its outline has n - 2 faces.
  return n == outline.next.size() && n == vertexCount(patch) && patch.size() + 2 == n;
}

/// The vertices of `loop` in coordinates on the plane (origin, unit normal),
/// the first axis along its first edge; empty where that edge is normal to
/// the plane.
template <class VertexType>
std::vector<Vec2> onPlane(const std::vector<VertexType *> &loop, const Vec3 &origin,
                          const Vec3 &normal) {
  Vec3 u = positionOf(loop[1]) - positionOf(loop[0]);
  u = u - normal * (u * normal);
  if (!(u.Norm() > 0)) return {};
  u /= u.Norm();
  const Vec3 v = normal ^ u;
  std::vector<Vec2> points;
  for (VertexType *x : loop) {
    const Vec3 d = positionOf(x) - origin;
    points.emplace_back(d * u, d * v);
  }
  return points;
}

/// Whether a face around `a` outside `patch` (sorted) has vertex `b`: edge
/// (a, b) is then an edge outside already.
template <class FaceType, class VertexType>
bool edgeOutsidePatch(const std::vector<FaceType *> &patch, const VertexType *a,
                      const VertexType *b) {
  std::vector<FaceType *> star;
  for (FaceType *f : patch)
    for (int z = 0; z < 3; ++z)
      if (f->V(z) == a) facesAround(f, z, star);
  for (FaceType *f : star)
    if (!inSortedPatch(patch, f))
      for (int k = 0; k < 3; ++k)
        if (f->V(k) == b) return true;
  return false;
}

/// Whether no inner edge of `tiles` (triangles of outline.loop's indices)
/// is an edge outside `patch` already: the mesh would not stay manifold.
template <class MeshType>
bool innerEdgesAreNew(const std::vector<typename MeshType::FaceType *> &patch,
                      const PatchOutline<MeshType> &outline,
                      const std::vector<std::array<int, 3>> &tiles) {
  for (const auto &t : tiles)
    for (int j = 0; j < 3; ++j) {
      auto *a = outline.loop[t[j]], *b = outline.loop[t[(j + 1) % 3]];
      if (!outline.contains(a, b) && edgeOutsidePatch(patch, a, b)) return false;
    }
  return true;
}

/// Makes face f's edge j and face g's edge k each other's neighbours.
template <class FaceType>
void linkEdges(FaceType *f, int j, FaceType *g, int k) {
  f->FFp(j) = g, f->FFi(j) = k;
  g->FFp(k) = f, g->FFi(k) = j;
}

/// Writes `tiles` into the faces of `patch` and links them: across the
/// outline to the faces outside, across the inner edges to each other.
template <class MeshType>
void writeTiles(const std::vector<typename MeshType::FaceType *> &patch,
                const PatchOutline<MeshType> &outline,
                const std::vector<std::array<int, 3>> &tiles) {
  using FaceType = typename MeshType::FaceType;
  using VertexType = typename MeshType::VertexType;
  for (std::size_t i = 0; i < tiles.size(); ++i)
    for (int j = 0; j < 3; ++j) patch[i]->V(j) = outline.loop[tiles[i][j]];
  std::map<std::pair<VertexType *, VertexType *>, std::pair<FaceType *, int>> inner;
  for (FaceType *f : patch)
    for (int j = 0; j < 3; ++j) {
      VertexType *a = f->V(j), *b = f->V((j + 1) % 3);
      if (outline.contains(a, b)) {
        const auto &h = outline.next.at(a);
        linkEdges(f, j, h.outside, h.outsideEdge);
        continue;
      }
      const auto [it, first] =
          inner.emplace(std::make_pair(std::min(a, b), std::max(a, b)), std::make_pair(f, j));
      if (!first) linkEdges(f, j, it->second.first, it->second.second);
    }
}

/// Tiles `patch` (sorted) again on the plane (origin, unit normal), in
/// place, FF adjacency kept, when its outline is one loop holding all its
/// vertices, simple and counter-clockwise seen from the normal, and tiles
/// with angles of at least `minAngleRad` whose new inner edges are not edges
/// outside already. \return whether it did.
template <class MeshType>
bool retileFlatPatch(const std::vector<typename MeshType::FaceType *> &patch, const Vec3 &origin,
                     const Vec3 &normal, double minAngleRad) {
  PatchOutline<MeshType> outline;
  if (!diskOutline(patch, outline)) return false;
  const std::vector<Vec2> points = onPlane(outline.loop, origin, normal);
  if (points.empty()) return false;
  const std::vector<std::array<int, 3>> tiles = triangulateSimplePolygon(points, minAngleRad);
  if (tiles.size() != patch.size() || !innerEdgesAreNew(patch, outline, tiles)) return false;
  writeTiles(patch, outline, tiles);
  return true;
}

/// Tiles the flat patch around a fold again: from face `seed` and its
/// neighbour across edge `j`, it grows by faces on their plane (within
/// `tolerance`) one edge-neighbour at a time, never closing a vertex's fan,
/// until retileFlatPatch succeeds or `maxFaces` are in. The plane is that
/// of the largest face around on the seed's plane that faces the side most
/// of their area faces (a fold's faces are slivers).
/// \return whether it did.
template <class MeshType>
bool unfoldAround(typename MeshType::FaceType *seed, int j, double tolerance, double minAngleRad,
                  std::size_t maxFaces) {
  using FaceType = typename MeshType::FaceType;
  std::vector<FaceType *> around;
  for (int z = 0; z < 3; ++z) facesAround(seed, z, around);
  std::sort(around.begin(), around.end());
  around.erase(std::unique(around.begin(), around.end()), around.end());
  const auto within = [&](const FaceType *f, const Vec3 &origin, const Vec3 &unitNormal) {
    for (int k = 0; k < 3; ++k)
      if (std::abs(unitNormal * (positionOf(f->cV(k)) - origin)) > tolerance) return false;
    return true;
  };
  // The side the flat faces around face: their area-weighted normals' sum.
  Vec3 seedNormal = faceNormal(*seed);
  if (!(seedNormal.Norm() > 0)) return false;
  seedNormal /= seedNormal.Norm();
  std::vector<FaceType *> flat;
  for (FaceType *f : around)
    if (within(f, positionOf(seed->cV(0)), seedNormal)) flat.push_back(f);
  Vec3 areaNormal(0, 0, 0);
  for (FaceType *f : flat) areaNormal += faceNormal(*f);
  FaceType *largest = nullptr;
  for (FaceType *f : flat)
    if (faceNormal(*f) * areaNormal > 0 &&
        (!largest || faceNormal(*f).Norm() > faceNormal(*largest).Norm()))
      largest = f;
  if (!largest) return false;
  Vec3 normal = faceNormal(*largest);
  normal /= normal.Norm();
  const Vec3 origin = positionOf(largest->cV(0));
  const auto onPlane = [&](const FaceType *f) { return within(f, origin, normal); };
  std::vector<FaceType *> patch{seed, seed->FFp(j)};
  std::sort(patch.begin(), patch.end());
  if (!onPlane(seed) || !onPlane(seed->FFp(j))) return false;
  const auto inPatch = [&](const FaceType *f) {
    return std::binary_search(patch.begin(), patch.end(), f);
  };
  const auto closesAFan = [&](FaceType *g) {
    for (int z = 0; z < 3; ++z) {
      std::vector<FaceType *> fan;
      facesAround(g, z, fan);
      if (std::all_of(fan.begin(), fan.end(), [&](FaceType *f) { return f == g || inPatch(f); }))
        return true;
    }
    return false;
  };
  while (true) {
    if (retileFlatPatch<MeshType>(patch, origin, normal, minAngleRad)) return true;
    if (patch.size() >= maxFaces) return false;
    FaceType *grow = nullptr;
    for (FaceType *f : patch)
      for (int k = 0; k < 3 && !grow; ++k) {
        FaceType *g = f->FFp(k);
        if (!inPatch(g) && onPlane(g) && !closesAFan(g)) grow = g;
      }
    if (!grow) return false;
    patch.insert(std::upper_bound(patch.begin(), patch.end(), grow), grow);
  }
}

/// Whether face `f` and its neighbour across edge `j` are folded over each
/// other on one plane: normals opposite, each one's far vertex within
/// `tolerance` of the other's plane.
template <class FaceType>
bool foldedOnPlane(const FaceType &f, int j, double tolerance) {
  const FaceType *g = f.cFFp(j);
  if (g == &f) return false;
  const Vec3 nf = faceNormal(f), ng = faceNormal(*g);
  if (!(nf.Norm() > 0 && ng.Norm() > 0) || nf * ng > VertexRules::kFoldMaxCos * nf.Norm() * ng.Norm()) return false;
  const Vec3 onEdge = positionOf(f.cV(j));
  const Vec3 farF = positionOf(f.cV((j + 2) % 3)) - onEdge;
  const Vec3 farG = positionOf(g->cV((f.cFFi(j) + 2) % 3)) - onEdge;
  return std::abs(nf * farG) <= tolerance * nf.Norm() &&
         std::abs(ng * farF) <= tolerance * ng.Norm();
}

}  // namespace detail

/// Finds the faces with a moved vertex (`isMoved(vertex index)`) folded
/// over a neighbour on one plane (detail::foldedOnPlane, `tolerance`
/// absolute) and tiles the flat patch around each fold again
/// (detail::unfoldAround), tiles with angles of at least `minAngleRad`.
/// Needs a closed 2-manifold with FF adjacency up to date; it stays so.
/// Faces keep their slots and no element is added, so an ElementSnapshot
/// taken before restores the mesh.
template <class MeshType, class IsMoved>
PlanarFoldStats unfoldPlanarPatches(MeshType &m, const IsMoved &isMoved, double tolerance,
                                    double minAngleRad) {
  using FaceType = typename MeshType::FaceType;
  // Per vertex first, in memory order (cheaper than three lookups per face).
  const std::int64_t vertexCount = std::int64_t(m.vert.size());
  std::vector<char> moved(m.vert.size());
#pragma omp parallel for schedule(static, 8192) if (vertexCount > kParallelMin)
  for (std::int64_t v = 0; v < vertexCount; ++v) moved[v] = isMoved(std::size_t(v));
  // Listed in face order on every core, so the seeds' order does not depend
  // on the thread count.
  const auto *first = m.vert.data();
  const std::vector<std::uint32_t> folded = detail::indicesWhere(
      std::int64_t(m.face.size()),
      [&](std::int64_t fi) {
        const FaceType &f = m.face[fi];
        if (f.IsD()) return false;
        if (!moved[f.cV(0) - first] && !moved[f.cV(1) - first] && !moved[f.cV(2) - first])
          return false;
        for (int j = 0; j < 3; ++j)
          if (detail::foldedOnPlane(f, j, tolerance)) return true;
        return false;
      },
      kParallelMin);
  PlanarFoldStats stats;
  for (const std::uint32_t fi : folded) {
    FaceType *f = &m.face[fi];
    ++stats.folds;
    for (int j = 0; j < 3; ++j)  // a patch tiled before may have taken this fold away
      if (detail::foldedOnPlane(*f, j, tolerance)) {
        stats.patches +=
            detail::unfoldAround<MeshType>(f, j, tolerance, minAngleRad, VertexRules::kMaxFoldPatchFaces);
        break;
      }
  }
  return stats;
}

}  // namespace edge_sharpener
