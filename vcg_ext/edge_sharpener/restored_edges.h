// The sharp edges a sharpening restored, for callers that shade, select or
// write them (Blender's Mark Sharp, the Python report, the CLI's --sharp-edges
// file): the output vertices moved onto a sharp edge or corner, and the output
// edges joining two of them (the restored feature lines; an inserted vertex
// joins the next one along its feature and a corner's vertex the features
// running into it).
#pragma once

#include <vcg/complex/complex.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "util/mesh_labels.h"

namespace edge_sharpener {

/// The per-vertex attribute (std::uint8_t) sharpen() fills when the caller
/// has added it: 1 on each output vertex placed on a sharp edge or corner,
/// else 0. Without it nothing is recorded. The caller deletes it
/// (Allocator::DeletePerVertexAttribute): vcglib's mesh does not.
inline constexpr const char *kRestoredVertexAttribute = "edge_sharpener_restored";

namespace detail {

/// Writes Placement::Moved into the caller's kRestoredVertexAttribute, if
/// present. \pre the labels are final (after every guard).
template <class MeshType>
void recordRestoredVertices(MeshType &m, const MeshLabels<MeshType> &labels) {
  using Allocator = vcg::tri::Allocator<MeshType>;
  if (!vcg::tri::HasPerVertexAttribute(m, kRestoredVertexAttribute)) return;
  auto restored =
      Allocator::template FindPerVertexAttribute<std::uint8_t>(m, kRestoredVertexAttribute);
  if (!Allocator::IsValidHandle(m, restored)) return;  // another type under that name
  for (auto &v : m.vert)
    if (!v.IsD()) restored[v] = labels.placement[&v] == Placement::Moved;
}

}  // namespace detail

/// The edges of `m` whose two vertices are both restored (`restored`, per
/// vertex index, as in kRestoredVertexAttribute): vertex index pairs, lower
/// index first, sorted, each once. \pre m is compact.
template <class MeshType, class Flags>
std::vector<std::array<std::uint32_t, 2>> restoredEdges(const MeshType &m, const Flags &restored) {
  std::vector<std::array<std::uint32_t, 2>> edges;
  for (const auto &f : m.face) {
    if (f.IsD()) continue;
    for (int i = 0; i < 3; ++i) {
      const auto a = std::uint32_t(vcg::tri::Index(m, f.cV(i)));
      const auto b = std::uint32_t(vcg::tri::Index(m, f.cV((i + 1) % 3)));
      if (restored[a] && restored[b]) edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace edge_sharpener
