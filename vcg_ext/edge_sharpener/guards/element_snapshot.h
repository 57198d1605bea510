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
    const SplitPlan &plan = moves.plan();
    const std::size_t n0 = plan.originalVertexCount, count = plan.faces.size();
    std::vector<std::vector<std::array<std::size_t, 3>>> children(count);
    std::vector<std::size_t> firstAppended(count);
    std::size_t next = triples_.size();  // the split appends children after the input faces
    for (std::size_t k = 0; k < count; ++k) {
      const auto &t = triples_[plan.faces[k].face];
      children[k] = detail::childTriangles(plan.faces[k], {t[0], t[1], t[2]}, n0);
      firstAppended[k] = next;
      next += children[k].size() - 1;
    }
    const auto insertedOf = [&](std::size_t k) {
      std::vector<std::size_t> out;
      for (int e : plan.faces[k].edgeVertex)
        if (e >= 0) out.push_back(n0 + std::size_t(e));
      if (plan.faces[k].centerVertex >= 0)
        out.push_back(n0 + std::size_t(plan.faces[k].centerVertex));
      return out;
    };
    const auto slot = [&](std::size_t k, std::size_t c) -> typename MeshType::FaceType & {
      return c == 0 ? m.face[plan.faces[k].face] : m.face[firstAppended[k] + c - 1];
    };
    std::vector<char> back(count, 0);
    std::vector<char> needed(plan.inserted.size(), 0);  // by a face that cannot go back
    for (std::size_t k = 0; k < count; ++k) {
      bool ok = true;
      for (std::size_t v : insertedOf(k)) ok = ok && !m.vert[v].IsD() && moves.isAtRest(v);
      for (std::uint32_t v : triples_[plan.faces[k].face]) ok = ok && moves.isAtRest(v);
      for (std::size_t c = 0; ok && c < children[k].size(); ++c) {
        const auto &f = slot(k, c);
        ok = !f.IsD();
        for (int j = 0; ok && j < 3; ++j) ok = vcg::tri::Index(m, f.cV(j)) == children[k][c][j];
      }
      back[k] = ok;
      if (!ok)
        for (std::size_t v : insertedOf(k)) needed[v - n0] = 1;
    }
    std::vector<std::vector<std::array<std::size_t, 3>>> rested(count);
    std::vector<char> rewritten(m.face.size(), 0);  // a given-back face's slots
    std::size_t given = 0;
    for (std::size_t k = 0; k < count; ++k) {
      if (!back[k]) continue;
      const SplitFace &sf = plan.faces[k];
      std::array<bool, 3> keep{};
      for (int i = 0; i < 3; ++i) keep[i] = sf.edgeVertex[i] >= 0 && needed[sf.edgeVertex[i]];
      const auto &t = triples_[sf.face];
      rested[k] = detail::restedTriangles(sf, {t[0], t[1], t[2]}, n0, keep);
      if (rested[k].size() == children[k].size()) {  // nothing to take away
        rested[k].clear();
        continue;
      }
      ++given;
      for (std::size_t c = 0; c < children[k].size(); ++c)
        rewritten[vcg::tri::Index(m, slot(k, c))] = 1;
    }
    if (given == 0) return 0;
    // Before the rewrite: the faces beside the rewritten ones, across the
    // edges they share with them (their vertices stay).
    std::vector<detail::FaceEdgeKey> beside;
    for (std::size_t k = 0; k < count; ++k)
      for (std::size_t c = 0; !rested[k].empty() && c < children[k].size(); ++c) {
        const auto &f = slot(k, c);
        for (int i = 0; i < 3; ++i) {
          const std::size_t g = vcg::tri::Index(m, f.cFFp(i));
          if (!rewritten[g]) beside.push_back(detail::faceEdgeKey(m, g, f.cFFi(i), true));
        }
      }
    std::vector<detail::FaceEdgeKey> edges;
    for (std::size_t k = 0; k < count; ++k) {
      if (rested[k].empty()) continue;
      for (std::size_t c = 0; c < children[k].size(); ++c) {
        auto &f = slot(k, c);
        if (c >= rested[k].size()) {
          vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
          continue;
        }
        for (int j = 0; j < 3; ++j) f.V(j) = &m.vert[rested[k][c][j]];
        for (int j = 0; j < 3; ++j)
          edges.push_back(detail::faceEdgeKey(m, vcg::tri::Index(m, f), j, false));
      }
      for (std::size_t v : insertedOf(k))
        if (!needed[v - n0] && !m.vert[v].IsD())
          vcg::tri::Allocator<MeshType>::DeleteVertex(m, m.vert[v]);
    }
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
    using FaceType = typename MeshType::FaceType;
    using VertexType = typename MeshType::VertexType;
    const SplitPlan &plan = moves.plan();
    const std::size_t first = moves.firstInserted(), n = plan.inserted.size();
    // v, a and b at rest, and v on the segment ab as rounded (checked below).
    const auto resting = [&](std::size_t k) {
      const InsertedVertexSource &s = plan.inserted[k];
      return s.originalCount == 2 && !m.vert[first + k].IsD() && moves.isAtRest(first + k) &&
             moves.isAtRest(s.original[0]) && moves.isAtRest(s.original[1]);
    };
    // Each candidate's first five faces (a fifth disqualifies it), in face
    // order: each thread lists (candidate, face) pairs of its own range of
    // faces, and the lists are read in range order.
    std::vector<char> candidate(n);
    for (std::size_t k = 0; k < n; ++k) candidate[k] = resting(k);
    const VertexType *firstInserted = m.vert.data() + first;
    const std::int64_t faceCount = std::int64_t(m.face.size());
    const int ranges = faceCount > kParallelMin ? detail::maxThreads() : 1;
    std::vector<detail::PerThread<std::vector<std::pair<std::uint32_t, std::uint32_t>>>> pairs(
        ranges);
