// Stage 2: the six colouring filters of Edge-Sharpener (paper, section 3).
// Each filter reads and writes labels only; together they turn the smooth
// ("brown") edges into smooth regions (red), chamfer edges (blue) and corner
// triangles (green).
#pragma once

#include <cstdint>
#include <vector>

#include "report.h"
#include "util/fast_topology.h"
#include "util/mesh_labels.h"

namespace edge_sharpener {

/// Filter 1: paint red each vertex whose incident edges are all smooth.
/// Walks faces rather than vertex stars, so it needs no vertex adjacency and
/// is robust on boundaries (a boundary edge is never smooth).
/// \return the number of red vertices.
template <class MeshType>
std::size_t paintInteriorRedVertices(MeshType &m, MeshLabels<MeshType> &labels) {
  std::vector<char> referenced(m.vert.size(), 0), allSmooth(m.vert.size(), 1);
  for (auto &f : m.face) {
    if (f.IsD()) continue;
    for (int i = 0; i < 3; ++i) {
      const auto vi = vcg::tri::Index(m, f.cV(i));
      referenced[vi] = 1;
      if (labels.edge[&f][i] != EdgeLabel::Smooth) {
        allSmooth[vi] = 0;
        allSmooth[vcg::tri::Index(m, f.cV((i + 1) % 3))] = 0;
      }
    }
  }
  std::size_t count = 0;
  for (std::size_t v = 0; v < m.vert.size(); ++v) {
    if (referenced[v] && allSmooth[v]) {
      labels.vertex[v] = VertexLabel::Red;
      ++count;
    }
  }
  return count;
}

/// Filter 2: paint red each triangle that has at least one red vertex.
/// \return the number of these core red faces.
template <class MeshType>
std::size_t paintCoreRedFaces(MeshType &m, MeshLabels<MeshType> &labels) {
  std::int64_t count = 0;
  const std::int64_t nf = std::int64_t(m.face.size());
#pragma omp parallel for schedule(static, 4096) reduction(+ : count) if (nf > kParallelMin)
  for (std::int64_t fi = 0; fi < nf; ++fi) {
    auto &f = m.face[fi];
    if (f.IsD()) continue;
    for (int i = 0; i < 3; ++i) {
      if (labels.vertex[f.cV(i)] == VertexLabel::Red) {
        labels.face[&f] = FaceLabel::Red;
        ++count;
        break;
      }
    }
  }
  return std::size_t(count);
}

/// Filter 3: paint red, recursively, each triangle adjacent to a red triangle
/// through a smooth edge (a breadth-first flood over FF adjacency).
/// \return the total number of red faces afterwards.
template <class MeshType>
std::size_t growRedFaces(MeshType &m, MeshLabels<MeshType> &labels) {
  using FacePointer = typename MeshType::FacePointer;
  // The flood reaches the same faces from any order; only red faces with a
  // smooth edge to a non-red face can spread, so only they start it.
  std::vector<FacePointer> frontier;
  std::size_t count = 0;
  for (auto &f : m.face) {
    if (f.IsD() || labels.face[&f] != FaceLabel::Red) continue;
    ++count;
    for (int i = 0; i < 3; ++i) {
      FacePointer g = f.FFp(i);
      if (g != &f && labels.edge[&f][i] == EdgeLabel::Smooth && labels.face[g] != FaceLabel::Red) {
        frontier.push_back(&f);
        break;
      }
    }
  }
  while (!frontier.empty()) {
    FacePointer f = frontier.back();
    frontier.pop_back();
    for (int i = 0; i < 3; ++i) {
      FacePointer g = f->FFp(i);
      if (g == f || labels.edge[f][i] != EdgeLabel::Smooth) continue;
      if (labels.face[g] == FaceLabel::Red) continue;
      labels.face[g] = FaceLabel::Red;
      ++count;
      frontier.push_back(g);
    }
  }
  return count;
}

/// Filter 4: paint red the edges and vertices of the red triangles.
/// \return {red vertices, red edges} (undirected).
template <class MeshType>
std::pair<std::size_t, std::size_t> paintRedBoundaries(MeshType &m, MeshLabels<MeshType> &labels) {
  for (auto &f : m.face) {
    if (f.IsD() || labels.face[&f] != FaceLabel::Red) continue;
    for (int i = 0; i < 3; ++i) {
      labels.setEdge(&f, i, EdgeLabel::Red);
      labels.vertex[f.cV(i)] = VertexLabel::Red;
    }
  }
  std::size_t vertices = 0, edges = 0;
  for (std::size_t v = 0; v < m.vert.size(); ++v)
    if (labels.vertex[v] == VertexLabel::Red) ++vertices;
  forEachEdge(m, [&](auto *f, int i, bool) {
    if (labels.edge[f][i] == EdgeLabel::Red) ++edges;
  });
  return {vertices, edges};
}

/// Filter 5: paint blue (chamfer) each non-red edge joining two red vertices.
/// A boundary edge can be one too (an open scan cut across a chamfer): its
/// vertex then moves along the crease to the rim.
/// \return the number of chamfer edges.
template <class MeshType>
std::size_t paintChamferEdges(MeshType &m, MeshLabels<MeshType> &labels) {
  std::size_t count = 0;
  forEachEdge(m, [&](auto *f, int i, bool) {
    if (labels.edge[f][i] == EdgeLabel::Red) return;
    if (labels.vertex[f->cV(i)] == VertexLabel::Red &&
        labels.vertex[f->cV((i + 1) % 3)] == VertexLabel::Red) {
      labels.setEdge(f, i, EdgeLabel::Chamfer);
      ++count;
    }
  });
  return count;
}

/// Filter 6: paint green (corner) each triangle with three chamfer edges;
/// the non-red triangles with one or two chamfer edges are chamfer triangles.
/// \return {corner faces, chamfer faces}.
template <class MeshType>
std::pair<std::size_t, std::size_t> paintCornerAndChamferFaces(MeshType &m,
                                                               MeshLabels<MeshType> &labels) {
  std::int64_t corners = 0, chamfers = 0;
  const std::int64_t nf = std::int64_t(m.face.size());
#pragma omp parallel for schedule(static, 4096) reduction(+ : corners, chamfers) \
    if (nf > kParallelMin)
  for (std::int64_t fi = 0; fi < nf; ++fi) {
    auto &f = m.face[fi];
    if (f.IsD()) continue;
    int blue = 0;
    for (int i = 0; i < 3; ++i) blue += labels.edge[&f][i] == EdgeLabel::Chamfer;
    if (blue == 3) {
      labels.face[&f] = FaceLabel::Corner;
      ++corners;
    } else if (blue > 0) {
      labels.face[&f] = FaceLabel::Chamfer;
      ++chamfers;
    }
  }
  return {std::size_t(corners), std::size_t(chamfers)};
}

/// Runs the six filters in order.
/// \pre labelSmoothEdges() ran.
template <class MeshType>
FilterStats runSixFilters(MeshType &m, MeshLabels<MeshType> &labels) {
  FilterStats s;
  s.interiorRedVertices = paintInteriorRedVertices(m, labels);
  s.coreRedFaces = paintCoreRedFaces(m, labels);
  s.redFaces = growRedFaces(m, labels);
  std::tie(s.redVertices, s.redEdges) = paintRedBoundaries(m, labels);
  s.chamferEdges = paintChamferEdges(m, labels);
  std::tie(s.cornerFaces, s.chamferFaces) = paintCornerAndChamferFaces(m, labels);
  return s;
}

}  // namespace edge_sharpener
