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
#include <vcg/space/distance3.h>
#include <vcg/space/triangle3.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
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

/// The tolerances of unfoldPlanarPatches.
struct FoldSettings {
  double planeTolerance = 0;    ///< a fold's faces lie on one plane within this (absolute)
  double minAngleRad = 0;       ///< the smallest angle of a tile or of a face moved
  double exactTolerance = 0;    ///< a vertex moves on a plane its faces lie on within this
  double parallelAngleRad = 0;  ///< two planes closer than this make no line to slide along
  int relaxRings = 0;           ///< how many rings out from a fold vertices may move
};

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

/// Whether every vertex of face f lies within `tolerance` of `plane`.
template <class FaceType>
bool faceOnPlane(const FaceType &f, const Plane &plane, double tolerance) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(plane.normal * (positionOf(f.cV(k)) - plane.point)) > tolerance) return false;
  return true;
}

/// The plane of a fold at face `seed`: that of the largest face around the
/// seed on its plane (within `tolerance`) that faces the side most of their
/// area faces (a fold's faces are slivers), its normal to that side.
template <class FaceType>
std::optional<Plane> foldPlane(FaceType *seed, double tolerance) {
  std::vector<FaceType *> around;
  for (int z = 0; z < 3; ++z) facesAround(seed, z, around);
  std::sort(around.begin(), around.end());
  around.erase(std::unique(around.begin(), around.end()), around.end());
  Vec3 seedNormal = faceNormal(*seed);
  if (!(seedNormal.Norm() > 0)) return std::nullopt;
  seedNormal /= seedNormal.Norm();
  const Plane seedPlane{positionOf(seed->cV(0)), seedNormal};
  std::vector<FaceType *> flat;
  for (FaceType *f : around)
    if (faceOnPlane(*f, seedPlane, tolerance)) flat.push_back(f);
  Vec3 areaNormal(0, 0, 0);
  for (FaceType *f : flat) areaNormal += faceNormal(*f);
  FaceType *largest = nullptr;
  for (FaceType *f : flat)
    if (faceNormal(*f) * areaNormal > 0 &&
        (!largest || faceNormal(*f).Norm() > faceNormal(*largest).Norm()))
      largest = f;
  if (!largest) return std::nullopt;
  const Vec3 normal = faceNormal(*largest);
  return Plane{positionOf(largest->cV(0)), normal / normal.Norm()};
}

/// Where a vertex may move without changing the surface: on a plane when
/// all its faces lie on it, along a line when they lie on two (the vertex on
/// both: a sharp edge), nowhere otherwise.
struct VertexFreedom {
  enum Kind { Fixed, OnPlane, OnLine } kind = Fixed;
  Vec3 direction{0, 0, 0};    ///< OnLine: the line's unit direction
  std::vector<Plane> planes;  ///< the one or two planes its faces lie on
};

/// Face f's corners in the order of their places (lexicographic): the same
/// whatever its winding and first corner.
template <class FaceType>
std::array<Vec3, 3> cornersByPlace(const FaceType &f) {
  std::array<Vec3, 3> c{positionOf(f.cV(0)), positionOf(f.cV(1)), positionOf(f.cV(2))};
  std::sort(c.begin(), c.end());
  return c;
}

/// The plane of the largest of `faces` (ties: the one whose corners come
/// first by place), through its first corner by place, its unit normal
/// facing its side, so that neither the faces' order nor their windings
/// change it by a rounding; nothing when they have no area.
template <class FaceType>
std::optional<Plane> planeOfLargest(const std::vector<const FaceType *> &faces) {
  const FaceType *largest = nullptr;
  double largestArea = 0;
  for (const FaceType *g : faces) {
    const double area = faceNormal(*g).Norm();
    if (!largest || area > largestArea ||
        (area == largestArea && cornersByPlace(*g) < cornersByPlace(*largest)))
      largest = g, largestArea = area;
  }
  if (!largest || !(largestArea > 0)) return std::nullopt;
  const std::array<Vec3, 3> c = cornersByPlace(*largest);
  Vec3 normal = triangleNormal(c[0], c[1], c[2]);
  if (normal * faceNormal(*largest) < 0) normal = -normal;
  if (!(normal.Norm() > 0)) return std::nullopt;
  return Plane{c[0], normal / normal.Norm()};
}

