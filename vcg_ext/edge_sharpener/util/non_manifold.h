// Non-manifold spots, held as they came: at a non-manifold vertex or edge the
// fans of faces are cut loose from each other (each fan gets its own copy of
// the vertex, at the same position) so that the pipelines see a 2-manifold
// mesh there; those faces are held (never split, their vertices never
// moved); afterwards every copy is welded back onto its vertex, so the output
// keeps the input's non-manifold vertices and edges exactly.
#pragma once

#include <vcg/complex/complex.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "../report.h"
#include "attributes.h"
#include "disjoint_sets.h"
#include "fast_topology.h"

namespace edge_sharpener {

/// The faces a run leaves exactly as they came, and their vertices, by index
/// at the start of the run (empty: nothing held); and the faces outside the
/// user's selection (SharpenOptions::selectedFacesOnly; empty: no selection),
/// which the auto method reads per feature, and the other methods hold.
struct HeldFaces {
  std::vector<char> face;        ///< per face
  std::vector<char> vertex;      ///< per vertex: a vertex of a held face
  std::vector<char> unselected;  ///< per face: outside the selection
  bool holds(std::size_t f) const { return f < face.size() && face[f]; }
  bool pins(std::size_t v) const { return v < vertex.size() && vertex[v]; }
  bool empty() const { return face.empty(); }
  bool outsideSelection(std::size_t f) const { return f < unselected.size() && unselected[f]; }
};

namespace detail {

/// Whether face f's edge e is shared by exactly two faces (its FF ring, as
/// buildFaceFace links it, has two members).
template <class FaceType>
bool twoFaceEdge(FaceType *f, int e) {
  FaceType *g = f->FFp(e);
  return g != f && g->FFp(f->FFi(e)) == f;
}

/// Per vertex: whether it is non-manifold (on an edge of three or more
/// faces, or its faces not joined into one fan by two-face edges).
/// \pre FF topology built by buildFaceFace(). Counts the edges of three or
/// more faces into `nonManifoldEdges`; `cornerFan` gets each face corner's
/// fan (corners of one vertex in one fan share it).
template <class MeshType>
std::vector<char> nonManifoldVertices(MeshType &m, std::size_t &nonManifoldEdges,
                                      std::vector<std::uint32_t> &cornerFan) {
  const std::size_t nf = m.face.size(), nv = m.vert.size();
  std::vector<char> bad(nv, 0);
  DisjointSets corners(3 * nf);  // face corners: 3 * face + corner
  nonManifoldEdges = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    auto *face = &m.face[f];
    for (int e = 0; e < 3; ++e) {
      const std::size_t a = vcg::tri::Index(m, face->V(e)),
                        b = vcg::tri::Index(m, face->V((e + 1) % 3));
      auto *g = face->FFp(e);
      if (g == face) continue;  // border
      if (!twoFaceEdge(face, e)) {
        bad[a] = bad[b] = 1;
        // Each ring of faces is counted once, at its lowest face edge.
        bool lowest = true;
        auto *h = g;
        int he = face->FFi(e);
        for (int guard = 0; h != face && guard < 1 << 20; ++guard) {
          if (h < face) lowest = false;
          auto *next = h->FFp(he);
          he = h->FFi(he);
          h = next;
        }
        nonManifoldEdges += lowest;
        continue;
      }
      const std::size_t gi = vcg::tri::Index(m, g);
      const int ge = face->FFi(e);
      // Corner of a in f joins the corner of a in g, likewise b.
      const int ga = g->V(ge) == face->V(e) ? ge : (ge + 1) % 3;
      const int gb = g->V(ge) == face->V(e) ? (ge + 1) % 3 : ge;
      corners.join(std::uint32_t(3 * f + e), std::uint32_t(3 * gi + ga));
      corners.join(std::uint32_t(3 * f + (e + 1) % 3), std::uint32_t(3 * gi + gb));
    }
  }
  constexpr std::uint32_t kNone = 0xffffffffu;
  std::vector<std::uint32_t> fan(nv, kNone);
  cornerFan.resize(3 * nf);
  for (std::size_t f = 0; f < nf; ++f)
    for (int i = 0; i < 3; ++i) {
      const std::size_t v = vcg::tri::Index(m, m.face[f].V(i));
      const std::uint32_t root = cornerFan[3 * f + i] = corners.find(std::uint32_t(3 * f + i));
      if (fan[v] == kNone)
        fan[v] = root;
      else if (fan[v] != root)
        bad[v] = 1;
    }
  return bad;
}

}  // namespace detail

