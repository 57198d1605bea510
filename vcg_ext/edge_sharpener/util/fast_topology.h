// Face-face adjacency in linear time: the face edges are bucketed by their
// lower vertex index (a counting sort) instead of sorted as a whole, and the
// buckets are matched in parallel (OpenMP). The result is the adjacency
// vcg::tri::UpdateTopology<M>::FaceFace builds, for any thread count:
//   - an edge with two faces: each face points at the other (FFp, FFi);
//   - a boundary edge: the face points at itself, FFi(i) == i;
//   - an edge with k > 2 faces (non-manifold): the faces form a ring, here in
//     the order of their (face index, edge index) - vcglib leaves that order
//     to std::sort, so any ring is as valid.
#pragma once

#include <vcg/complex/complex.h>
#include <vcg/simplex/face/pos.h>
#include <vcg/simplex/face/topology.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace edge_sharpener {

/// Loops over fewer elements than this run on one thread: below it, starting
/// threads costs more than it saves.
constexpr std::int64_t kParallelMin = 50000;

namespace detail {

/// One face edge in the bucket of its lower vertex: its higher vertex and its
/// id, 3 x face index + edge index.
struct BucketedEdge {
  std::uint32_t hi;
  std::uint32_t id;
  bool operator<(const BucketedEdge &o) const { return hi != o.hi ? hi < o.hi : id < o.id; }
};

/// The face edges of `m` grouped by lower vertex: bucket v is
/// edges[start[v] .. start[v+1]), sorted by (higher vertex, id).
struct EdgeBuckets {
  std::vector<std::uint32_t> start;
  std::vector<BucketedEdge> edges;
};

template <class MeshType>
EdgeBuckets bucketFaceEdges(MeshType &m) {
  EdgeBuckets b;
  const std::size_t nv = m.vert.size(), nf = m.face.size();
  b.start.assign(nv + 2, 0);
  if (nv == 0 || nf == 0) return b;
  const auto *v0 = &m.vert[0];
  // Visits every face edge as (face, side, one end, other end).
  const auto forEachFaceEdge = [&](auto &&visit) {
    for (std::size_t f = 0; f < nf; ++f) {
      const auto &face = m.face[f];
      if (face.IsD()) continue;
      for (int i = 0; i < 3; ++i)
        visit(f, i, std::uint32_t(face.cV(i) - v0), std::uint32_t(face.cV((i + 1) % 3) - v0));
    }
  };
  // Counts land in start[lo + 2] so that, after the prefix sum, start[lo + 1]
  // is the fill cursor of bucket lo and ends as the start of bucket lo + 1.
  forEachFaceEdge(
      [&](std::size_t, int, std::uint32_t a, std::uint32_t c) { ++b.start[std::min(a, c) + 2]; });
  for (std::size_t v = 2; v < nv + 2; ++v) b.start[v] += b.start[v - 1];
  b.edges.resize(b.start[nv + 1]);
  forEachFaceEdge([&](std::size_t f, int i, std::uint32_t a, std::uint32_t c) {
    b.edges[b.start[std::min(a, c) + 1]++] = BucketedEdge{std::max(a, c), std::uint32_t(3 * f + i)};
  });
  b.start.pop_back();
  // Filled in id order; sorting each small bucket by the higher vertex
  // groups the faces of each edge.
  const std::int64_t buckets = std::int64_t(nv);
#pragma omp parallel for schedule(static, 8192) if (buckets > kParallelMin)
  for (std::int64_t v = 0; v < buckets; ++v) {
    auto *first = b.edges.data() + b.start[v], *last = b.edges.data() + b.start[v + 1];
    if (last - first < 2) continue;
    // Insertion sort: buckets hold about six edges.
    for (auto *p = first + 1; p < last; ++p)
      for (auto *q = p; q > first && *q < *(q - 1); --q) std::swap(*q, *(q - 1));
  }
  return b;
}

}  // namespace detail

/// What buildFaceFace() saw of the edges while matching them.
struct FaceFaceDiagnostics {
  /// Lowest index of a face with an edge shared by three or more faces
  /// (the face count when there is none).
  std::size_t firstNonManifoldFace = 0;
  /// Whether two faces share a two-face edge in the same direction
  /// (vcg::face::CheckOrientation fails there).
  bool misoriented = false;
};

/// Rebuilds the face-face adjacency of `m`, like
/// vcg::tri::UpdateTopology<MeshType>::FaceFace (see the top of this file).
/// Deleted faces are skipped and keep their old adjacency.
/// \return the non-manifold edges and orientation it found on the way.
template <class MeshType>
FaceFaceDiagnostics buildFaceFace(MeshType &m) {
  vcg::tri::RequireFFAdjacency(m);
  FaceFaceDiagnostics diag;
  diag.firstNonManifoldFace = m.face.size();
  const detail::EdgeBuckets b = detail::bucketFaceEdges(m);
  if (b.edges.empty()) return diag;
  auto *f0 = &m.face[0];
  const auto *v0 = &m.vert[0];
  const std::int64_t buckets = std::int64_t(b.start.size()) - 1;
  std::int64_t firstNonManifold = std::int64_t(m.face.size());
  int misoriented = 0;
#pragma omp parallel for schedule(static, 8192) reduction(min                 \
                                                          : firstNonManifold) \
    reduction(max                                                             \
              : misoriented) if (buckets > kParallelMin)
  for (std::int64_t v = 0; v < buckets; ++v) {
    const detail::BucketedEdge *e = b.edges.data() + b.start[v];
    const detail::BucketedEdge *end = b.edges.data() + b.start[v + 1];
    while (e < end) {
      const detail::BucketedEdge *run = e + 1;
      while (run < end && run->hi == e->hi) ++run;
      // Each face edge of the run points at the next one, the last at the first.
      for (const detail::BucketedEdge *p = e; p < run; ++p) {
        const detail::BucketedEdge *q = p + 1 < run ? p + 1 : e;
        auto &f = f0[p->id / 3];
        f.FFp(p->id % 3) = f0 + q->id / 3;
        f.FFi(p->id % 3) = char(q->id % 3);
      }
      if (run - e > 2) {
        for (const detail::BucketedEdge *p = e; p < run; ++p)
          firstNonManifold = std::min(firstNonManifold, std::int64_t(p->id / 3));
      } else if (run - e == 2) {
        // Consistent faces walk their shared edge in opposite directions.
        const auto startsAtLow = [&](const detail::BucketedEdge *p) {
          return std::int64_t(f0[p->id / 3].cV(p->id % 3) - v0) == v;
        };
        if (startsAtLow(e) == startsAtLow(e + 1)) misoriented = 1;
      }
      e = run;
    }
  }
  diag.firstNonManifoldFace = std::size_t(firstNonManifold);
  diag.misoriented = misoriented != 0;
  return diag;
}

}  // namespace edge_sharpener