/// The freedom of vertex `z` of face `f`, whose faces are `star`: on a
/// plane when they all lie on the plane of the largest of them (within
/// `tolerance`); along a line when the others lie on the plane of the
/// largest of those, the two planes apart by at least `minLineAngleRad`.
template <class FaceType>
VertexFreedom freedomOf(const FaceType &f, int z, const std::vector<FaceType *> &star,
                        double tolerance, double minLineAngleRad) {
  VertexFreedom freedom;
  const std::vector<const FaceType *> all(star.begin(), star.end());
  const std::optional<Plane> first = planeOfLargest(all);
  if (!first) return freedom;
  std::vector<const FaceType *> on, off;
  for (const FaceType *g : all) (faceOnPlane(*g, *first, tolerance) ? on : off).push_back(g);
  if (off.empty()) {
    freedom.kind = VertexFreedom::OnPlane;
    freedom.planes = {*first};
    return freedom;
  }
  const std::optional<Plane> second = planeOfLargest(off);
  if (!second || angleBetween(first->normal, second->normal) < minLineAngleRad ||
      std::abs(first->normal * (positionOf(f.cV(z)) - first->point)) > tolerance)
    return freedom;
  for (const FaceType *g : off)
    if (!faceOnPlane(*g, *second, tolerance)) return freedom;
  freedom.kind = VertexFreedom::OnLine;
  freedom.direction = first->normal ^ second->normal;
  freedom.direction /= freedom.direction.Norm();
  freedom.planes = {*first, *second};
  return freedom;
}

/// Moves each vertex of `free` to the mean of its `neighbours`, projected
/// onto its line or plane through where it is, the others held: a Tutte
/// embedding of the patch (Gauss-Seidel sweeps in list order, in double
/// precision, until no vertex moves by more than a millionth of its
/// neighbourhood's size).
template <class VertexType>
void relaxToNeighbourMeans(const std::vector<VertexType *> &free,
                           const std::vector<VertexFreedom> &freedom,
                           const std::vector<std::vector<VertexType *>> &neighbours) {
  using Coord = typename VertexType::CoordType;
  std::map<const VertexType *, std::size_t> slot;
  std::vector<Vec3> x;
  for (VertexType *v : free) slot.emplace(v, x.size()), x.push_back(positionOf(v));
  // Per free vertex, its neighbours: a free one's slot, or a held one's place.
  std::vector<std::vector<std::size_t>> freeNeighbours(free.size());
  std::vector<Vec3> heldSum(free.size(), Vec3(0, 0, 0));
  double size = 0;
  for (std::size_t i = 0; i < free.size(); ++i)
    for (VertexType *u : neighbours[i]) {
      size = std::max(size, (positionOf(u) - x[i]).Norm());
      const auto it = slot.find(u);
      if (it != slot.end())
        freeNeighbours[i].push_back(it->second);
      else
        heldSum[i] += positionOf(u);
    }
  constexpr int kMaxSweeps = 10000;
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    double largest = 0;
    for (std::size_t i = 0; i < free.size(); ++i) {
      Vec3 mean = heldSum[i];
      for (const std::size_t k : freeNeighbours[i]) mean += x[k];
      mean /= double(neighbours[i].size());
      const Vec3 &p = x[i];
      if (freedom[i].kind == VertexFreedom::OnLine)
        mean = p + freedom[i].direction * ((mean - p) * freedom[i].direction);
      else
        mean = mean - freedom[i].planes[0].normal * ((mean - p) * freedom[i].planes[0].normal);
      largest = std::max(largest, (mean - p).Norm());
      x[i] = mean;
    }
    if (largest <= 1e-12 * size) break;
  }
  for (std::size_t i = 0; i < free.size(); ++i) free[i]->P() = Coord::Construct(x[i]);
}

