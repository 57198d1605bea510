// Preconditions of Edge-Sharpener, checked before anything is modified.
#pragma once

#include <vcg/complex/complex.h>
#include <vcg/simplex/face/pos.h>
#include <vcg/simplex/face/topology.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "fast_topology.h"
#include "parallel.h"

namespace edge_sharpener {

namespace detail {

/// Number of vertices whose faces do not form a single fan (the count
/// vcg::tri::Clean::CountNonManifoldVertexFF returns on a mesh whose edges are
/// all manifold), without touching the vertex flags. Fans are walked in parallel.
/// \pre FF topology up to date; every edge has at most two faces.
template <class MeshType>
std::size_t countNonManifoldVertices(MeshType &m) {
  using FaceType = typename MeshType::FaceType;
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  const std::size_t nv = m.vert.size();
  if (nv == 0 || m.face.empty()) return 0;
  const auto *v0 = &m.vert[0];
  // Corners counted per contiguous range of faces (one per thread), with
  // the first corner of each vertex in each range; the lowest range that
  // has a vertex's corners holds its first corner.
  const std::int64_t nf = std::int64_t(m.face.size());
  const int ranges = nf > kParallelMin ? detail::maxThreads() : 1;
  std::vector<std::vector<std::uint32_t>> incident(ranges), firstCorner(ranges);
#pragma omp parallel for schedule(static, 1) num_threads(ranges)
  for (int t = 0; t < ranges; ++t) {
    incident[t].assign(nv, 0);
    firstCorner[t].assign(nv, kNone);
    for (std::int64_t f = nf * t / ranges; f < nf * (t + 1) / ranges; ++f) {
      if (m.face[f].IsD()) continue;
      for (int i = 0; i < 3; ++i) {
        const std::size_t v = std::size_t(m.face[f].cV(i) - v0);
        if (incident[t][v]++ == 0) firstCorner[t][v] = std::uint32_t(3 * f + i);
      }
    }
  }
  std::int64_t count = 0;
  const std::int64_t n = std::int64_t(nv);
#pragma omp parallel for schedule(static, 8192) reduction(+ : count) if (n > kParallelMin)
  for (std::int64_t v = 0; v < n; ++v) {
    std::uint32_t corner = kNone, faces = 0;
    for (int t = 0; t < ranges; ++t) {
      if (corner == kNone) corner = firstCorner[t][v];
      faces += incident[t][v];
    }
    if (corner == kNone) continue;
    vcg::face::Pos<FaceType> pos(&m.face[corner / 3], int(corner % 3));
    if (std::uint32_t(pos.NumberOfIncidentFaces()) != faces) ++count;
  }
  return std::size_t(count);
}

}  // namespace detail

/// Returns "" when `m` can be processed, else a one-line reason. Refuses:
/// no faces (empty or point cloud), non-finite coordinates, faces that repeat
/// a vertex, inconsistent orientation (of the faces that share an edge two by
/// two). Boundaries (open meshes), several components and non-manifold
/// vertices and edges are accepted (held as they came: util/non_manifold.h);
/// `nonManifold`, when given, tells whether there are any.
/// \pre m has FF adjacency and no deleted elements. Rebuilds FF topology
///      (fast_topology.h); leaves every flag as it was.
template <class MeshType>
std::string findInputProblem(MeshType &m, bool *nonManifold) {
  vcg::tri::RequireFFAdjacency(m);
  if (m.vn != int(m.vert.size()) || m.fn != int(m.face.size()))
    return "mesh has deleted elements; compact it first";
  if (m.fn == 0)
    return m.vn == 0 ? "mesh is empty" : "mesh has no faces (a point cloud cannot be sharpened)";
  // The first offending vertex and face are named (a min-reduction, the
  // same for any thread count).
  const std::int64_t nv = std::int64_t(m.vert.size());
  std::int64_t firstNonFinite = nv;
#pragma omp parallel for schedule(static, 8192) reduction(min \
                                                          : firstNonFinite) if (nv > kParallelMin)
  for (std::int64_t i = 0; i < nv; ++i) {
    const auto &p = m.vert[i].cP();
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      firstNonFinite = std::min(firstNonFinite, i);
  }
  if (firstNonFinite < nv)
    return "vertex " + std::to_string(firstNonFinite) + " has a NaN or infinite coordinate";
  const std::int64_t faceCount = std::int64_t(m.face.size());
  std::int64_t firstRepeat = faceCount;
#pragma omp parallel for schedule(static, 8192) \
    reduction(min                               \
              : firstRepeat) if (faceCount > kParallelMin)
  for (std::int64_t i = 0; i < faceCount; ++i) {
    const auto &f = m.face[i];
    if (f.cV(0) == f.cV(1) || f.cV(1) == f.cV(2) || f.cV(2) == f.cV(0))
      firstRepeat = std::min(firstRepeat, i);
  }
  if (firstRepeat < faceCount)
    return "face " + std::to_string(firstRepeat) +
           " repeats a vertex (remove duplicated vertices/faces first)";
  // An edge is manifold when its FF ring has at most two faces. The FF
  // build finds that and the orientation while it matches the edges. (Not
  // Clean::CountNonManifoldEdgeFF: it takes face bit flags it never returns,
  // which inside MeshLab are shared with every other filter.)
  const FaceFaceDiagnostics edges = buildFaceFace(m);
  const bool spots =
      edges.firstNonManifoldFace < m.face.size() || detail::countNonManifoldVertices(m) > 0;
  if (nonManifold) *nonManifold = spots;
  if (edges.misoriented) return "faces are not consistently oriented (re-orient the mesh first)";
  return "";
}

template <class MeshType>
std::string findInputProblem(MeshType &m) {
  return findInputProblem(m, nullptr);
}

}  // namespace edge_sharpener
