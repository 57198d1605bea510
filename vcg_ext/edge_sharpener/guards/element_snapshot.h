// The state of the mesh's vertices and faces at one point of sharpen(), to
// return to it exactly: positions, connectivity, FF adjacency and flags.
// Valid while no element is added: the cleanup and the intersection guard
// only move vertices, flip edges and flag elements deleted, so the element
// arrays keep their addresses.
#pragma once

#include <vcg/complex/algorithms/update/topology.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "../subdivision.h"
#include "../util/fast_topology.h"
#include "../util/geometry.h"
#include "../util/mesh_labels.h"
#include "../util/parallel.h"
#include "vertex_moves.h"

namespace edge_sharpener {

template <class MeshType>
class ElementSnapshot {
 public:
  ElementSnapshot(const MeshType &m, const MeshLabels<MeshType> &labels)
      : vertices_(m.vert.size()), faces_(m.face.size()), vn_(m.vn), fn_(m.fn) {
    const std::int64_t nv = std::int64_t(m.vert.size()), nf = std::int64_t(m.face.size());
#pragma omp parallel for schedule(static, 8192) if (nv > kParallelMin)
    for (std::int64_t i = 0; i < nv; ++i) {
      const auto &v = m.vert[i];
      vertices_[i] = {v.cP(), v.cFlags(), labels.placement[&v]};
    }
#pragma omp parallel for schedule(static, 8192) if (nf > kParallelMin)
    for (std::int64_t i = 0; i < nf; ++i) {
      const auto &f = m.face[i];
      FaceState &s = faces_[i];
      for (int k = 0; k < 3; ++k) {
        s.vertex[k] = std::uint32_t(vcg::tri::Index(m, f.cV(k)));
        s.adjacent[k] = std::uint32_t(vcg::tri::Index(m, f.cFFp(k)));
        s.adjacentEdge[k] = std::int8_t(f.cFFi(k));
      }
      s.flags = f.cFlags();
    }
  }

  /// Writes the states back. \throws std::logic_error if elements were added.
  void restore(MeshType &m, MeshLabels<MeshType> &labels) const {
    if (m.vert.size() != vertices_.size() || m.face.size() != faces_.size())
      throw std::logic_error("ElementSnapshot: elements were added since the snapshot");
    for (std::size_t i = 0; i < vertices_.size(); ++i) {
      auto &v = m.vert[i];
      v.P() = vertices_[i].position;
      v.Flags() = vertices_[i].flags;
      labels.placement[&v] = vertices_[i].placement;
    }
    for (std::size_t i = 0; i < faces_.size(); ++i) {
      auto &f = m.face[i];
      const FaceState &s = faces_[i];
      for (int k = 0; k < 3; ++k) {
        f.V(k) = &m.vert[s.vertex[k]];
        f.FFp(k) = &m.face[s.adjacent[k]];
        f.FFi(k) = s.adjacentEdge[k];
      }
      f.Flags() = s.flags;
    }
    m.vn = vn_;
    m.fn = fn_;
  }

 private:
  // Only what the cleanup and the intersection guard change: positions,
  // connectivity, adjacency, flags, placement outcomes.
  struct VertexState {
    typename MeshType::CoordType position;
    int flags;
    Placement placement;
  };
  struct FaceState {
    std::array<std::uint32_t, 3> vertex, adjacent;
    std::array<std::int8_t, 3> adjacentEdge;
    int flags;
  };
  std::vector<VertexState> vertices_;
  std::vector<FaceState> faces_;
  int vn_, fn_;
};

}  // namespace edge_sharpener

namespace edge_sharpener {

/// The input's faces as vertex index triples, taken before the split: the
/// auto method gives back its input face to every split face it left at rest
/// (the split's extra vertices would change nothing of the surface, but they
/// would stay in the user's mesh, and in its sampling), and so the input
/// whole when it sharpens nothing.
template <class MeshType>
class InputFaces {
 public:
  explicit InputFaces(const MeshType &m) : triples_(m.face.size()) {
    const auto index = [&](const typename MeshType::VertexType *v) {
      return std::uint32_t(vcg::tri::Index(m, v));
    };
    const std::int64_t nf = std::int64_t(m.face.size());
#pragma omp parallel for schedule(static, 8192) if (nf > kParallelMin)
    for (std::int64_t i = 0; i < nf; ++i) {
      const auto &f = m.face[i];
      triples_[i] = {index(f.cV(0)), index(f.cV(1)), index(f.cV(2))};
    }
  }