/// Unfolds the fold between face `seed` and its neighbour across edge `j`
/// by moving vertices where they can move without changing the surface
/// (freedomOf: on the plane their faces lie on, or along the line of two;
/// on them within `settings.exactTolerance`, the precision of a sampling on the
/// surface, so that a curved face or edge, a plane or a line only nearby,
/// stays). The free vertices of the two faces, then those with their
/// neighbours up to `settings.relaxRings` rings out, go each to the mean of its
/// neighbours (relaxToNeighbourMeans, the other vertices held), kept when
/// every face around them then faces its plane's side with angles of at
/// least `settings.minAngleRad` and the surface stays within that tolerance of
/// where it was. Two planes closer than `settings.parallelAngleRad` make no line.
/// Where a remesher cast its samples onto the surface a hair from a sharp
/// line or corner, the restored line's vertices come out of order along it
/// and faces fold over each other; retiling cannot take a vertex inside the
/// patch away. A vertex a relaxation moved before (`settled`, indexed from
/// `first`) is held, and those moved here are marked: each moves once, so
/// that the order the folds are met in does not move one again by a
/// rounding. \return the vertices moved (0: none).
template <class MeshType>
std::size_t relaxFlatFold(typename MeshType::FaceType *seed, int j, const FoldSettings &settings,
                          std::vector<char> &settled, const typename MeshType::VertexType *first) {
  const double exactTolerance = settings.exactTolerance;
  using FaceType = typename MeshType::FaceType;
  using VertexType = typename MeshType::VertexType;
  using Coord = typename MeshType::CoordType;
  // Each vertex met: its faces and its freedom.
  std::map<VertexType *, std::pair<std::vector<FaceType *>, VertexFreedom>> met;
  const auto meet = [&](FaceType * f, int z) -> const auto & {
    auto [it, added] = met.try_emplace(f->V(z));
    if (added) {
      facesAround(f, z, it->second.first);
      it->second.second =
          freedomOf(*f, z, it->second.first, exactTolerance, settings.parallelAngleRad);
    }
    return it->second;
  };
  std::vector<VertexType *> free;
  // In the order of their places, so that the relaxation's sweeps do not
  // depend on the vertices' indices, the faces' winding or the order they
  // are met in.
  const auto byPlace = [](const VertexType *u, const VertexType *w) {
    return u->cP() < w->cP() || (u->cP() == w->cP() && u < w);
  };
  const auto addFree = [&](FaceType *f) {
    for (int z = 0; z < 3; ++z) {
      const auto at = std::lower_bound(free.begin(), free.end(), f->V(z), byPlace);
      if ((at == free.end() || *at != f->V(z)) && !settled[f->V(z) - first] &&
          meet(f, z).second.kind != VertexFreedom::Fixed)
        free.insert(at, f->V(z));
    }
  };
  addFree(seed);
  addFree(seed->FFp(j));
  for (int ring = 0; ring <= settings.relaxRings && !free.empty(); ++ring) {
    // The faces around the free vertices, each with the plane it lies on.
    std::vector<std::pair<FaceType *, const Plane *>> patch;
    std::vector<VertexFreedom> freedom;
    std::vector<std::vector<VertexType *>> neighbours(free.size());
    for (std::size_t i = 0; i < free.size(); ++i) {
      const auto &[star, vertexFreedom] = met.at(free[i]);
      freedom.push_back(vertexFreedom);
      for (FaceType *f : star) {
        const Vec3 n = faceNormal(*f);
        const Plane *on = &vertexFreedom.planes[0];
        for (const Plane &pl : vertexFreedom.planes)
          if (std::abs(pl.normal * n) > std::abs(on->normal * n)) on = &pl;
        patch.emplace_back(f, on);
        for (int k = 0; k < 3; ++k)
          if (f->V(k) != free[i]) neighbours[i].push_back(f->V(k));
      }
      std::sort(neighbours[i].begin(), neighbours[i].end(), byPlace);
      neighbours[i].erase(std::unique(neighbours[i].begin(), neighbours[i].end()),
                          neighbours[i].end());
    }
    // The side each face should face: that of the largest face of the patch
    // on its plane, turned with it or against it as a fold's faces are
    // (around a fold, a vertex's own faces may be mostly folded).
    const auto sideOf = [&](const Plane &plane) {
      const FaceType *largest = nullptr;
      for (const auto &[f, on] : patch)
        if (faceOnPlane(*f, plane, exactTolerance) &&
            std::abs(faceNormal(*f) * plane.normal) >
                -VertexRules::kFoldMaxCos * faceNormal(*f).Norm() &&
            (!largest || faceNormal(*f).Norm() > faceNormal(*largest).Norm()))
          largest = f;
      return largest && faceNormal(*largest) * plane.normal < 0 ? -plane.normal : plane.normal;
    };
    std::vector<Vec3> side;
    for (const auto &[f, on] : patch) side.push_back(sideOf(*on));
    std::vector<Coord> before;
    for (VertexType *v : free) before.push_back(v->P());
    // The patch's faces once each (a face around two free vertices is
    // listed twice above, with the plane each sees it on).
    std::vector<FaceType *> faces;
    for (const auto &[f, on] : patch) faces.push_back(f);
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    const auto triangles = [&] {
      std::vector<vcg::Triangle3<double>> out;
      for (const FaceType *f : faces)
        out.emplace_back(positionOf(f->cV(0)), positionOf(f->cV(1)), positionOf(f->cV(2)));
      return out;
    };
    const std::vector<vcg::Triangle3<double>> surface = triangles();
    relaxToNeighbourMeans(free, freedom, neighbours);
    // The surface stays where it was, both ways: each vertex moved on the
    // faces as they were, and where it was on the faces as they are.
    const std::vector<vcg::Triangle3<double>> relaxed = triangles();
    bool unfolded = true;
    for (std::size_t i = 0; i < free.size() && unfolded; ++i)
      unfolded = distanceToTriangles(positionOf(free[i]), surface) <= exactTolerance &&
                 distanceToTriangles(Vec3::Construct(before[i]), relaxed) <= exactTolerance;
    // ...and each face as it was (its centre and the middles of its sides)
    // on the faces as they are.
    for (std::size_t k = 0; k < surface.size() && unfolded; ++k) {
      const auto &t = surface[k];
      for (const Vec3 &x : {(t.P(0) + t.P(1) + t.P(2)) / 3.0, (t.P(0) + t.P(1)) / 2.0,
                            (t.P(1) + t.P(2)) / 2.0, (t.P(2) + t.P(0)) / 2.0})
        unfolded = unfolded && distanceToTriangles(x, relaxed) <= exactTolerance;
    }
    for (std::size_t k = 0; k < patch.size() && unfolded; ++k) {
      const FaceType &f = *patch[k].first;
      const Vec3 a = positionOf(f.cV(0)), b = positionOf(f.cV(1)), c = positionOf(f.cV(2));
      unfolded = faceNormal(f) * side[k] > 0 && minTriangleAngle(a, b, c) >= settings.minAngleRad;
    }
    if (unfolded) {
      for (VertexType *v : free) settled[v - first] = 1;
      return free.size();
    }
    for (std::size_t i = 0; i < free.size(); ++i) free[i]->P() = before[i];
    // One ring out: the free vertices of the patch's faces.
    for (const auto &[f, on] : patch) addFree(f);
  }
  return 0;
}

