// Preconditions of Edge-Sharpener, checked before anything is modified.
#pragma once

#include <cmath>
#include <string>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/topology.h>

namespace edge_sharpener {

/// Returns "" when `m` can be processed, else a one-line reason. Refuses:
/// no faces (empty or point cloud), non-finite coordinates, faces that repeat
/// a vertex, non-manifold edges or vertices, inconsistent orientation.
/// Boundaries (open meshes) and several components are accepted.
/// \pre m has FF adjacency and no deleted elements. Rebuilds FF topology and
///      uses the vertex/face "visited" flags.
template <class MeshType>
std::string findInputProblem(MeshType &m) {
  vcg::tri::RequireFFAdjacency(m);
  if (m.vn != int(m.vert.size()) || m.fn != int(m.face.size()))
    return "mesh has deleted elements; compact it first";
  if (m.fn == 0)
    return m.vn == 0 ? "mesh is empty" : "mesh has no faces (a point cloud cannot be sharpened)";
  for (std::size_t i = 0; i < m.vert.size(); ++i) {
    const auto &p = m.vert[i].cP();
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      return "vertex " + std::to_string(i) + " has a NaN or infinite coordinate";
  }
  for (std::size_t i = 0; i < m.face.size(); ++i) {
    const auto &f = m.face[i];
    if (f.cV(0) == f.cV(1) || f.cV(1) == f.cV(2) || f.cV(2) == f.cV(0))
      return "face " + std::to_string(i) + " repeats a vertex (remove duplicated vertices/faces first)";
  }
  vcg::tri::UpdateTopology<MeshType>::FaceFace(m);
  // An edge is manifold when its FF ring has at most two faces. (Not
  // Clean::CountNonManifoldEdgeFF: it takes face bit flags it never returns,
  // which inside MeshLab are shared with every other filter.)
  std::size_t nonManifoldFaceEdges = 0, firstFace = 0;
  for (std::size_t i = 0; i < m.face.size(); ++i)
    for (int j = 0; j < 3; ++j)
      if (!vcg::face::IsManifold(m.face[i], j) && nonManifoldFaceEdges++ == 0) firstFace = i;
  if (nonManifoldFaceEdges > 0)
    return "mesh has non-manifold edges (three or more faces on an edge, e.g. at face " +
           std::to_string(firstFace) + ")";
  if (int n = vcg::tri::Clean<MeshType>::CountNonManifoldVertexFF(m, false, false))
    return "mesh has " + std::to_string(n) + " non-manifold vertices";
  if (!vcg::tri::Clean<MeshType>::IsCoherentlyOrientedMesh(m))
    return "faces are not consistently oriented (re-orient the mesh first)";
  return "";
}

}  // namespace edge_sharpener
