// Non-manifold spots added to a closed mesh, for the tests of meshes people
// actually have (a CAD export's touching parts, a decimation's pinched edge):
// a small tetrahedron standing on one vertex (a non-manifold vertex) or on
// one edge (four faces on that edge: a non-manifold edge), put on the
// surface at a vertex near a chamfer, far from every chamfer, or on one.
#pragma once

#include <vcg/complex/complex.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace edge_sharpener::test_meshes {

enum class SpotKind { Vertex, Edge };
enum class SpotPlace { OnChamfer, NearChamfer, FarFromChamfers };

namespace detail {

/// Per vertex: 1 - the smallest cosine between its area-weighted normal and
/// a face normal around it (0 on a flat spot; large on a chamfer).
template <class M>
std::vector<double> vertexBend(const M &m, std::vector<vcg::Point3d> &normal) {
  const std::size_t nv = m.vert.size();
  normal.assign(nv, vcg::Point3d(0, 0, 0));
  std::vector<vcg::Point3d> faceNormal;
  for (const auto &f : m.face) {
    const vcg::Point3d a = vcg::Point3d::Construct(f.cV(0)->cP());
    const vcg::Point3d n =
        (vcg::Point3d::Construct(f.cV(1)->cP()) - a) ^ (vcg::Point3d::Construct(f.cV(2)->cP()) - a);
    faceNormal.push_back(n);
    for (int i = 0; i < 3; ++i) normal[vcg::tri::Index(m, f.cV(i))] += n;
  }
  for (auto &n : normal) n.Normalize();
  std::vector<double> bend(nv, 0);
  for (std::size_t fi = 0; fi < m.face.size(); ++fi) {
    const vcg::Point3d n = faceNormal[fi] / faceNormal[fi].Norm();
    for (int i = 0; i < 3; ++i) {
      const std::size_t v = vcg::tri::Index(m, m.face[fi].cV(i));
      bend[v] = std::max(bend[v], 1 - n * normal[v]);
    }
  }
  return bend;
}

}  // namespace detail

/// The vertex a spot goes on: on a chamfer, the most bent vertex; else the
/// vertex nearest to (NearChamfer: at least 1.5 median edges from) or
/// farthest from (FarFromChamfers) the chamfer vertices (bend above 0.05).
template <class M>
std::size_t spotVertex(const M &m, SpotPlace place) {
  std::vector<vcg::Point3d> normal;
  const std::vector<double> bend = detail::vertexBend(m, normal);
  if (place == SpotPlace::OnChamfer)
    return std::size_t(std::max_element(bend.begin(), bend.end()) - bend.begin());
  std::vector<double> edges;
  for (const auto &f : m.face) edges.push_back(vcg::Distance(f.cV(0)->cP(), f.cV(1)->cP()));
  std::nth_element(edges.begin(), edges.begin() + edges.size() / 2, edges.end());
  const double edge = edges[edges.size() / 2];
  std::size_t best = 0;
  double bestDistance = place == SpotPlace::NearChamfer ? std::numeric_limits<double>::max() : -1;
  for (std::size_t v = 0; v < m.vert.size(); ++v) {
    double nearest = std::numeric_limits<double>::max();
    for (std::size_t w = 0; w < m.vert.size(); ++w)
      if (bend[w] > 0.05)
        nearest = std::min(nearest, double(vcg::Distance(m.vert[v].cP(), m.vert[w].cP())));
    const bool better = place == SpotPlace::NearChamfer
                            ? nearest > 1.5 * edge && nearest < bestDistance
                            : nearest > bestDistance;
    if (better) {
      best = v;
      bestDistance = nearest;
    }
  }
  return best;
}

/// Adds a spot of `kind` at vertex `a` of closed mesh `m`: a tetrahedron of
/// edge about the median edge length, outside the surface, sharing vertex a
/// (Vertex) or the edge from a to the next vertex of a's first face (Edge).
/// \return the input's vertex indices the spot touches (a; a and the edge's
/// other end).
template <class M>
std::vector<std::size_t> addSpot(M &m, SpotKind kind, std::size_t a) {
  using Coord = typename M::CoordType;
  std::vector<vcg::Point3d> normal;
  detail::vertexBend(m, normal);
  const vcg::Point3d n = normal[a];
  std::size_t b = a, firstFace = 0;
  for (std::size_t fi = 0; fi < m.face.size(); ++fi)
    for (int i = 0; i < 3; ++i)
      if (vcg::tri::Index(m, m.face[fi].cV(i)) == a && b == a) {
        b = vcg::tri::Index(m, m.face[fi].cV((i + 1) % 3));
        firstFace = fi;
      }
  (void)firstFace;
  const double edge = vcg::Distance(m.vert[a].cP(), m.vert[b].cP());
  const vcg::Point3d pa = vcg::Point3d::Construct(m.vert[a].cP());
  const vcg::Point3d pb = vcg::Point3d::Construct(m.vert[b].cP());
  vcg::Point3d t = n ^ vcg::Point3d(1, 0, 0);
  if (t.Norm() < 0.1) t = n ^ vcg::Point3d(0, 1, 0);
  t.Normalize();
  const vcg::Point3d s = n ^ t;
  std::vector<vcg::Point3d> apex;
  if (kind == SpotKind::Vertex) {
    const vcg::Point3d c = pa + n * edge;
    apex = {c + t * (0.5 * edge), c + (t * -0.5 + s * 0.87) * (0.5 * edge),
            c + (t * -0.5 - s * 0.87) * (0.5 * edge)};
  } else {
    vcg::Point3d side = (pb - pa) ^ n;
    side.Normalize();
    const vcg::Point3d mid = (pa + pb) / 2 + n * edge;
    apex = {mid + side * (0.3 * edge), mid - side * (0.3 * edge)};
  }
  const std::size_t first = m.vert.size();
  auto vi = vcg::tri::Allocator<M>::AddVertices(m, apex.size());
  for (const auto &p : apex) (vi++)->P() = Coord::Construct(p);
  std::vector<std::array<std::size_t, 3>> tet;
  if (kind == SpotKind::Vertex)
    tet = {{a, first, first + 1},
           {a, first + 1, first + 2},
           {a, first + 2, first},
           {first, first + 2, first + 1}};
  else
    tet = {{a, b, first}, {b, a, first + 1}, {a, first, first + 1}, {b, first + 1, first}};
  // Each face outward from the tetrahedron's centroid.
  vcg::Point3d centroid(0, 0, 0);
  for (const auto &f : tet)
    for (std::size_t v : f) centroid += vcg::Point3d::Construct(m.vert[v].cP()) / 12;
  for (auto &f : tet) {
    const vcg::Point3d p0 = vcg::Point3d::Construct(m.vert[f[0]].cP());
    const vcg::Point3d p1 = vcg::Point3d::Construct(m.vert[f[1]].cP());
    const vcg::Point3d p2 = vcg::Point3d::Construct(m.vert[f[2]].cP());
    if (((p1 - p0) ^ (p2 - p0)) * ((p0 + p1 + p2) / 3 - centroid) < 0) std::swap(f[1], f[2]);
    vcg::tri::Allocator<M>::AddFace(m, &m.vert[f[0]], &m.vert[f[1]], &m.vert[f[2]]);
  }
  if (kind == SpotKind::Vertex) return {a};
  return {a, b};
}

}  // namespace edge_sharpener::test_meshes
