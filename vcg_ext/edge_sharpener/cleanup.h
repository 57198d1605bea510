// Stage 6: removal of the degenerate triangles that sharpening can create,
// e.g. where more than three sharp edges meet and several inserted vertices
// move to the same corner (paper, Figure 8; Botsch & Kobbelt, VMV 2001).
// Only faces produced by the subdivision are touched; original vertices never
// move and faces of smooth regions are never changed (an input vertex on a
// restored line may be merged away where every face around it keeps its plane).
#pragma once

#include <vcg/complex/complex.h>
#include <vcg/simplex/face/pos.h>
#include <vcg/simplex/face/topology.h>

#include <algorithm>
#include <vector>

#include "guards/vertex_moves.h"
#include "subdivision.h"
#include "util/fast_topology.h"
#include "util/parallel.h"

namespace edge_sharpener {

/// An inserted vertex whose placement the degenerate cleanup refused, and
/// where it had been placed (refused_moves.h may take it part of the way out).
struct RefusedPlacement {
  std::uint32_t vertex = 0;
  Vec3 placed;
};

namespace detail {

inline bool isSplitChild(FaceLabel label) {
  return label == FaceLabel::Chamfer || label == FaceLabel::Corner;
}

template <class FaceType>
double faceMinAngle(const FaceType &f) {
  return minTriangleAngle(positionOf(f.cV(0)), positionOf(f.cV(1)), positionOf(f.cV(2)));
}

template <class FaceType>
int longestEdgeIndex(const FaceType &f) {
  int best = 0;
  double bestLen = -1;
  for (int i = 0; i < 3; ++i) {
    const double len = (positionOf(f.cV(i)) - positionOf(f.cV((i + 1) % 3))).SquaredNorm();
    if (len > bestLen) bestLen = len, best = i;
  }
  return best;
}

template <class FaceType>
int shortestEdgeIndex(const FaceType &f) {
  int best = 0;
  double bestLen = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double len = (positionOf(f.cV(i)) - positionOf(f.cV((i + 1) % 3))).SquaredNorm();
    if (len < bestLen) bestLen = len, best = i;
  }
  return best;
}

/// Whether degenerate face `f` is a child of an input sliver that no revert
/// cures: its shortest edge joins two original vertices (the input's own short
/// edge) and it has an angle below `angleRad` with every vertex at rest too.
/// Wherever its inserted vertex lies, such a face stays a needle; sending the
/// vertex back would only give up its sharp edge or corner.
template <class MeshType>
bool isInputSliverAtRest(const MeshType &m, const typename MeshType::FaceType &f,
                         const VertexMoves<MeshType> &moves, double angleRad) {
  const int z = shortestEdgeIndex(f);
  if (vcg::tri::Index(m, f.cV(z)) >= moves.firstInserted() ||
      vcg::tri::Index(m, f.cV((z + 1) % 3)) >= moves.firstInserted())
    return false;
  const auto rest = [&](int k) { return moves.exactRest(vcg::tri::Index(m, f.cV(k))); };
  return minTriangleAngle(rest(0), rest(1), rest(2)) < angleRad;
}

}  // namespace detail