  /// Each input face's three vertices.
  const std::vector<std::array<std::uint32_t, 3>> &faceVertices() const {
    return triples_;
  }

  /// Gives back its input face to every split face whose vertices all rest
  /// and whose children are as the split made them. An inserted vertex on
  /// its edge that a split face beside it still needs (that face cannot go
  /// back) stays, and the face becomes its input face fanned from that
  /// vertex (restedTriangles): the same surface, as the face is at rest.
  /// Rewrites the children's slots and deletes the rest and the inserted
  /// vertices no face needs, by flag. FF adjacency, up to date on entry,
  /// stays up to date (detail::linkFaceEdges over the rewritten faces).
  /// \return the number of faces given back (with or without a kept vertex).
  std::size_t unsplitResting(MeshType &m, const VertexMoves<MeshType> &moves) const {
    const SplitChildren children = splitChildren(m, moves.plan());
    const std::vector<char> back = splitFacesGoingBack(children, moves);
    const std::vector<char> needed = neededInserted(children, back);
    const std::vector<Triangles> rested = restedChildren(children, back, needed);
    const std::size_t given = std::size_t(
        std::count_if(rested.begin(), rested.end(), [](const Triangles &r) { return !r.empty(); }));
    if (given == 0) return 0;
    const std::vector<detail::FaceEdgeKey> beside = edgesBeside(children, rested);
    std::vector<detail::FaceEdgeKey> edges = rewriteChildren(children, rested, needed);
    edges.insert(edges.end(), beside.begin(), beside.end());
    detail::linkFaceEdges(m, edges);
    return given;
  }

  /// Removes each inserted edge vertex that unsplitResting could not (a
  /// split face beside it kept a moved vertex) where it and its input edge
  /// (a, b) are at rest and exactly two triangles (a, v, x) and (v, b, x)
  /// hold it on each side: these become (a, b, x), the same surface, as v
  /// lies on the segment ab. Such a vertex adds nothing to the shape, and
  /// metrics that sample vertices (MeshLab's Hausdorff filter) would count
  /// it twice. Deletes by flag. FF adjacency, up to date on entry, stays up
  /// to date, by a local update around each merge.
  /// \return the number of vertices removed.
  static std::size_t dissolveRestingEdgeVertices(MeshType &m, const VertexMoves<MeshType> &moves) {
    using VertexType = typename MeshType::VertexType;
    const SplitPlan &plan = moves.plan();
    const std::size_t first = moves.firstInserted();
    const std::vector<char> candidate = restingEdgeVertices(m, moves);
    const FacesAround around = firstFacesAround(m, candidate, first);
    std::size_t removed = 0;
    for (std::size_t k = 0; k < candidate.size(); ++k) {
      if (around.count[k] != 4) continue;  // two triangles on each side, no border
      VertexType *v = &m.vert[first + k];
      VertexType *a = &m.vert[plan.inserted[k].original[0]];
      VertexType *b = &m.vert[plan.inserted[k].original[1]];
      std::array<Side, 2> sides;
      if (!findSides(v, a, b, around.faces[k], sides) ||
          !liesOnSegment(positionOf(v), positionOf(a), positionOf(b)) ||
          // merging v into a collapses edge (a, v): not where a and b are
          // joined already (the collapse would give edge (a, b) a third face)
          !detail::linkConditionHolds(*sides[0].withA, edgeIndex(*sides[0].withA, a, v)))
        continue;
      mergeSides(m, v, a, sides);
      ++removed;
    }
    return removed;
  }

 private:
  using Triangles = std::vector<std::array<std::size_t, 3>>;

  /// Input face f's vertices.
  std::array<std::size_t, 3> inputFace(std::size_t f) const {
    const auto &t = triples_[f];
    return {t[0], t[1], t[2]};
  }

  /// Each split face's children (per SplitPlan::faces) as the split made
  /// them, and their slots: child 0 in the input face's, the others appended
  /// after the input faces, split face after split face.
  struct SplitChildren {
    MeshType &m;
    const SplitPlan &plan;
    std::vector<Triangles> triangles;
    std::vector<std::size_t> firstAppended;

