// Vertex -> incident faces as compressed rows: built once in O(F), read-only,
// and independent of the mesh's optional VF adjacency (which MeshLab meshes
// may not have enabled).
#pragma once

#include <vcg/complex/complex.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "fast_topology.h"
#include "geometry.h"
#include "parallel.h"

namespace edge_sharpener {

class VertexFaceTable {
 public:
  /// No rows (assign a built table before reading it).
  VertexFaceTable() = default;

  /// Every vertex's faces.
  template <class MeshType>
  explicit VertexFaceTable(const MeshType &m) {
    build(m, [](std::size_t) { return true; });
  }

  /// Only the vertices v with wanted[v] != 0 get their faces (the others
  /// none): little is written when few are wanted.
  /// \pre wanted.size() == m.vert.size().
  template <class MeshType>
  VertexFaceTable(const MeshType &m, const std::vector<char> &wanted) {
    build(m, [&](std::size_t v) { return wanted[v] != 0; });
  }

  /// Indices of the faces incident to vertex v, in increasing order.
  const std::uint32_t *begin(std::size_t v) const { return face_.data() + offset_[v]; }
  const std::uint32_t *end(std::size_t v) const { return face_.data() + offset_[v + 1]; }
  std::size_t degree(std::size_t v) const { return offset_[v + 1] - offset_[v]; }

 private:
  /// On every core where that pays: the faces are cut into one contiguous
  /// range per thread; each range's corners are counted, then filled in
  /// after those of the ranges before it, so every row is still in
  /// increasing face order.
  template <class MeshType, class Wanted>
  void build(const MeshType &m, Wanted &&wanted) {
    const std::size_t nv = m.vert.size();
    offset_.assign(nv + 1, 0);
    const std::int64_t nf = std::int64_t(m.face.size());
    const int ranges = nf > kParallelMin ? detail::maxThreads() : 1;
    // Per range of faces and vertex: corners counted, then the next slot to fill.
    std::vector<std::vector<std::uint32_t>> slot(ranges);
    const auto bounds = [&](int t) {
      return std::pair<std::int64_t, std::int64_t>{nf * t / ranges, nf * (t + 1) / ranges};
    };
#pragma omp parallel for schedule(static, 1) num_threads(ranges)
    for (int t = 0; t < ranges; ++t) {
      slot[t].assign(nv, 0);
      const auto [first, last] = bounds(t);
      for (std::int64_t fi = first; fi < last; ++fi)
        if (!m.face[fi].IsD())
          for (int k = 0; k < 3; ++k) {
            const std::size_t v = vcg::tri::Index(m, m.face[fi].cV(k));
            if (wanted(v)) ++slot[t][v];
          }
    }
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < nv; ++v) {
      offset_[v] = next;
      for (int t = 0; t < ranges; ++t) {
        const std::uint32_t count = slot[t][v];
        slot[t][v] = next;
        next += count;
      }
    }
    offset_[nv] = next;
    face_.resize(next);
#pragma omp parallel for schedule(static, 1) num_threads(ranges)
    for (int t = 0; t < ranges; ++t) {
      const auto [first, last] = bounds(t);
      for (std::int64_t fi = first; fi < last; ++fi)
        if (!m.face[fi].IsD())
          for (int k = 0; k < 3; ++k) {
            const std::size_t v = vcg::tri::Index(m, m.face[fi].cV(k));
            if (wanted(v)) face_[slot[t][v]++] = std::uint32_t(fi);
          }
    }
  }

  std::vector<std::uint32_t> offset_;
  std::vector<std::uint32_t> face_;
};

namespace detail {

/// Neighbouring vertices of v (through its faces in `vf`), with
/// repetitions: each neighbour of an inner vertex twice (the two faces of
/// their edge).
template <class MeshType, class Visit>
void forEachNeighbour(const MeshType &m, const VertexFaceTable &vf, std::size_t v, Visit &&visit) {
  for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v); ++fi)
    for (int k = 0; k < 3; ++k) {
      const std::size_t u = vcg::tri::Index(m, m.face[*fi].cV(k));
      if (u != v) visit(u);
    }
}

/// Walks the rings of vertices around v (through its faces in `vf`): calls
/// visitRing(ring) with each ring's vertices, the nearest ring first, until
/// `rings` rings are visited or visitRing returns false. A vertex u counts as
/// seen when mark[u] == seen (v's entry is set first), so a caller reuses
/// `mark` between walks with a new `seen`; `frontier` and `next` are buffers.
template <class MeshType, class Mark, class VisitRing>
void forEachRing(const MeshType &m, const VertexFaceTable &vf, std::size_t v, int rings,
                 std::vector<Mark> &mark, Mark seen, std::vector<std::size_t> &frontier,
                 std::vector<std::size_t> &next, VisitRing &&visitRing) {
  frontier.assign(1, v);
  mark[v] = seen;
  for (int ring = 0; ring < rings; ++ring) {
    next.clear();
    for (const std::size_t w : frontier)
      forEachNeighbour(m, vf, w, [&](std::size_t u) {
        if (mark[u] == seen) return;
        mark[u] = seen;
        next.push_back(u);
      });
    if (!visitRing(next)) return;
    frontier.swap(next);
  }
}

/// Whether moving v to `target` keeps every face of `faces` facing the same
/// way and creates no angle below `degenerateAngleRad` that was not there. A
/// face with two corners at one point before the move and after it
/// (hasCoincidentCorners: placement put two new vertices of a grid-aligned
/// edge on one target) faces no way and refuses nothing; a face that already
/// had such an angle (v beside two new vertices on the restored line) may
/// keep one, thinner or not: the cleanup removes both kinds later. Where
/// the target lies on the restored edge, a face whose other two corners are
/// new vertices (index `firstInserted` or above: placed on that line) and
/// that is left with such an angle refuses nothing either, whichever way it
/// faces: the cleanup removes it too. `firstInserted` 0: no such face.
template <class MeshType>
bool moveKeepsFaces(const MeshType &m, const std::vector<std::uint32_t> &faces, std::size_t v,
                    const Vec3 &target, double degenerateAngleRad, std::size_t firstInserted = 0) {
  for (const std::uint32_t fi : faces) {
    const auto &f = m.face[fi];
    Vec3 q[3], r[3];
    int newCorners = 0;
    for (int k = 0; k < 3; ++k) {
      const std::size_t u = vcg::tri::Index(m, f.cV(k));
      q[k] = positionOf(f.cV(k));
      r[k] = u == v ? target : q[k];
      newCorners += firstInserted > 0 && u >= firstInserted;
    }
    if (hasCoincidentCorners(q[0], q[1], q[2]) && hasCoincidentCorners(r[0], r[1], r[2])) continue;
    const Vec3 before = (q[1] - q[0]) ^ (q[2] - q[0]);
    const Vec3 after = (r[1] - r[0]) ^ (r[2] - r[0]);
    const double minBefore = minTriangleAngle(q[0], q[1], q[2]);
    const double minAfter = minTriangleAngle(r[0], r[1], r[2]);
    if (newCorners == 2 && minAfter < degenerateAngleRad) continue;
    if (!(before * after > 0 && (minAfter >= degenerateAngleRad || minBefore < degenerateAngleRad)))
      return false;
  }
  return true;
}

}  // namespace detail

}  // namespace edge_sharpener