namespace edge_sharpener::detail {

/// One face edge for a local adjacency update: its vertices (lo < hi), its
/// face and side, and whether it belongs to a face outside the changed ones
/// (such an edge must find its partner among the changed faces).
struct FaceEdgeKey {
  std::uint32_t lo, hi, face;
  std::int8_t edge;
  bool outside;
  bool operator<(const FaceEdgeKey &o) const {
    if (lo != o.lo) return lo < o.lo;
    if (hi != o.hi) return hi < o.hi;
    return face != o.face ? face < o.face : edge < o.edge;
  }
};

template <class MeshType>
FaceEdgeKey faceEdgeKey(const MeshType &m, std::size_t face, int edge, bool outside) {
  const auto &f = m.face[face];
  const auto a = std::uint32_t(vcg::tri::Index(m, f.cV(edge)));
  const auto b = std::uint32_t(vcg::tri::Index(m, f.cV((edge + 1) % 3)));
  return {std::min(a, b), std::max(a, b), std::uint32_t(face), std::int8_t(edge), outside};
}

/// Face-face adjacency of the changed faces' edges (`outside` false) and of
/// the edges their unchanged neighbours share with them (`outside` true):
/// pairs of equal edges point at each other, a changed face's lone edge is a
/// boundary. What a full rebuild gives on a 2-manifold mesh; anything else
/// (three faces on an edge, an outside edge without its partner) falls back
/// to the full rebuild.
template <class MeshType>
void linkFaceEdges(MeshType &m, std::vector<FaceEdgeKey> &edges) {
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end(),
                          [](const FaceEdgeKey &a, const FaceEdgeKey &b) {
                            return a.face == b.face && a.edge == b.edge && a.lo == b.lo &&
                                   a.hi == b.hi;
                          }),
              edges.end());
  const auto link = [&](const FaceEdgeKey &a, const FaceEdgeKey &b) {
    m.face[a.face].FFp(a.edge) = &m.face[b.face];
    m.face[a.face].FFi(a.edge) = char(b.edge);
  };
  for (std::size_t e = 0; e < edges.size();) {
    std::size_t run = e + 1;
    while (run < edges.size() && edges[run].lo == edges[e].lo && edges[run].hi == edges[e].hi)
      ++run;
    const bool paired = run - e == 2 && !(edges[e].outside && edges[e + 1].outside);
    const bool boundary = run - e == 1 && !edges[e].outside;
    if (!paired && !boundary) {
      buildFaceFace(m);
      return;
    }
    link(edges[e], edges[run - 1]);
    link(edges[run - 1], edges[e]);
    e = run;
  }
}

/// Vertex `z` of face `f` seen from the faces around it: the vertices joined
/// to it by an edge, and whether a border edge ends at it. vcglib's
/// VVOrderedStarFF takes one vertex per face, so at a border vertex (k
/// faces, k + 1 neighbours) it misses one.
template <class FaceType>
struct VertexStar {
  std::vector<typename FaceType::VertexType *> neighbours;
  bool onBorder = false;

  VertexStar(FaceType &f, int z) {
    using Pos = vcg::face::Pos<FaceType>;
    auto *v = f.V(z);
    std::vector<Pos> star;
    vcg::face::VFOrderedStarFF(Pos(&f, z, v), star);
    for (const Pos &p : star) {
      FaceType *h = p.F();
      for (int j = 0; j < 3; ++j) {
        auto *u = h->V(j);
        if (u == v) {
          onBorder |= h->FFp(j) == h || h->FFp((j + 2) % 3) == h;
        } else if (std::find(neighbours.begin(), neighbours.end(), u) == neighbours.end()) {
          neighbours.push_back(u);
        }
      }
    }
  }
};

/// The link condition of edge z of face f (Dey et al.; what
/// vcg::face::FFLinkCondition tests, with every neighbour of a border
/// vertex): collapsing it keeps the mesh 2-manifold when its ends share no
/// neighbour but the vertices opposite the edge, and, for an edge between
/// faces, are not both on a border.
template <class FaceType>
bool linkConditionHolds(FaceType &f, int z) {
  const bool borderEdge = f.FFp(z) == &f;
  const VertexStar<FaceType> end0(f, z), end1(f, (z + 1) % 3);
  std::size_t shared = 0;
  for (auto *u : end0.neighbours)
    shared += std::find(end1.neighbours.begin(), end1.neighbours.end(), u) != end1.neighbours.end();
  if (shared != (borderEdge ? 1u : 2u)) return false;
  return borderEdge || !(end0.onBorder && end1.onBorder);
}

}  // namespace edge_sharpener::detail