#pragma omp parallel for schedule(static, 1) num_threads(ranges)
    for (int t = 0; t < ranges; ++t) {
      const std::int64_t begin = faceCount * t / ranges, end = faceCount * (t + 1) / ranges;
      for (std::int64_t fi = begin; fi < end; ++fi) {
        const FaceType &f = m.face[fi];
        if (f.IsD()) continue;
        for (int j = 0; j < 3; ++j) {
          const std::size_t k = std::size_t(f.cV(j) - firstInserted);  // wraps below first
          if (k < n && candidate[k]) pairs[t].value.emplace_back(std::uint32_t(k), fi);
        }
      }
    }
    std::vector<std::uint8_t> count(n, 0);
    std::vector<std::array<FaceType *, 4>> around(n);
    for (const auto &list : pairs)
      for (const auto &[k, fi] : list.value) {
        if (count[k] == 5) continue;
        if (count[k] < 4) around[k][count[k]] = &m.face[fi];
        ++count[k];
      }
    std::size_t removed = 0;
    for (std::size_t k = 0; k < n; ++k) {
      if (count[k] != 4) continue;  // two triangles on each side, no border
      VertexType *v = &m.vert[first + k];
      VertexType *a = &m.vert[plan.inserted[k].original[0]];
      VertexType *b = &m.vert[plan.inserted[k].original[1]];
      struct Side {
        VertexType *apex = nullptr;
        FaceType *withA = nullptr, *withB = nullptr;
      };
      std::array<Side, 2> sides;
      bool ok = true;
      for (FaceType *f : around[k]) {
        // An earlier merge may have deleted or changed a face (one holding
        // two candidates).
        const int iv = f->IsD() ? -1 : f->V(0) == v ? 0 : f->V(1) == v ? 1 : f->V(2) == v ? 2 : -1;
        if (iv < 0) {
          ok = false;
          break;
        }
        VertexType *p = f->V((iv + 1) % 3), *q = f->V((iv + 2) % 3);
        const bool hasA = p == a || q == a, hasB = p == b || q == b;
        if (hasA == hasB) {
          ok = false;
          break;
        }
        VertexType *apex = (p == a || p == b) ? q : p;
        Side *side = sides[0].apex == apex || !sides[0].apex ? &sides[0] : &sides[1];
        if (side->apex && side->apex != apex) {
          ok = false;
          break;
        }
        side->apex = apex;
        FaceType *&slot = hasA ? side->withA : side->withB;
        ok = slot == nullptr;
        slot = f;
        if (!ok) break;
      }
      for (const Side &side : sides) ok = ok && side.withA && side.withB && side.apex != v;
      if (!ok || !liesOnSegment(positionOf(v), positionOf(a), positionOf(b))) continue;
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
      ++removed;
    }
    return removed;
  }

 private:
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
