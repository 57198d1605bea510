// Vertex -> incident faces as compressed rows: built once in O(F), read-only,
// and independent of the mesh's optional VF adjacency (which MeshLab meshes
// may not have enabled).
#pragma once

#include <vcg/complex/complex.h>

#include <cstdint>
#include <vector>

#include "fast_topology.h"
#include "parallel.h"

namespace edge_sharpener {

class VertexFaceTable {
 public:
  /// Built on every core where that pays: the faces are cut into one
  /// contiguous range per thread; each range's corners are counted, then
  /// filled in after those of the ranges before it, so every row is still
  /// in increasing face order.
  template <class MeshType>
  explicit VertexFaceTable(const MeshType &m) : offset_(m.vert.size() + 1, 0) {
    const std::size_t nv = m.vert.size();
    const std::int64_t nf = std::int64_t(m.face.size());
    const int threads = nf > kParallelMin ? detail::maxThreads() : 1;
    // Per range of faces and vertex: corners counted, then the next slot to fill.
    std::vector<std::vector<std::uint32_t>> slot(threads);
    const auto range = [&](int t) {
      return std::pair<std::int64_t, std::int64_t>{nf * t / threads, nf * (t + 1) / threads};
    };
#pragma omp parallel for schedule(static, 1) num_threads(threads)
    for (int t = 0; t < threads; ++t) {
      slot[t].assign(nv, 0);
      const auto [begin, end] = range(t);
      for (std::int64_t fi = begin; fi < end; ++fi)
        if (!m.face[fi].IsD())
          for (int k = 0; k < 3; ++k) ++slot[t][vcg::tri::Index(m, m.face[fi].cV(k))];
    }
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < nv; ++v) {
      offset_[v] = next;
      for (int t = 0; t < threads; ++t) {
        const std::uint32_t count = slot[t][v];
        slot[t][v] = next;
        next += count;
      }
    }
    offset_[nv] = next;
    face_.resize(next);
#pragma omp parallel for schedule(static, 1) num_threads(threads)
    for (int t = 0; t < threads; ++t) {
      const auto [begin, end] = range(t);
      for (std::int64_t fi = begin; fi < end; ++fi)
        if (!m.face[fi].IsD())
          for (int k = 0; k < 3; ++k)
            face_[slot[t][vcg::tri::Index(m, m.face[fi].cV(k))]++] = std::uint32_t(fi);
    }
  }

  /// Only the vertices v with wanted[v] != 0 get their faces (the others
  /// none): a pass over the faces that writes little when few are wanted.
  /// \pre wanted.size() == m.vert.size().
  template <class MeshType>
  VertexFaceTable(const MeshType &m, const std::vector<char> &wanted)
      : offset_(m.vert.size() + 1, 0) {
    for (const auto &f : m.face)
      if (!f.IsD())
        for (int k = 0; k < 3; ++k) {
          const std::size_t v = vcg::tri::Index(m, f.cV(k));
          if (wanted[v]) ++offset_[v + 1];
        }
    for (std::size_t v = 0; v + 1 < offset_.size(); ++v) offset_[v + 1] += offset_[v];
    face_.resize(offset_.back());
    std::vector<std::uint32_t> fill(offset_.begin(), offset_.end() - 1);
    for (std::size_t fi = 0; fi < m.face.size(); ++fi) {
      const auto &f = m.face[fi];
      if (f.IsD()) continue;
      for (int k = 0; k < 3; ++k) {
        const std::size_t v = vcg::tri::Index(m, f.cV(k));
        if (wanted[v]) face_[fill[v]++] = std::uint32_t(fi);
      }
    }
  }

  /// Indices of the faces incident to vertex v, in increasing order.
  const std::uint32_t *begin(std::size_t v) const {
    return face_.data() + offset_[v];
  }
  const std::uint32_t *end(std::size_t v) const {
    return face_.data() + offset_[v + 1];
  }
  std::size_t degree(std::size_t v) const {
    return offset_[v + 1] - offset_[v];
  }

 private:
  std::vector<std::uint32_t> offset_;
  std::vector<std::uint32_t> face_;
};

}  // namespace edge_sharpener
