// Stages 3 and 4: the split plan (which edges and faces receive a new vertex)
// and the subdivision that carries it out (paper, Figure 4).
#pragma once

#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/complex.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "report.h"
#include "util/fast_topology.h"
#include "util/mesh_labels.h"

namespace edge_sharpener {

/// Where an inserted vertex comes from: the original vertices whose support
/// planes place it (2 for a chamfer-edge vertex, 3 for a corner vertex) and
/// its unmoved ("rest") position, the midpoint or the centroid.
struct InsertedVertexSource {
  std::array<std::size_t, 3> original{};
  int originalCount = 0;
  Vec3 rest{0, 0, 0};
  /// A chamfer-edge vertex: the sum of the unit normals of the edge's two
  /// faces, whose direction is its chamfer's normal (lineAngleToSurface reads
  /// only the direction). Zero for a corner vertex.
  Vec3 chamferNormal{0, 0, 0};
};

/// One chamfer or corner face and the inserted vertices on it, as indices
/// into SplitPlan::inserted (-1: none).
struct SplitFace {
  std::size_t face = 0;
  std::array<int, 3> edgeVertex{-1, -1, -1};
  int centerVertex = -1;
  /// Two-chamfer-edge faces only: the quad left after cutting the apex is
  /// split along the diagonal from the free edge's first vertex (0) or second (1).
  int diagonal = 0;
};

struct SplitPlan {
  std::size_t originalVertexCount = 0;  ///< inserted vertex k gets index originalVertexCount + k
  std::vector<InsertedVertexSource> inserted;
  std::vector<SplitFace> faces;
};

/// Stage 3: one new vertex in the middle of every chamfer edge (shared by
/// both faces of the edge) and of every corner triangle; never on an edge
/// between a chamfer and a non-chamfer triangle (such an edge is red or gray).
/// \pre runSixFilters() ran; FF topology up to date; the mesh is compact.
template <class MeshType>
SplitPlan planSplits(MeshType &m, MeshLabels<MeshType> &labels) {
  SplitPlan plan;
  plan.originalVertexCount = m.vert.size();
  ScopedFaceAttribute<MeshType, int> splitIndex(m, -1);
  for (auto &f : m.face) {
    const FaceLabel label = labels.face[&f];
    if (f.IsD() || (label != FaceLabel::Chamfer && label != FaceLabel::Corner)) continue;
    splitIndex[&f] = int(plan.faces.size());
    plan.faces.push_back(SplitFace{vcg::tri::Index(m, &f)});
  }
  const auto addVertex = [&](std::initializer_list<const typename MeshType::VertexType *> vs) {
    InsertedVertexSource s;
    Vec3 sum(0, 0, 0);
    for (auto *v : vs) {
      s.original[s.originalCount++] = vcg::tri::Index(m, v);
      sum += positionOf(v);
    }
    s.rest = sum / double(s.originalCount);
    plan.inserted.push_back(s);
    return int(plan.inserted.size() - 1);
  };
  for (std::size_t k = 0; k < plan.faces.size(); ++k) {
    SplitFace &sf = plan.faces[k];
    auto *f = &m.face[sf.face];
    for (int i = 0; i < 3; ++i) {
      if (labels.edge[f][i] != EdgeLabel::Chamfer) continue;
      auto *g = f->FFp(i);
      const int twin = splitIndex[g];
      // The face listed first creates the shared vertex; the other reuses it.
      if (twin >= 0 && std::size_t(twin) < k)
        sf.edgeVertex[i] = plan.faces[twin].edgeVertex[f->FFi(i)];
      else {
        sf.edgeVertex[i] = addVertex({f->cV(i), f->cV((i + 1) % 3)});
        plan.inserted.back().chamferNormal = labels.normal[f] + labels.normal[g];
      }
    }
    if (labels.face[f] == FaceLabel::Corner) {
      sf.centerVertex = addVertex({f->cV(0), f->cV(1), f->cV(2)});
    } else {
      const int free = sf.edgeVertex[0] < 0 ? 0 : sf.edgeVertex[1] < 0 ? 1 : 2;
      if (sf.edgeVertex[(free + 1) % 3] >= 0 && sf.edgeVertex[(free + 2) % 3] >= 0) {
        // Free edge a-b, apex c; m1 on b-c, m2 on c-a. Shorter diagonal wins.
        const Vec3 a = positionOf(f->cV(free)), b = positionOf(f->cV((free + 1) % 3));
        const Vec3 m1 = plan.inserted[sf.edgeVertex[(free + 1) % 3]].rest;
        const Vec3 m2 = plan.inserted[sf.edgeVertex[(free + 2) % 3]].rest;
        sf.diagonal = (a - m1).SquaredNorm() <= (b - m2).SquaredNorm() ? 0 : 1;
      }
    }
  }
  return plan;
}

namespace detail {

/// The child triangles of one split face as vertex indices, first child
/// first; orientation follows the parent.
inline std::vector<std::array<std::size_t, 3>> childTriangles(const SplitFace &sf,
                                                              const std::array<std::size_t, 3> &v,
                                                              std::size_t firstInserted) {
  const auto ins = [&](int k) { return firstInserted + std::size_t(k); };
  std::vector<std::array<std::size_t, 3>> out;
  if (sf.centerVertex >= 0) {  // corner: fan of six around the centre
    const std::size_t c = ins(sf.centerVertex);
    for (int i = 0; i < 3; ++i) {
      const std::size_t e = ins(sf.edgeVertex[i]);
      out.push_back({v[i], e, c});
      out.push_back({e, v[(i + 1) % 3], c});
    }
    return out;
  }
  int split = 0;
  for (int i = 0; i < 3; ++i) split += sf.edgeVertex[i] >= 0;
  if (split == 1) {
    const int i = sf.edgeVertex[0] >= 0 ? 0 : sf.edgeVertex[1] >= 0 ? 1 : 2;
    const std::size_t e = ins(sf.edgeVertex[i]);
    out.push_back({v[i], e, v[(i + 2) % 3]});
    out.push_back({e, v[(i + 1) % 3], v[(i + 2) % 3]});
    return out;
  }
  const int k = sf.edgeVertex[0] < 0 ? 0 : sf.edgeVertex[1] < 0 ? 1 : 2;  // the free edge
  const std::size_t a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
  const std::size_t m1 = ins(sf.edgeVertex[(k + 1) % 3]), m2 = ins(sf.edgeVertex[(k + 2) % 3]);
  out.push_back({m1, c, m2});
  if (sf.diagonal == 0) {
    out.push_back({a, b, m1});
    out.push_back({a, m1, m2});
  } else {
    out.push_back({a, b, m2});
    out.push_back({b, m1, m2});
  }
  return out;
}

/// A split face left at rest, triangulated again with only the inserted
/// edge vertices a neighbour still needs (`keep[i]`: edge (v[i], v[i+1])'s
/// vertex stays): the parent itself when none stays, else a fan from the
/// first kept vertex over the parent's corners and the other kept vertices,
/// in the parent's orientation. The fan never joins two points of one edge,
/// as an edge holds one inserted vertex. Pure.
inline std::vector<std::array<std::size_t, 3>> restedTriangles(const SplitFace &sf,
                                                               const std::array<std::size_t, 3> &v,
                                                               std::size_t firstInserted,
                                                               const std::array<bool, 3> &keep) {
  std::vector<std::size_t> polygon;  // the parent's outline, kept edge vertices included
  std::size_t apex = 0;  // where the fan starts: the first kept vertex (never at 0), or corner 0
  for (int i = 0; i < 3; ++i) {
    polygon.push_back(v[i]);
    if (sf.edgeVertex[i] >= 0 && keep[i]) {
      if (apex == 0) apex = polygon.size();
      polygon.push_back(firstInserted + std::size_t(sf.edgeVertex[i]));
    }
  }
  std::rotate(polygon.begin(), polygon.begin() + std::ptrdiff_t(apex), polygon.end());
  std::vector<std::array<std::size_t, 3>> out;
  for (std::size_t j = 1; j + 1 < polygon.size(); ++j)
    out.push_back({polygon[0], polygon[j], polygon[j + 1]});
  return out;
}

}  // namespace detail

namespace detail {

/// Gives inserted vertex `v` the mean of its sources' per-vertex colour,
/// quality and texture coordinate, where the mesh has them (a coloured scan
/// in MeshLab, say): vcglib gives a new vertex white, 0 and (0, 0), which
/// would show as spots along every restored edge. Sharpening moves the
/// vertex later; its attributes stay those of the chamfer it was made on.
template <class MeshType>
void blendSourceAttributes(MeshType &m, typename MeshType::VertexType &v,
                           const InsertedVertexSource &src) {
  const int n = src.originalCount;
  if (n <= 0) return;
  const auto source = [&](int i) -> const typename MeshType::VertexType & {
    return m.vert[src.original[std::size_t(i)]];
  };
  if (vcg::tri::HasPerVertexColor(m))
    for (int c = 0; c < 4; ++c) {
      int sum = 0;
      for (int i = 0; i < n; ++i) sum += source(i).cC()[c];
      v.C()[c] = static_cast<unsigned char>((sum + n / 2) / n);  // rounded
    }
  if (vcg::tri::HasPerVertexQuality(m)) {
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += double(source(i).cQ());
    v.Q() = static_cast<typename MeshType::VertexType::QualityType>(sum / n);
  }
  if (vcg::tri::HasPerVertexTexCoord(m)) {
    double u = 0, w = 0;
    for (int i = 0; i < n; ++i) u += double(source(i).cT().U()), w += double(source(i).cT().V());
    v.T() = source(0).cT();  // its texture index
    v.T().U() = static_cast<typename MeshType::VertexType::TexCoordType::ScalarType>(u / n);
    v.T().V() = static_cast<typename MeshType::VertexType::TexCoordType::ScalarType>(w / n);
  }
}

/// The parent's face-face adjacency before it was split, per edge.
struct OldAdjacency {
  std::array<std::size_t, 3> face;
  std::array<int, 3> edge;
};

/// Face-face adjacency after the split, updated locally (linkFaceEdges):
/// every edge of every child (child 0 in its parent's slot, the others from
/// `firstNew` on), and the edges the unsplit faces across the parents' edges
/// share with them. Gives what a full rebuild gives, since the mesh is
/// 2-manifold (its edges have at most two faces); falls back to a full
/// rebuild (fast_topology.h) otherwise.
template <class MeshType>
void updateSplitAdjacency(MeshType &m, const SplitPlan &plan,
                          const std::vector<std::vector<std::array<std::size_t, 3>>> &children,
                          const std::vector<OldAdjacency> &old, std::size_t firstNew) {
  std::vector<char> split(m.face.size(), 0);
  for (const SplitFace &sf : plan.faces) split[sf.face] = 1;
  std::vector<FaceEdgeKey> edges;
  std::size_t next = firstNew;
  for (std::size_t k = 0; k < plan.faces.size(); ++k) {
    for (std::size_t c = 0; c < children[k].size(); ++c) {
      const std::size_t face = c == 0 ? plan.faces[k].face : next++;
      for (int j = 0; j < 3; ++j) edges.push_back(faceEdgeKey(m, face, j, false));
    }
    // An unsplit neighbour across a parent's edge (a split one's children
    // pair the edge themselves; the parent itself: a border).
    for (int i = 0; i < 3; ++i) {
      const std::size_t g = old[k].face[i];
      if (!split[g]) edges.push_back(faceEdgeKey(m, g, old[k].edge[i], true));
    }
  }
  linkFaceEdges(m, edges);
}
}  // namespace detail

/// Stage 4: inserts the planned vertices at their rest positions and splits
/// each chamfer face into 2 or 3 triangles and each corner face into a fan of
/// 6, preserving orientation. Children keep the parent's label and data
/// (colour, quality, flags); inserted vertices take their sources' mean
/// per-vertex colour, quality and texture coordinate (blendSourceAttributes).
/// FF topology is updated around the split faces (the same as
/// vcg::tri::UpdateTopology::FaceFace would rebuild).
/// \pre FF topology up to date.
template <class MeshType>
SubdivisionStats subdivide(MeshType &m, const SplitPlan &plan, MeshLabels<MeshType> &labels) {
  using Scalar = typename MeshType::ScalarType;
  SubdivisionStats s;
  s.insertedVertices = plan.inserted.size();
  if (plan.faces.empty()) return s;

  auto vi = vcg::tri::Allocator<MeshType>::AddVertices(m, plan.inserted.size());
  for (const auto &src : plan.inserted) {
    vi->P() = vcg::Point3<Scalar>::Construct(src.rest);
    detail::blendSourceAttributes(m, *vi, src);
    ++vi;
  }
  std::size_t extra = 0;
  std::vector<std::vector<std::array<std::size_t, 3>>> children(plan.faces.size());
  for (std::size_t k = 0; k < plan.faces.size(); ++k) {
    const auto &f = m.face[plan.faces[k].face];
    const std::array<std::size_t, 3> v{vcg::tri::Index(m, f.cV(0)), vcg::tri::Index(m, f.cV(1)),
                                       vcg::tri::Index(m, f.cV(2))};
    children[k] = detail::childTriangles(plan.faces[k], v, plan.originalVertexCount);
    extra += children[k].size() - 1;
    switch (children[k].size()) {
      case 2: ++s.facesSplitIn2; break;
      case 3: ++s.facesSplitIn3; break;
      default: ++s.facesSplitIn6; break;
    }
  }
  const std::size_t firstNew = m.face.size();
  vcg::tri::Allocator<MeshType>::AddFaces(m, extra);
  s.addedFaces = extra;

  std::vector<detail::OldAdjacency> old(plan.faces.size());
  for (std::size_t k = 0; k < plan.faces.size(); ++k) {
    const auto &f = m.face[plan.faces[k].face];
    for (int i = 0; i < 3; ++i) {
      old[k].face[i] = vcg::tri::Index(m, f.cFFp(i));
      old[k].edge[i] = f.cFFi(i);
    }
  }

  std::size_t next = firstNew;
  for (std::size_t k = 0; k < plan.faces.size(); ++k) {
    auto &parent = m.face[plan.faces[k].face];
    const FaceLabel label = labels.face[&parent];
    for (std::size_t c = 0; c < children[k].size(); ++c) {
      auto &child = c == 0 ? parent : m.face[next++];
      if (c != 0) {
        child.ImportData(parent);
        labels.face[&child] = label;
      }
      for (int j = 0; j < 3; ++j) child.V(j) = &m.vert[children[k][c][j]];
    }
  }
  detail::updateSplitAdjacency(m, plan, children, old, firstNew);
  return s;
}

}  // namespace edge_sharpener