/// Cuts the non-manifold spots of `m` loose in place (see the top of the
/// file) and welds them back. Each fan of faces at a non-manifold vertex
/// gets its own copy of it; two faces of one fan can meet on a cut edge
/// again, so it repeats until no vertex is non-manifold.
template <class MeshType>
class NonManifoldCut {
 public:
  /// \pre m compact, FF enabled, no face repeating a vertex.
  explicit NonManifoldCut(MeshType &m) : m_(m), weldTo_(m, 0) {
    std::vector<char> held(m.face.size(), 0);
    for (int round = 0; round < kMaxRounds; ++round) {
      buildFaceFace(m);
      std::size_t edges = 0;
      std::vector<std::uint32_t> cornerFan;
      const std::vector<char> bad = detail::nonManifoldVertices(m, edges, cornerFan);
      std::size_t count = 0;
      for (char b : bad) count += b != 0;
      if (round == 0) {
        stats_.edges = edges;
        stats_.vertices = count;
      }
      if (count == 0) {
        manifold_ = true;
        break;
      }
      splitFans(bad, cornerFan, held);
    }
    if (stats_.vertices == 0) return;
    held_.face = held;
    held_.vertex.assign(m.vert.size(), 0);
    for (std::size_t f = 0; f < held.size(); ++f) {
      if (!held[f]) continue;
      if (stats_.heldFaces++ == 0) stats_.firstHeldFace = f;
      for (int i = 0; i < 3; ++i) held_.vertex[vcg::tri::Index(m, m.face[f].V(i))] = 1;
    }
    pinnedPosition_.resize(m.vert.size());
    for (std::size_t v = 0; v < m.vert.size(); ++v) pinnedPosition_[v] = m.vert[v].cP();
  }

  /// Whether the cut left a 2-manifold mesh (false: spots too tangled).
  bool manifold() const { return manifold_; }
  const NonManifoldStats &stats() const { return stats_; }
  const HeldFaces &held() const { return held_; }

  /// Every held vertex back at its input position, every copy welded onto
  /// its vertex and removed; FF topology rebuilt. Vertices after the copies
  /// (inserted by the run) move down, in order.
  void weld() {
    if (held_.empty()) return;
    for (std::size_t v = 0; v < pinnedPosition_.size() && v < m_.vert.size(); ++v)
      if (held_.vertex[v] && !m_.vert[v].IsD()) m_.vert[v].P() = pinnedPosition_[v];
    for (auto &f : m_.face) {
      if (f.IsD()) continue;
      for (int i = 0; i < 3; ++i) {
        const int to = weldTo_[f.V(i)];
        if (to > 0) f.V(i) = &m_.vert[std::size_t(to - 1)];
      }
    }
    for (std::size_t v = 0; v < m_.vert.size(); ++v)
      if (weldTo_[v] > 0 && !m_.vert[v].IsD())
        vcg::tri::Allocator<MeshType>::DeleteVertex(m_, m_.vert[v]);
    vcg::tri::Allocator<MeshType>::CompactVertexVector(m_);
    buildFaceFace(m_);
  }

 private:
  static constexpr int kMaxRounds = 8;

  /// Gives every fan of a bad vertex but its first its own copy of it (a
  /// fan: the faces joined around it by two-face edges); its faces are held.
  void splitFans(const std::vector<char> &bad, const std::vector<std::uint32_t> &cornerFan,
                 std::vector<char> &held) {
    // Per bad vertex, its fans in order of first corner: the first keeps it.
    std::vector<std::vector<std::uint32_t>> fans(m_.vert.size());
    std::size_t copies = 0;
    for (std::size_t fi = 0; fi < m_.face.size(); ++fi)
      for (int i = 0; i < 3; ++i) {
        const std::size_t v = vcg::tri::Index(m_, m_.face[fi].V(i));
        if (!bad[v]) continue;
        auto &list = fans[v];
        const std::uint32_t fan = cornerFan[3 * fi + i];
        if (std::find(list.begin(), list.end(), fan) != list.end()) continue;
        list.push_back(fan);
        copies += list.size() > 1;
      }
    const std::size_t first = m_.vert.size();
    // Adding may move the vertex array: vcglib re-points the faces.
    vcg::tri::Allocator<MeshType>::AddVertices(m_, copies);
    std::vector<std::size_t> firstCopy(first, 0);
    for (std::size_t v = 0, next = first; v < first; ++v) {
      if (fans[v].size() < 2) continue;
      firstCopy[v] = next;
      for (std::size_t k = 1; k < fans[v].size(); ++k, ++next) {
        m_.vert[next].ImportData(m_.vert[v]);
        weldTo_[next] = weldTo_[v] > 0 ? weldTo_[v] : int(v) + 1;
      }
    }
    for (std::size_t fi = 0; fi < m_.face.size(); ++fi) {
      auto &f = m_.face[fi];
      for (int i = 0; i < 3; ++i) {
        const std::size_t v = vcg::tri::Index(m_, f.V(i));
        if (v >= first || !bad[v]) continue;
        held[fi] = 1;
        const auto &list = fans[v];
        const std::size_t k =
            std::size_t(std::find(list.begin(), list.end(), cornerFan[3 * fi + i]) - list.begin());
        if (k > 0) f.V(i) = &m_.vert[firstCopy[v] + k - 1];
      }
    }
  }

  MeshType &m_;
  /// Per vertex: 1 + the index of the vertex a copy welds onto; 0 (what
  /// vcglib gives vertices added later) for every other vertex.
  ScopedVertexAttribute<MeshType, int> weldTo_;
  bool manifold_ = false;
  NonManifoldStats stats_;
  HeldFaces held_;
  std::vector<typename MeshType::CoordType> pinnedPosition_;
};

}  // namespace edge_sharpener
