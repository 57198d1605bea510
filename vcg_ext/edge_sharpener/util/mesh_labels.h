// The labels all stages read and write, held in scoped mesh attributes.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "../labels.h"
#include "attributes.h"
#include "fast_topology.h"
#include "geometry.h"

namespace edge_sharpener {

using EdgeLabels3 = std::array<EdgeLabel, 3>;

/// Unit normal of face f in double precision from its current vertex
/// positions; zero for a zero-area (or non-finite) face, so that its edges
/// can never be smooth. A pure function of the three positions: the same
/// bits wherever and however often it is evaluated.
template <class FaceType>
inline Vec3 faceUnitNormal(const FaceType &f) {
  const Vec3 p0 = positionOf(f.cV(0)), p1 = positionOf(f.cV(1)), p2 = positionOf(f.cV(2));
  const Vec3 n = (p1 - p0) ^ (p2 - p0);
  const double scale =
      std::max({(p1 - p0).SquaredNorm(), (p2 - p1).SquaredNorm(), (p0 - p2).SquaredNorm()});
  const double len = n.Norm();
  // A relative test: |n| / longest^2 is about the sine of the smallest angle.
  if (!(len > 1e-12 * scale) || !std::isfinite(len)) return Vec3(0, 0, 0);
  return n / len;
}

/// Unit face normals (faceUnitNormal): stored while detection reads them
/// for every edge (fill() to release()), evaluated on demand otherwise - the
/// same bits either way. A double normal per face is 24 bytes a face, the
/// largest array of the labels, so it is held only as long as it pays.
template <class MeshType>
class FaceNormals {
 public:
  using FaceType = typename MeshType::FaceType;
  explicit FaceNormals(const MeshType &m) : m_(m) {}

  Vec3 operator[](const FaceType *f) const {
    if (const Vec3 *n = stored()) return n[f - base_];
    return faceUnitNormal(*f);
  }
  /// The stored normals, indexed like m.face, while they are valid; else null.
  const Vec3 *stored() const {
    return !stored_.empty() && m_.face.data() == base_ && m_.face.size() == stored_.size()
               ? stored_.data()
               : nullptr;
  }
  /// Stores the normal of every face (in parallel where that pays).
  /// \return the number of zero-area faces (zero normal).
  std::size_t fill();
  void release() { std::vector<Vec3>().swap(stored_); }

 private:
  const MeshType &m_;
  const FaceType *base_ = nullptr;
  std::vector<Vec3> stored_;
};

template <class MeshType>
std::size_t FaceNormals<MeshType>::fill() {
  const std::int64_t nf = std::int64_t(m_.face.size());
  stored_.resize(std::size_t(nf));  // Vec3's constructor leaves it unset: written below
  base_ = m_.face.data();
  std::int64_t degenerate = 0;
#pragma omp parallel for schedule(static, 4096) reduction(+ : degenerate) if (nf > kParallelMin)
  for (std::int64_t fi = 0; fi < nf; ++fi) {
    const FaceType &f = m_.face[fi];
    stored_[fi] = f.IsD() ? Vec3(0, 0, 0) : faceUnitNormal(f);
    if (f.IsD()) continue;
    if (stored_[fi].SquaredNorm() == 0) ++degenerate;
  }
  return std::size_t(degenerate);
}

template <class MeshType>
struct MeshLabels {
  explicit MeshLabels(MeshType &m)
      : face(m, FaceLabel::Gray),
        edge(m, EdgeLabels3{EdgeLabel::Gray, EdgeLabel::Gray, EdgeLabel::Gray}),
        normal(m),
        vertex(m, VertexLabel::Gray),
        placement(m, Placement::Original),
        bentFlank(m, 0) {}

  ScopedFaceAttribute<MeshType, FaceLabel> face;
  /// Label of edge i (from V(i) to V(i+1)) of each face; equal on both sides.
  ScopedFaceAttribute<MeshType, EdgeLabels3> edge;
  /// Unit face normal in double precision; zero for a zero-area face.
  FaceNormals<MeshType> normal;
  ScopedVertexAttribute<MeshType, VertexLabel> vertex;
  /// Outcome for inserted vertices; Placement::Original for the others.
  ScopedVertexAttribute<MeshType, Placement> placement;
  /// Inserted vertices placed although a flank bends away before their
  /// target (auto method, placement.h: veto::flankBendsAway): they move only
  /// with a feature whose evidence is strong, and count as refused in it.
  ScopedVertexAttribute<MeshType, char> bentFlank;

  /// Sets the label of edge i of f and of its twin on the adjacent face.
  void setEdge(typename MeshType::FaceType *f, int i, EdgeLabel label) {
    edge[f][i] = label;
    typename MeshType::FaceType *g = f->FFp(i);
    if (g != f) edge[g][f->FFi(i)] = label;
  }
};

/// Visits every undirected edge once as (face, edge index, is boundary).
template <class MeshType, class Visit>
void forEachEdge(MeshType &m, Visit &&visit) {
  for (auto &f : m.face) {
    if (f.IsD()) continue;
    for (int i = 0; i < 3; ++i) {
      auto *g = f.FFp(i);
      if (g == &f)
        visit(&f, i, true);
      else if (&f < g)
        visit(&f, i, false);
    }
  }
}

}  // namespace edge_sharpener
