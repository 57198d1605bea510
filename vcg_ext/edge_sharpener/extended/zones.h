// The extended method's shared state: which smooth region each face belongs
// to, and the label and plane of each vertex (feature_zones.h: the stages).
#pragma once

#include <vcg/complex/complex.h>

#include <cstdint>
#include <vector>
// (vcglib's algorithm headers, included below, need complex.h first)

#include "../placement.h"
#include "../util/geometry.h"
#include "../util/vertex_faces.h"

namespace edge_sharpener {

constexpr int kZone = -1;    ///< face or vertex outside every smooth region
constexpr int kCrease = -2;  ///< vertex shared by two or more regions: already sharp

/// Per-face region and per-vertex label of the extended method.
struct FeatureZones {
  std::vector<int> faceRegion;   ///< region id, or kZone
  std::vector<int> vertexLabel;  ///< region id, kZone (unlabelled) or kCrease
  std::vector<char> inRegion;    ///< 1: a vertex of some region's face (never moves)
  SupportPlanes support;         ///< plane of the label's region near the vertex
  VertexFaceTable inputFaces;    ///< faces of each vertex, as detection saw them
};

namespace detail {

/// Neighbouring vertices of v (through its faces), with repetitions.
template <class MeshType, class Visit>
void forEachNeighbour(const MeshType &m, const VertexFaceTable &vf, std::size_t v, Visit &&visit) {
  for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v); ++fi)
    for (int k = 0; k < 3; ++k) {
      const std::size_t u = vcg::tri::Index(m, m.face[*fi].cV(k));
      if (u != v) visit(u);
    }
}

}  // namespace detail

}  // namespace edge_sharpener