    typename MeshType::FaceType &slot(std::size_t k, std::size_t c) const {
      return c == 0 ? m.face[plan.faces[k].face] : m.face[firstAppended[k] + c - 1];
    }
    /// Split face k's inserted vertices (mesh indices).
    std::vector<std::size_t> inserted(std::size_t k) const {
      const std::size_t n0 = plan.originalVertexCount;
      std::vector<std::size_t> out;
      for (int e : plan.faces[k].edgeVertex)
        if (e >= 0) out.push_back(n0 + std::size_t(e));
      if (plan.faces[k].centerVertex >= 0)
        out.push_back(n0 + std::size_t(plan.faces[k].centerVertex));
      return out;
    }
  };

  SplitChildren splitChildren(MeshType &m, const SplitPlan &plan) const {
    const std::size_t count = plan.faces.size();
    SplitChildren out{m, plan, std::vector<Triangles>(count), std::vector<std::size_t>(count)};
    std::size_t next = triples_.size();  // the split appends children after the input faces
    for (std::size_t k = 0; k < count; ++k) {
      const SplitFace &sf = plan.faces[k];
      out.triangles[k] = detail::childTriangles(sf, inputFace(sf.face), plan.originalVertexCount);
      out.firstAppended[k] = next;
      next += out.triangles[k].size() - 1;
    }
    return out;
  }

  /// Per split face: whether it may go back, its vertices (input and
  /// inserted, none deleted) at rest and its children as the split made them.
  std::vector<char> splitFacesGoingBack(const SplitChildren &ch,
                                        const VertexMoves<MeshType> &moves) const {
    const MeshType &m = ch.m;
    std::vector<char> back(ch.plan.faces.size(), 0);
    for (std::size_t k = 0; k < back.size(); ++k) {
      bool ok = true;
      for (std::size_t v : ch.inserted(k)) ok = ok && !m.vert[v].IsD() && moves.isAtRest(v);
      for (std::uint32_t v : triples_[ch.plan.faces[k].face]) ok = ok && moves.isAtRest(v);
      for (std::size_t c = 0; ok && c < ch.triangles[k].size(); ++c) {
        const auto &f = ch.slot(k, c);
        ok = !f.IsD();
        for (int j = 0; ok && j < 3; ++j) ok = vcg::tri::Index(m, f.cV(j)) == ch.triangles[k][c][j];
      }
      back[k] = ok;
    }
    return back;
  }

  /// Per inserted vertex: whether a split face that cannot go back needs it.
  static std::vector<char> neededInserted(const SplitChildren &ch, const std::vector<char> &back) {
    std::vector<char> needed(ch.plan.inserted.size(), 0);
    for (std::size_t k = 0; k < back.size(); ++k)
      if (!back[k])
        for (std::size_t v : ch.inserted(k)) needed[v - ch.plan.originalVertexCount] = 1;
    return needed;
  }

  /// Per split face going back: its input face fanned from the edge
  /// vertices still needed (restedTriangles); empty where it stays split
  /// (it cannot go back, or there is nothing to take away).
  std::vector<Triangles> restedChildren(const SplitChildren &ch, const std::vector<char> &back,
                                        const std::vector<char> &needed) const {
    std::vector<Triangles> rested(back.size());
    for (std::size_t k = 0; k < back.size(); ++k) {
      if (!back[k]) continue;
      const SplitFace &sf = ch.plan.faces[k];
      std::array<bool, 3> keep{};
      for (int i = 0; i < 3; ++i) keep[i] = sf.edgeVertex[i] >= 0 && needed[sf.edgeVertex[i]];
      rested[k] =
          detail::restedTriangles(sf, inputFace(sf.face), ch.plan.originalVertexCount, keep);
      if (rested[k].size() == ch.triangles[k].size()) rested[k].clear();  // nothing to take away
    }
    return rested;
  }

  /// Before the rewrite: the faces beside the rewritten ones, across the
  /// edges they share with them (their vertices stay).
  static std::vector<detail::FaceEdgeKey> edgesBeside(const SplitChildren &ch,
                                                      const std::vector<Triangles> &rested) {
    const MeshType &m = ch.m;
    std::vector<char> rewritten(m.face.size(), 0);  // a given-back face's slots
    for (std::size_t k = 0; k < rested.size(); ++k)
      for (std::size_t c = 0; !rested[k].empty() && c < ch.triangles[k].size(); ++c)
        rewritten[vcg::tri::Index(m, ch.slot(k, c))] = 1;
    std::vector<detail::FaceEdgeKey> beside;
    for (std::size_t k = 0; k < rested.size(); ++k)
      for (std::size_t c = 0; !rested[k].empty() && c < ch.triangles[k].size(); ++c) {
        const auto &f = ch.slot(k, c);
        for (int i = 0; i < 3; ++i) {
          const std::size_t g = vcg::tri::Index(m, f.cFFp(i));
          if (!rewritten[g]) beside.push_back(detail::faceEdgeKey(m, g, f.cFFi(i), true));
        }
      }
    return beside;
  }

