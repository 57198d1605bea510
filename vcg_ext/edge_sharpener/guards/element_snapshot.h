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
#include <vector>

#include "../subdivision.h"
#include "../util/mesh_labels.h"
#include "vertex_moves.h"

namespace edge_sharpener {

template <class MeshType>
class ElementSnapshot {
 public:
  ElementSnapshot(const MeshType &m, const MeshLabels<MeshType> &labels) : vn_(m.vn), fn_(m.fn) {
    vertices_.reserve(m.vert.size());
    for (const auto &v : m.vert) vertices_.push_back({v.cP(), v.cFlags(), labels.placement[&v]});
    faces_.reserve(m.face.size());
    for (const auto &f : m.face) {
      FaceState s;
      for (int k = 0; k < 3; ++k) {
        s.vertex[k] = std::uint32_t(vcg::tri::Index(m, f.cV(k)));
        s.adjacent[k] = std::uint32_t(vcg::tri::Index(m, f.cFFp(k)));
        s.adjacentEdge[k] = std::int8_t(f.cFFi(k));
      }
      s.flags = f.cFlags();
      faces_.push_back(s);
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
  explicit InputFaces(const MeshType &m) {
    triples_.reserve(m.face.size());
    const auto index = [&](const typename MeshType::VertexType *v) {
      return std::uint32_t(vcg::tri::Index(m, v));
    };
    for (const auto &f : m.face)
      triples_.push_back({index(f.cV(0)), index(f.cV(1)), index(f.cV(2))});
  }

  /// Each input face's three vertices.
  const std::vector<std::array<std::uint32_t, 3>> &faceVertices() const { return triples_; }

  /// Gives back its input face to every split face whose vertices all rest
  /// and whose children are as the split made them, when every split face
  /// sharing one of its inserted vertices can be given back too; deletes the
  /// children and the inserted vertices (flags: compact, then rebuild FF
  /// adjacency). \return the number of faces given back.
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
    const auto childAt = [&](std::size_t k, std::size_t c) -> const typename MeshType::FaceType & {
      return c == 0 ? m.face[plan.faces[k].face] : m.face[firstAppended[k] + c - 1];
    };
    std::vector<char> back(count, 0);
    std::vector<std::vector<std::uint32_t>> facesOf(plan.inserted.size());
    for (std::size_t k = 0; k < count; ++k) {
      bool ok = true;
      for (std::size_t v : insertedOf(k)) {
        facesOf[v - n0].push_back(std::uint32_t(k));
        ok = ok && !m.vert[v].IsD() && !moves.isMoved(v);
      }
      for (std::uint32_t v : triples_[plan.faces[k].face]) ok = ok && !moves.isMoved(v);
      for (std::size_t c = 0; ok && c < children[k].size(); ++c) {
        const auto &f = childAt(k, c);
        ok = !f.IsD();
        for (int j = 0; ok && j < 3; ++j) ok = vcg::tri::Index(m, f.cV(j)) == children[k][c][j];
      }
      back[k] = ok;
    }
    // A vertex on an edge between two split faces goes only with both.
    for (bool changed = true; changed;) {
      changed = false;
      for (const auto &faces : facesOf) {
        bool all = true;
        for (std::uint32_t k : faces) all = all && back[k];
        if (all) continue;
        for (std::uint32_t k : faces) changed |= back[k] != 0, back[k] = 0;
      }
    }
    std::size_t given = 0;
    for (std::size_t k = 0; k < count; ++k) {
      if (!back[k]) continue;
      ++given;
      auto &parent = m.face[plan.faces[k].face];
      for (int j = 0; j < 3; ++j) parent.V(j) = &m.vert[triples_[plan.faces[k].face][j]];
      for (std::size_t c = 1; c < children[k].size(); ++c)
        vcg::tri::Allocator<MeshType>::DeleteFace(m, m.face[firstAppended[k] + c - 1]);
      for (std::size_t v : insertedOf(k))
        if (!m.vert[v].IsD()) vcg::tri::Allocator<MeshType>::DeleteVertex(m, m.vert[v]);
    }
    return given;
  }

 private:
  std::vector<std::array<std::uint32_t, 3>> triples_;
};

}  // namespace edge_sharpener
