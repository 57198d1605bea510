// The labels all stages read and write, held in scoped mesh attributes.
#pragma once

#include <array>

#include "attributes.h"
#include "geometry.h"
#include "labels.h"

namespace edge_sharpener {

using EdgeLabels3 = std::array<EdgeLabel, 3>;

template <class MeshType>
struct MeshLabels {
  explicit MeshLabels(MeshType &m)
      : face(m, FaceLabel::Gray),
        edge(m, EdgeLabels3{EdgeLabel::Gray, EdgeLabel::Gray, EdgeLabel::Gray}),
        normal(m, Vec3(0, 0, 0)),
        vertex(m, VertexLabel::Gray),
        placement(m, Placement::Original) {}

  ScopedFaceAttribute<MeshType, FaceLabel> face;
  /// Label of edge i (from V(i) to V(i+1)) of each face; equal on both sides.
  ScopedFaceAttribute<MeshType, EdgeLabels3> edge;
  /// Unit face normal in double precision; zero for a zero-area face.
  ScopedFaceAttribute<MeshType, Vec3> normal;
  ScopedVertexAttribute<MeshType, VertexLabel> vertex;
  /// Outcome for inserted vertices; Placement::Original for the others.
  ScopedVertexAttribute<MeshType, Placement> placement;

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