/// Tiles the flat patch around a fold again: from face `seed` and its
/// neighbour across edge `j`, it grows by faces on their plane (within
/// `tolerance`) one edge-neighbour at a time, never closing a vertex's fan,
/// until retileFlatPatch succeeds or `maxFaces` are in, on foldPlane.
/// \return whether it did.
template <class MeshType>
bool unfoldAround(typename MeshType::FaceType *seed, int j, double tolerance, double minAngleRad,
                  std::size_t maxFaces) {
  using FaceType = typename MeshType::FaceType;
  const std::optional<Plane> plane = foldPlane(seed, tolerance);
  if (!plane) return false;
  const Vec3 origin = plane->point, normal = plane->normal;
  const auto onPlane = [&](const FaceType *f) { return faceOnPlane(*f, *plane, tolerance); };
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

/// Whether two faces with normals `nf` and `ng` (any length) face 120
/// degrees apart or more (VertexRules::kFoldMaxCos): one folded over the other.
inline bool normalsFolded(const Vec3 &nf, const Vec3 &ng) {
  return nf.Norm() > 0 && ng.Norm() > 0 &&
         nf * ng <= VertexRules::kFoldMaxCos * nf.Norm() * ng.Norm();
}

/// Whether face `f` and its neighbour across edge `j` are folded over each
/// other on one plane: normals folded, each one's far vertex within
/// `tolerance` of the other's plane.
template <class FaceType>
bool foldedOnPlane(const FaceType &f, int j, double tolerance) {
  const FaceType *g = f.cFFp(j);
  if (g == &f) return false;
  const Vec3 nf = faceNormal(f), ng = faceNormal(*g);
  if (!normalsFolded(nf, ng)) return false;
  const Vec3 onEdge = positionOf(f.cV(j));
  const Vec3 farF = positionOf(f.cV((j + 2) % 3)) - onEdge;
  const Vec3 farG = positionOf(g->cV((f.cFFi(j) + 2) % 3)) - onEdge;
  return std::abs(nf * farG) <= tolerance * nf.Norm() &&
         std::abs(ng * farF) <= tolerance * ng.Norm();
}

}  // namespace detail