  /// Writes each rested face into its children's slots and deletes the
  /// children left over and the inserted vertices no face needs.
  /// \return the rewritten faces' edges.
  static std::vector<detail::FaceEdgeKey> rewriteChildren(const SplitChildren &ch,
                                                          const std::vector<Triangles> &rested,
                                                          const std::vector<char> &needed) {
    MeshType &m = ch.m;
    std::vector<detail::FaceEdgeKey> edges;
    for (std::size_t k = 0; k < rested.size(); ++k) {
      if (rested[k].empty()) continue;
      for (std::size_t c = 0; c < ch.triangles[k].size(); ++c) {
        auto &f = ch.slot(k, c);
        if (c >= rested[k].size()) {
          vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
          continue;
        }
        for (int j = 0; j < 3; ++j) f.V(j) = &m.vert[rested[k][c][j]];
        for (int j = 0; j < 3; ++j)
          edges.push_back(detail::faceEdgeKey(m, vcg::tri::Index(m, f), j, false));
      }
      for (std::size_t v : ch.inserted(k))
        if (!needed[v - ch.plan.originalVertexCount] && !m.vert[v].IsD())
          vcg::tri::Allocator<MeshType>::DeleteVertex(m, m.vert[v]);
    }
    return edges;
  }

  /// Per inserted vertex: whether it is an edge vertex at rest, and its
  /// input edge's ends too (that it lies on the segment as rounded is
  /// checked apart).
  static std::vector<char> restingEdgeVertices(const MeshType &m,
                                               const VertexMoves<MeshType> &moves) {
    const SplitPlan &plan = moves.plan();
    const std::size_t first = moves.firstInserted();
    std::vector<char> resting(plan.inserted.size());
    for (std::size_t k = 0; k < resting.size(); ++k) {
      const InsertedVertexSource &s = plan.inserted[k];
      resting[k] = s.originalCount == 2 && !m.vert[first + k].IsD() && moves.isAtRest(first + k) &&
                   moves.isAtRest(s.original[0]) && moves.isAtRest(s.original[1]);
    }
    return resting;
  }

  /// Per candidate: how many faces hold it (counted up to five: a fifth
  /// disqualifies it) and the first four, in face order.
  struct FacesAround {
    std::vector<std::uint8_t> count;
    std::vector<std::array<typename MeshType::FaceType *, 4>> faces;
  };

  /// The faces around each `candidate` (inserted vertex first + k). The
  /// faces holding one are listed on every core, in face order.
  static FacesAround firstFacesAround(MeshType &m, const std::vector<char> &candidate,
                                      std::size_t first) {
    const std::size_t n = candidate.size();
    const auto *firstInserted = m.vert.data() + first;
    // Vertex v's candidate index, or n (below first, the index wraps).
    const auto candidateOf = [&](const typename MeshType::VertexType *v) {
      const std::size_t k = std::size_t(v - firstInserted);
      return k < n && candidate[k] ? k : n;
    };
    const std::vector<std::uint32_t> holding = detail::indicesWhere(
        std::int64_t(m.face.size()),
        [&](std::int64_t fi) {
          const auto &f = m.face[fi];
          return !f.IsD() &&
                 (candidateOf(f.cV(0)) < n || candidateOf(f.cV(1)) < n || candidateOf(f.cV(2)) < n);
        },
        kParallelMin);
    FacesAround out{std::vector<std::uint8_t>(n, 0),
                    std::vector<std::array<typename MeshType::FaceType *, 4>>(n)};
    for (const std::uint32_t fi : holding)
      for (int j = 0; j < 3; ++j) {
        const std::size_t k = candidateOf(m.face[fi].cV(j));
        if (k == n || out.count[k] == 5) continue;
        if (out.count[k] < 4) out.faces[k][out.count[k]] = &m.face[fi];
        ++out.count[k];
      }
    return out;
  }

