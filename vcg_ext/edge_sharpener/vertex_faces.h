// Vertex -> incident faces as compressed rows: built once in O(F), read-only,
// and independent of the mesh's optional VF adjacency (which MeshLab meshes
// may not have enabled).
#pragma once

#include <cstdint>
#include <vector>

#include <vcg/complex/complex.h>

namespace edge_sharpener {

class VertexFaceTable {
 public:
  template <class MeshType>
  explicit VertexFaceTable(const MeshType &m) : offset_(m.vert.size() + 1, 0) {
    for (const auto &f : m.face)
      if (!f.IsD())
        for (int k = 0; k < 3; ++k) ++offset_[vcg::tri::Index(m, f.cV(k)) + 1];
    for (std::size_t v = 0; v + 1 < offset_.size(); ++v) offset_[v + 1] += offset_[v];
    face_.resize(offset_.back());
    std::vector<std::uint32_t> fill(offset_.begin(), offset_.end() - 1);
    for (std::size_t fi = 0; fi < m.face.size(); ++fi) {
      const auto &f = m.face[fi];
      if (f.IsD()) continue;
      for (int k = 0; k < 3; ++k) face_[fill[vcg::tri::Index(m, f.cV(k))]++] = std::uint32_t(fi);
    }
  }

  /// Indices of the faces incident to vertex v, in increasing order.
  const std::uint32_t *begin(std::size_t v) const { return face_.data() + offset_[v]; }
  const std::uint32_t *end(std::size_t v) const { return face_.data() + offset_[v + 1]; }
  std::size_t degree(std::size_t v) const { return offset_[v + 1] - offset_[v]; }

 private:
  std::vector<std::uint32_t> offset_;
  std::vector<std::uint32_t> face_;
};

}  // namespace edge_sharpener