/// Finds the faces folded over a neighbour on one plane
/// (detail::foldedOnPlane, within `settings.planeTolerance`) that have a
/// moved vertex (`isMoved(vertex index)`) or an edge neighbour with one (the
/// input's own folds beside a sharpened face too; folds far from any stay as
/// they came) and tiles the flat patch around each fold again
/// (detail::unfoldAround, across each edge the face is folded over until one
/// patch is), tiles with angles of at least `minAngleRad`. Then, at each
/// fold no tiling undid, it moves the vertices up to `relaxRings` rings
/// around it on the planes or lines their faces lie on within
/// `exactTolerance` (detail::relaxFlatFold): after every tiling, so that no
/// vertex a relaxation moved changes which outline is tiled. Needs a closed
/// 2-manifold with FF adjacency up to date; it stays so. Faces keep their
/// slots and no element is added, so an ElementSnapshot taken before
/// restores the mesh.
template <class MeshType, class IsMoved>
PlanarFoldStats unfoldPlanarPatches(MeshType &m, const IsMoved &isMoved,
                                    const FoldSettings &settings) {
  const double tolerance = settings.planeTolerance;
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
        const auto hasMoved = [&](const FaceType &g) {
          return moved[g.cV(0) - first] || moved[g.cV(1) - first] || moved[g.cV(2) - first];
        };
        if (!hasMoved(f) && !hasMoved(*f.cFFp(0)) && !hasMoved(*f.cFFp(1)) && !hasMoved(*f.cFFp(2)))
          return false;
        for (int j = 0; j < 3; ++j)
          if (detail::foldedOnPlane(f, j, tolerance)) return true;
        return false;
      },
      kParallelMin);
  PlanarFoldStats stats;
  std::vector<std::uint32_t> untiled;
  for (const std::uint32_t fi : folded) {
    FaceType *f = &m.face[fi];
    ++stats.folds;
    // Across each edge it is folded over (a patch tiled before may have
    // taken the fold away) until a patch there is tiled again.
    bool tiled = false;
    for (int j = 0; j < 3 && !tiled; ++j)
      if (detail::foldedOnPlane(*f, j, tolerance))
        tiled = detail::unfoldAround<MeshType>(f, j, tolerance, settings.minAngleRad,
                                               VertexRules::kMaxFoldPatchFaces);
    if (tiled)
      ++stats.patches;
    else
      untiled.push_back(fi);
  }
  std::vector<char> settled(m.vert.size(), 0);  // relaxed once: held from then on
  for (const std::uint32_t fi : untiled) {
    FaceType *f = &m.face[fi];
    for (int j = 0; j < 3; ++j)
      if (detail::foldedOnPlane(*f, j, tolerance)) {
        stats.relaxedVertices += detail::relaxFlatFold<MeshType>(f, j, settings, settled, first);
        break;
      }
  }
  return stats;
}

}  // namespace edge_sharpener