  /// One side of an edge vertex v between a and b: its apex x and the
  /// triangles (a, v, x) and (v, b, x).
  struct Side {
    typename MeshType::VertexType *apex = nullptr;
    typename MeshType::FaceType *withA = nullptr, *withB = nullptr;
  };

  /// Puts face f around v on its side. \return false where f does not fit
  /// the two sides (an earlier merge may have deleted or changed a face
  /// holding two candidates).
  template <class FaceType, class VertexType>
  static bool addToSide(FaceType *f, const VertexType *v, const VertexType *a, const VertexType *b,
                        std::array<Side, 2> &sides) {
    const int iv = f->IsD() ? -1 : f->V(0) == v ? 0 : f->V(1) == v ? 1 : f->V(2) == v ? 2 : -1;
    if (iv < 0) return false;
    VertexType *p = f->V((iv + 1) % 3), *q = f->V((iv + 2) % 3);
    const bool hasA = p == a || q == a, hasB = p == b || q == b;
    if (hasA == hasB) return false;
    VertexType *apex = (p == a || p == b) ? q : p;
    Side *side = sides[0].apex == apex || !sides[0].apex ? &sides[0] : &sides[1];
    if (side->apex && side->apex != apex) return false;
    side->apex = apex;
    FaceType *&slot = hasA ? side->withA : side->withB;
    const bool wasEmpty = slot == nullptr;
    slot = f;
    return wasEmpty;
  }

  /// The two sides of edge vertex v between a and b from its four faces.
  /// \return whether each side has both its triangles.
  template <class FaceType, class VertexType>
  static bool findSides(const VertexType *v, const VertexType *a, const VertexType *b,
                        const std::array<FaceType *, 4> &faces, std::array<Side, 2> &sides) {
    for (FaceType *f : faces)
      if (!addToSide(f, v, a, b, sides)) return false;
    for (const Side &side : sides)
      if (!side.withA || !side.withB || side.apex == v) return false;
    return true;
  }

  /// Each side's (a, v, x) and (v, b, x) become (a, b, x); v is deleted.
  template <class VertexType>
  static void mergeSides(MeshType &m, VertexType *v, VertexType *a,
                         const std::array<Side, 2> &sides) {
    for (const Side &side : sides) {
      // (v, b, x) -> (a, b, x): v lies between a and b, so the winding stays.
      for (int j = 0; j < 3; ++j)
        if (side.withB->V(j) == v) side.withB->V(j) = a;
      // Edge (v, b) became (a, b) in place: its neighbour, the other
      // side's (v, b, y), is still right. Edge (x, v) became (x, a): its
      // neighbour is (a, v, x)'s across (x, a).
      adoptNeighbour(*side.withB, *side.withA, a, side.apex);
      vcg::tri::Allocator<MeshType>::DeleteFace(m, *side.withA);
    }
    vcg::tri::Allocator<MeshType>::DeleteVertex(m, *v);
  }

  /// The index of f's edge between vertices p and q (-1: none).
  template <class FaceType, class VertexType>
  static int edgeIndex(const FaceType &f, const VertexType *p, const VertexType *q) {
    for (int i = 0; i < 3; ++i) {
      const VertexType *s = f.cV(i), *t = f.cV((i + 1) % 3);
      if ((s == p && t == q) || (s == q && t == p)) return i;
    }
    return -1;
  }

  /// `kept`'s edge (p, q) takes over `gone`'s edge (p, q) and its neighbour
  /// (a border stays a border), before `gone` is deleted.
  template <class FaceType, class VertexType>
  static void adoptNeighbour(FaceType &kept, FaceType &gone, const VertexType *p,
                             const VertexType *q) {
    const int i = edgeIndex(kept, p, q), j = edgeIndex(gone, p, q);
    if (i < 0 || j < 0) throw std::logic_error("resting-vertex merge: edge not found");
    FaceType *g = gone.FFp(j);
    if (g == &gone) {
      kept.FFp(i) = &kept;
      kept.FFi(i) = i;
      return;
    }
    const int eg = gone.FFi(j);
    kept.FFp(i) = g;
    kept.FFi(i) = eg;
    g->FFp(eg) = &kept;
    g->FFi(eg) = i;
  }

  std::vector<std::array<std::uint32_t, 3>> triples_;
};

}  // namespace edge_sharpener
