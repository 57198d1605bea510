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

}  // namespace edge_sharpener