/// Collapses the shortest edge of a needle (a triangle whose shortest edge is
/// tiny next to its longest) when an endpoint is an inserted vertex: the
/// inserted vertex is removed and merged into the other endpoint, which keeps
/// its position. With `capsBetweenInserted`, also the shortest edge of a cap
/// when both its ends are inserted vertices (two new vertices placed on one
/// line, side by side, with a third vertex of it: the flat face between them
/// goes, and the line keeps its points); a corner vertex then stays, an edge
/// vertex goes; and of a cap with a vertex of a corner `placedWhole` (the
/// guards give such a corner up whole, undoing what merged into it) whose
/// shortest edge joins an inserted and an input vertex, its middle vertex
/// (opposite its longest edge) into the other end, where every face around
/// it keeps its plane (within `angleRad`). Refused when it would break
/// manifoldness (link condition) or flip a surrounding face. \return true
/// if collapsed; `removedFaces` then holds the number of faces deleted (2,
/// or 1 on a border edge).
template <class MeshType>
bool collapseNeedle(MeshType &m, typename MeshType::FaceType &f, const SplitPlan &plan,
                    double angleRad, int &removedFaces, bool capsBetweenInserted = false,
                    const std::vector<char> *placedWhole = nullptr) {
  using FaceType = typename MeshType::FaceType;
  using Pos = vcg::face::Pos<FaceType>;
  const int z = detail::shortestEdgeIndex(f);
  const double shortLen = (positionOf(f.cV(z)) - positionOf(f.cV((z + 1) % 3))).Norm();
  const int zl = detail::longestEdgeIndex(f);
  const double longLen = (positionOf(f.cV(zl)) - positionOf(f.cV((zl + 1) % 3))).Norm();
  const std::size_t ia = vcg::tri::Index(m, f.cV(z)), ib = vcg::tri::Index(m, f.cV((z + 1) % 3));
  const std::size_t n0 = plan.originalVertexCount;
  const bool insA = ia >= n0, insB = ib >= n0;
  const bool needle = shortLen <= 2 * std::sin(angleRad) * longLen;
  if (!insA && !insB) return false;
  // A cap with a vertex of a corner placed whole, all three on one line
  // into the corner (a remesher that casts its samples onto the surface
  // puts them on its sharp edges), between an inserted and an input vertex:
  // its middle vertex goes into the other end of its shortest edge where
  // every face around it keeps its plane.
  const auto isPlacedWhole = [&](int j) {
    const std::size_t v = vcg::tri::Index(m, f.cV(j));
    return placedWhole && v < placedWhole->size() && (*placedWhole)[v];
  };
  const bool middleOnLine = capsBetweenInserted && !needle && insA != insB &&
                            (isPlacedWhole(0) || isPlacedWhole(1) || isPlacedWhole(2)) &&
                            !isPlacedWhole((zl + 2) % 3);
  if (!needle && !(capsBetweenInserted && insA && insB) && !middleOnLine) return false;
  // FFEdgeCollapse removes V0 of the edge: pick the side where that is the
  // inserted vertex (the higher index when both are inserted; of a cap's
  // two, the one with fewer sources: a corner stays), or the cap's middle.
  bool removeA = middleOnLine ? f.cV(z) == f.cV((zl + 2) % 3) : insA && (!insB || ia > ib);
  if (!needle && !middleOnLine) {
    const int sourcesA = plan.inserted[ia - n0].originalCount;
    const int sourcesB = plan.inserted[ib - n0].originalCount;
    if (sourcesA != sourcesB) removeA = sourcesA < sourcesB;
  }
  FaceType *cf = &f;
  int cz = z;
  if (!removeA) {
    cf = f.FFp(z);
    cz = f.FFi(z);
    if (cf == &f) return false;
  }
  if (!detail::linkConditionHolds(*cf, cz)) return false;

  auto *gone = cf->V0(cz);
  auto *kept = cf->V1(cz);
  const Vec3 shift = positionOf(kept) - positionOf(gone);
  std::vector<Pos> star;
  vcg::face::VFOrderedStarFF(Pos(cf, cz, gone), star);
  for (const Pos &p : star) {
    const FaceType *g = p.F();
    if (g->cV(0) == kept || g->cV(1) == kept || g->cV(2) == kept)
      continue;  // removed with the edge
    Vec3 q[3], r[3];
    for (int j = 0; j < 3; ++j) {
      q[j] = positionOf(g->cV(j));
      r[j] = g->cV(j) == gone ? positionOf(kept) : q[j];
    }
    // A face with two corners at one point already (where several inserted
    // vertices and an input vertex meet at one target) has no orientation to
    // lose; a later collapse removes it.
    if (hasCoincidentCorners(q[0], q[1], q[2])) continue;
    const Vec3 before = triangleNormal(q[0], q[1], q[2]);
    const Vec3 after = triangleNormal(r[0], r[1], r[2]);
    if (!(before * after > 0)) return false;
    if (middleOnLine &&
        std::abs(before * shift) > std::sin(angleRad) * before.Norm() * shift.Norm())
      return false;
  }
  removedFaces = cf->FFp(cz) == cf ? 1 : 2;  // a border edge has one face
  vcg::face::FFEdgeCollapse(m, *cf, cz);
  return true;
}

/// Flips the longest edge of a cap (a triangle with an angle near 180
/// degrees) when the face across it also comes from a split face and the flip
/// raises the smaller minimum angle of the pair without folding it.
/// \return true if flipped.
template <class MeshType>
bool flipCap(typename MeshType::FaceType &f, MeshLabels<MeshType> &labels) {
  using FaceType = typename MeshType::FaceType;
  const int z = detail::longestEdgeIndex(f);
  FaceType *g = f.FFp(z);
  if (g == &f || !detail::isSplitChild(labels.face[g])) return false;
  const int w = f.FFi(z);
  auto *p = f.V0(z), *q = f.V1(z), *r = f.V2(z), *s = g->V2(w);
  if (r == s || g->V(w) != q || g->V1(w) != p) return false;
  for (auto *v : detail::VertexStar<FaceType>(f, (z + 2) % 3).neighbours)
    if (v == s) return false;  // the new edge exists already

  const Vec3 P = positionOf(p), Q = positionOf(q), R = positionOf(r), S = positionOf(s);
  const double before = std::min(minTriangleAngle(P, Q, R), minTriangleAngle(Q, P, S));
  const double after = std::min(minTriangleAngle(P, S, R), minTriangleAngle(S, Q, R));
  if (!(after > before)) return false;
  const Vec3 reference = triangleNormal(P, Q, R) + triangleNormal(Q, P, S);
  const Vec3 n1 = triangleNormal(P, S, R), n2 = triangleNormal(S, Q, R);
  if (!(n1 * reference > 0 && n2 * reference > 0 && n1 * n2 > 0)) return false;
  vcg::face::FlipEdge(f, z);
  return true;
}

