// Faces held as they came (the faces at a non-manifold spot): after
// detection their chamfer labels are cleared, so no split touches them; after
// placement their vertices go back to rest, so no move does.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "guards/vertex_moves.h"
#include "labels.h"
#include "report.h"
#include "util/mesh_labels.h"
#include "util/non_manifold.h"

namespace edge_sharpener {

/// Stage after detection: no held face is split. A held face loses its
/// chamfer or corner label and its chamfer edges (on both sides); a
/// neighbour that lost a chamfer edge is labelled again by the chamfer edges
/// it keeps (none: not split; three: a corner). The detection's counts in
/// `filters` follow (the report then counts what will be split and what
/// Detect selects).
template <class MeshType>
void holdFaces(MeshType &m, MeshLabels<MeshType> &labels, const HeldFaces &held,
               FilterStats &filters) {
  if (held.empty()) return;
  std::size_t cleared = 0;
  std::vector<typename MeshType::FacePointer> touched;
  for (std::size_t fi = 0; fi < m.face.size(); ++fi) {
    if (!held.holds(fi)) continue;
    auto *f = &m.face[fi];
    labels.face[f] = FaceLabel::Gray;
    for (int i = 0; i < 3; ++i) {
      if (labels.edge[f][i] != EdgeLabel::Chamfer) continue;
      auto *g = f->FFp(i);
      labels.edge[f][i] = EdgeLabel::Gray;
      labels.edge[g][f->FFi(i)] = EdgeLabel::Gray;
      ++cleared;
      if (g != f) touched.push_back(g);
    }
  }
  for (auto *g : touched) {
    const FaceLabel label = labels.face[g];
    if (held.holds(vcg::tri::Index(m, g)) ||
        (label != FaceLabel::Chamfer && label != FaceLabel::Corner))
      continue;
    int chamferEdges = 0;
    for (int i = 0; i < 3; ++i) chamferEdges += labels.edge[g][i] == EdgeLabel::Chamfer;
    labels.face[g] = chamferEdges == 0   ? FaceLabel::Gray
                     : chamferEdges == 3 ? FaceLabel::Corner
                                         : FaceLabel::Chamfer;
  }
  filters.chamferEdges -= std::min(filters.chamferEdges, cleared);
  filters.chamferFaces = filters.cornerFaces = 0;
  for (auto &f : m.face) {
    filters.chamferFaces += labels.face[&f] == FaceLabel::Chamfer;
    filters.cornerFaces += labels.face[&f] == FaceLabel::Corner;
  }
}

/// Stage after placement: every vertex of a held face that placement moved
/// goes back to rest.
template <class MeshType>
void sendBackHeldVertices(VertexMoves<MeshType> &moves, const HeldFaces &held) {
  for (std::size_t v = 0; v < held.vertex.size() && v < moves.firstInserted(); ++v)
    if (held.pins(v) && moves.hasRest(v) && moves.isMoved(v))
      moves.sendBack(v, Placement::Original);
}

}  // namespace edge_sharpener