/// Sends the moved inserted vertices of `f` back to rest; where each was
/// placed goes to `refused` (optional).
/// \return how many were sent back.
template <class MeshType>
std::size_t revertInsertedVertices(MeshType &m, typename MeshType::FaceType &f,
                                   VertexMoves<MeshType> &moves,
                                   std::vector<RefusedPlacement> *refused = nullptr) {
  std::size_t n = 0;
  for (int j = 0; j < 3; ++j) {
    const std::size_t v = vcg::tri::Index(m, f.V(j));
    if (v < moves.firstInserted() || !moves.isMoved(v)) continue;
    if (refused) refused->push_back({std::uint32_t(v), positionOf(f.cV(j))});
    moves.sendBack(v, Placement::DegenerateRevert);
    ++n;
  }
  return n;
}

/// Stage 6: removes faces with an angle below `angleRad` among the faces made
/// by subdivide(): needles by collapse, caps by flip or, where no flip helps
/// and both ends of the cap's shortest edge are inserted vertices or one of
/// them is and the cap has a vertex of a corner `placedWhole`, by collapse
/// (collapseNeedle), and otherwise by sending the face's moved vertices back
/// to rest, unless the face is an input sliver's child that stays a needle
/// at rest too (detail::isInputSliverAtRest). What is left is inherited from
/// the input: children of input slivers. Deleted elements are left flagged
/// (compact afterwards). With `onlyWhereMoved` (the auto method), a face none
/// of whose vertices moved is left as it is: it lies on its input face, and
/// a collapse would move the input's surface. `placedWhole` (by vertex index,
/// optional): the auto method's corners placed whole. `refused` (optional):
/// each vertex sent back, with where it was placed (takeRefusedPartWay()).
/// \pre placeInsertedVertices() ran; FF topology up to date.
template <class MeshType>
CleanupStats removeDegenerateTriangles(MeshType &m, VertexMoves<MeshType> &moves, double angleRad,
                                       bool onlyWhereMoved = false,
                                       const std::vector<char> *placedWhole = nullptr,
                                       std::vector<RefusedPlacement> *refused = nullptr) {
  const SplitPlan &plan = moves.plan();
  MeshLabels<MeshType> &labels = moves.labels();
  CleanupStats s;
  const auto anyMoved = [&](const typename MeshType::FaceType &f) {
    for (int j = 0; j < 3; ++j)
      if (moves.isMoved(vcg::tri::Index(m, f.cV(j)))) return true;
    return false;
  };
  const auto degenerate = [&](const typename MeshType::FaceType &f) {
    return !f.IsD() && detail::isSplitChild(labels.face[&f]) &&
           detail::faceMinAngle(f) < angleRad && (!onlyWhereMoved || anyMoved(f));
  };
  // Only split children can be degenerate, and no step below relabels a face
  // or adds one: scanning these (in index order) is scanning every face.
  const std::vector<std::uint32_t> children = detail::indicesWhere(
      std::int64_t(m.face.size()),
      [&](std::int64_t i) {
        return !m.face[i].IsD() && detail::isSplitChild(labels.face[&m.face[i]]);
      },
      kParallelMin);
  for (const std::size_t i : children) s.degenerateFound += degenerate(m.face[i]);
  if (s.degenerateFound == 0) return s;

  constexpr int kMaxPasses = 16;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    bool changed = false;
    for (const std::size_t i : children) {
      auto &f = m.face[i];
      if (!degenerate(f)) continue;
      int removed = 0;
      if (collapseNeedle(m, f, plan, angleRad, removed)) {
        ++s.collapses;
        s.removedFaces += std::size_t(removed);
      } else if (flipCap(f, labels)) {
        ++s.flips;
      } else if (collapseNeedle(m, f, plan, angleRad, removed, /*capsBetweenInserted=*/true,
                                placedWhole)) {
        ++s.collapses;
        s.removedFaces += std::size_t(removed);
      } else if (detail::isInputSliverAtRest(m, f, moves, angleRad)) {
        continue;
      } else if (std::size_t n = revertInsertedVertices(m, f, moves, refused)) {
        s.reverted += n;
      } else {
        continue;
      }
      changed = true;
    }
    if (!changed) break;
  }
  for (const std::size_t i : children) {
    const auto &f = m.face[i];
    if (!degenerate(f)) continue;
    bool moved = false;
    for (int j = 0; j < 3; ++j) moved |= labels.placement[f.cV(j)] == Placement::Moved;
    ++(moved && !detail::isInputSliverAtRest(m, f, moves, angleRad) ? s.remaining : s.inherited);
  }
  return s;
}

}  // namespace edge_sharpener
