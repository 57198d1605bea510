// Extended method, detection: the smooth part split into regions (the
// paper's "global approach": triangles connected through smooth edges), and
// the regions' faces that belong to the feature zone returned to it:
// corridors, region contacts, internal creases.
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>
#include <vector>

#include "../filters.h"
#include "../report.h"
#include "../util/mesh_labels.h"
#include "../util/parallel.h"
#include "zones.h"

namespace edge_sharpener {

namespace detail {

/// Components of faces joined by smooth edges, as a union-find forest whose
/// every root is the smallest face of its component. Union-find in face
/// order: sequential, where a flood fill walks the faces at random. A union
/// links the larger root under the smaller, so the roots do not depend on
/// the order of the unions: each thread joins the edges inside its own range
/// of faces, then the edges between ranges are joined serially.
template <class MeshType>
std::vector<std::uint32_t> smoothComponents(const MeshType &m, const MeshLabels<MeshType> &labels) {
  const std::size_t nf = m.face.size();
  std::vector<std::uint32_t> parent(nf);
  for (std::size_t f = 0; f < nf; ++f) parent[f] = std::uint32_t(f);
  const auto find = [&parent](std::uint32_t f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];  // path halving
    return f;
  };
  const auto unite = [&](std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  };
  const std::int64_t faceCount = std::int64_t(nf);
  const int ranges = faceCount > kParallelMin ? detail::maxThreads() : 1;
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> between(ranges);
#pragma omp parallel for schedule(static, 1) num_threads(ranges)
  for (int t = 0; t < ranges; ++t) {
    const std::int64_t first = faceCount * t / ranges, last = faceCount * (t + 1) / ranges;
    for (std::int64_t fi = first; fi < last; ++fi) {
      const auto &f = m.face[fi];
      if (f.IsD()) continue;
      for (int i = 0; i < 3; ++i) {
        const auto *g = f.cFFp(i);
        if (g == &f || labels.edge[&f][i] != EdgeLabel::Smooth) continue;
        const std::int64_t gi = std::int64_t(vcg::tri::Index(m, g));
        if (gi < first || gi >= last)
          between[t].emplace_back(std::uint32_t(fi), std::uint32_t(gi));
        else
          unite(std::uint32_t(fi), std::uint32_t(gi));  // touches this range only
      }
    }
  }
  for (const auto &edges : between)
    for (const auto &[a, b] : edges) unite(a, b);
  return parent;
}

/// Numbers the components holding a core red face, in the order of their
/// first red face, into zones.faceRegion (kZone elsewhere).
/// \return the number of regions.
template <class MeshType>
int numberRegions(const MeshLabels<MeshType> &labels, std::vector<std::uint32_t> &parent,
                  FeatureZones &zones) {
  // Every root is the smallest face of its component (a union keeps the
  // smaller root, halving points to smaller faces), so one pass in face order
  // points every face at its root; the root's entry of faceRegion holds the
  // region id until the second pass copies it to the component.
  // (The mesh is compact here: no face is deleted, and these passes read
  // labels and parents only, never the faces themselves.)
  const std::size_t nf = parent.size();
  zones.faceRegion.assign(nf, kZone);
  int regions = 0;
  for (std::size_t fi = 0; fi < nf; ++fi) {
    parent[fi] = parent[parent[fi]];
    if (labels.face[fi] == FaceLabel::Red) {
      int &id = zones.faceRegion[parent[fi]];
      if (id == kZone) id = regions++;
    }
  }
  const std::int64_t faceCount = std::int64_t(nf);
#pragma omp parallel for schedule(static, 8192) if (faceCount > kParallelMin)
  for (std::int64_t fi = 0; fi < faceCount; ++fi)
    if (parent[fi] != fi) zones.faceRegion[fi] = zones.faceRegion[parent[fi]];
  return regions;
}

/// Per vertex: its region when all its faces lie in that one region and no
/// border edge ends there (an interior vertex), else kZone. Border edges are
/// looked for only where the mesh has one (`meshHasBorder`): it reads the
/// faces themselves. Runs on every core.
template <class MeshType>
std::vector<int> interiorVertexRegions(const MeshType &m, const VertexFaceTable &vf,
                                       const FeatureZones &zones, bool meshHasBorder) {
  const std::int64_t nv = std::int64_t(m.vert.size());
  std::vector<int> vertexRegion(nv, kZone);
#pragma omp parallel for schedule(static, 8192) if (nv > kParallelMin)
  for (std::int64_t v = 0; v < nv; ++v) {
    if (vf.degree(v) == 0) continue;
    int r = zones.faceRegion[*vf.begin(v)];
    bool interior = r != kZone;
    for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v) && interior; ++fi)
      interior = zones.faceRegion[*fi] == r;
    for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v) && interior && meshHasBorder;
         ++fi) {
      const auto &f = m.face[*fi];
      for (int k = 0; k < 3 && interior; ++k)
        if (f.cFFp(k) == &f && (vcg::tri::Index(m, f.cV(k)) == std::size_t(v) ||
                                vcg::tri::Index(m, f.cV((k + 1) % 3)) == std::size_t(v)))
          interior = false;
    }
    if (interior) vertexRegion[v] = r;
  }
  return vertexRegion;
}

/// Each region's depth in hops from its border, capped at `minDepth`: waves
/// from every non-interior vertex, which stop there instead of sweeping
/// every region's interior (only whether a region reaches minDepth matters).
template <class MeshType>
std::vector<int> regionDepths(const MeshType &m, const VertexFaceTable &vf,
                              const std::vector<int> &vertexRegion, int regions, int minDepth) {
  const std::size_t nv = m.vert.size();
  std::vector<int> depth(nv, -1);
  std::deque<std::size_t> queue;
  for (std::size_t v = 0; v < nv; ++v)
    if (vf.degree(v) > 0 && vertexRegion[v] == kZone) {
      depth[v] = 0;
      queue.push_back(v);
    }
  std::vector<int> maxDepth(regions, 0);
  while (!queue.empty()) {
    const std::size_t v = queue.front();
    queue.pop_front();
    if (depth[v] >= minDepth) continue;
    forEachNeighbour(m, vf, v, [&](std::size_t u) {
      if (depth[u] >= 0 || vertexRegion[u] == kZone) return;
      depth[u] = depth[v] + 1;
      maxDepth[vertexRegion[u]] = std::max(maxDepth[vertexRegion[u]], depth[u]);
      queue.push_back(u);
    });
  }
  return maxDepth;
}

/// Returns to the zone every region thinner than `minDepth` (a corridor) and
/// renumbers the others in order; counts regions, corridors and zone faces.
inline void dropCorridors(const std::vector<int> &maxDepth, int minDepth, FeatureZones &zones,
                          ExtendedStats &stats) {
  const int regions = int(maxDepth.size());
  std::vector<int> renumber(regions, kZone);
  int kept = 0;
  for (int r = 0; r < regions; ++r)
    if (maxDepth[r] >= minDepth) renumber[r] = kept++;
  stats.regions = std::size_t(kept);
  stats.corridors = std::size_t(regions - kept);
  const std::int64_t faceCount = std::int64_t(zones.faceRegion.size());
  std::int64_t zoneFaces = 0;
#pragma omp parallel for schedule(static, 8192) reduction(+ : zoneFaces) if (faceCount > kParallelMin)
  for (std::int64_t f = 0; f < faceCount; ++f) {
    int &r = zones.faceRegion[f];
    if (r != kZone) r = renumber[r];
    zoneFaces += r == kZone;
  }
  stats.zoneFaces += std::size_t(zoneFaces);
}

}  // namespace detail

/// Splits the smooth part into regions: the components of faces joined by
/// smooth edges that hold one of the paper's core faces (filters 1-2), one id
/// per component, then returns to the zone every region thinner than `minDepth` hops
/// (a corridor of smooth triangles, e.g. a wide but regular chamfer band).
/// `meshHasBorder` false (no edge with one face: SmoothEdgeStats::boundaryEdges
/// is 0) skips looking for border edges.
/// \pre labelSmoothEdges() ran; m is compact (no deleted faces).
/// Writes labels.vertex/face like filters 1-2.
template <class MeshType>
void segmentRegions(MeshType &m, MeshLabels<MeshType> &labels, const VertexFaceTable &vf,
                    int minDepth, FeatureZones &zones, ExtendedStats &stats,
                    bool meshHasBorder = true) {
  paintInteriorRedVertices(m, labels);
  paintCoreRedFaces(m, labels);
  std::vector<std::uint32_t> parent = detail::smoothComponents(m, labels);
  const int regions = detail::numberRegions(labels, parent, zones);
  std::vector<std::uint32_t>().swap(parent);
  const std::vector<int> vertexRegion = detail::interiorVertexRegions(m, vf, zones, meshHasBorder);
  detail::dropCorridors(detail::regionDepths(m, vf, vertexRegion, regions, minDepth), minDepth,
                        zones, stats);
}

/// Returns to the zone every region face incident to a marked vertex, except
/// the faces of the regions in `kept` (indexed by region; empty: none kept).
/// \return the number of faces returned.
inline std::size_t openFacesAround(const VertexFaceTable &vf, const std::vector<char> &marked,
                                   FeatureZones &zones, const std::vector<char> &kept = {}) {
  std::size_t opened = 0;
  for (std::size_t v = 0; v < marked.size(); ++v) {
    if (!marked[v]) continue;
    for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v); ++fi) {
      const int r = zones.faceRegion[*fi];
      if (r == kZone || (!kept.empty() && kept[r])) continue;
      zones.faceRegion[*fi] = kZone;
      ++opened;
    }
  }
  return opened;
}

namespace detail {

/// The region of vertex v's faces: kZone where none lies in a region,
/// kCrease where several regions meet there.
inline int regionAtVertex(const VertexFaceTable &vf, const FeatureZones &zones, std::size_t v) {
  int region = kZone;
  for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v); ++fi) {
    const int r = zones.faceRegion[*fi];
    if (r == kZone) continue;
    if (region == kZone)
      region = r;
    else if (region != r)
      return kCrease;
  }
  return region;
}

/// Per region: whether opening the faces around the `marked` vertices would
/// leave it no interior vertex (interiorVertexRegions, with no marked vertex
/// among its neighbours) although its faces span at least `minLength` (their
/// bounding box's diagonal). Such a region is a facet narrower than its
/// contacts' rings (of a coarse cylinder), not a smooth piece of a chamfer
/// band: those are short, and the bands without an interior vertex were
/// corridors (dropCorridors).
template <class MeshType>
std::vector<char> narrowFacets(const MeshType &m, const VertexFaceTable &vf,
                               const std::vector<char> &marked, const FeatureZones &zones,
                               double minLength, bool meshHasBorder) {
  int regions = 0;
  for (const int r : zones.faceRegion) regions = std::max(regions, r + 1);
  std::vector<char> narrow(regions, 0);
  if (!(minLength > 0)) return narrow;
  const std::vector<int> vertexRegion = interiorVertexRegions(m, vf, zones, meshHasBorder);
  std::vector<char> survives(regions, 0);
  for (std::size_t v = 0; v < vertexRegion.size(); ++v) {
    const int r = vertexRegion[v];
    if (r == kZone || survives[r] || marked[v]) continue;
    bool clear = true;
    forEachNeighbour(m, vf, v, [&](std::size_t u) { clear = clear && !marked[u]; });
    survives[r] = clear;
  }
  std::vector<vcg::Box3<double>> extent(regions);
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    const int r = zones.faceRegion[f];
    if (r == kZone || survives[r] || m.face[f].IsD()) continue;
    for (int k = 0; k < 3; ++k) extent[r].Add(positionOf(m.face[f].cV(k)));
  }
  for (int r = 0; r < regions; ++r)
    narrow[r] = !survives[r] && !extent[r].IsNull() && extent[r].Diag() >= minLength;
  return narrow;
}

}  // namespace detail

/// Returns to the zone every region face with a vertex shared by two or more
/// regions. Where two regions touch directly the chamfer was swallowed by
/// their growth (its edges passed the smooth test); opening the contact
/// turns it back into a zone to sharpen. A narrow facet (detail::narrowFacets,
/// at least `minFacetLength` long) keeps its faces: opened, it would vanish
/// and the planes beside it would be extrapolated across it.
/// `meshHasBorder` as for segmentRegions.
/// \return the number of faces returned to the zone; `keptFacets` counts
///         the narrow facets kept.
template <class MeshType>
std::size_t openRegionContacts(const MeshType &m, const VertexFaceTable &vf, FeatureZones &zones,
                               double minFacetLength, std::size_t &keptFacets,
                               bool meshHasBorder = true) {
  const std::int64_t nv = std::int64_t(m.vert.size());
  std::vector<char> contact(nv, 0);
#pragma omp parallel for schedule(static, 8192) if (nv > kParallelMin)
  for (std::int64_t v = 0; v < nv; ++v)
    contact[v] = detail::regionAtVertex(vf, zones, v) == kCrease;
  const std::vector<char> narrow =
      detail::narrowFacets(m, vf, contact, zones, minFacetLength, meshHasBorder);
  keptFacets = std::size_t(std::count(narrow.begin(), narrow.end(), 1));
  return openFacesAround(vf, contact, zones, narrow);
}

/// Returns to the zone every region face around a vertex of an internal
/// crease: a non-smooth edge whose two faces grew into the same region. A
/// region leaks around the end of a feature whose angle fades out (fandisk's
/// blends), so both flanks of the sharp part carry one id; opening the crease
/// gives that part a zone, which labelZoneVertices() splits by plane.
/// \pre segmentRegions() ran. \return the number of faces returned.
template <class MeshType>
std::size_t openInternalCreases(const MeshType &m, const MeshLabels<MeshType> &labels,
                                const VertexFaceTable &vf, double minAngleRad,
                                FeatureZones &zones) {
  // On every core; each thread lists the crease edges it finds.
  const std::int64_t nf = std::int64_t(m.face.size());
  const int threads = nf > kParallelMin ? detail::maxThreads() : 1;
  std::vector<detail::PerThread<std::vector<std::uint32_t>>> found(threads);
#pragma omp parallel num_threads(threads)
  {
    std::vector<std::uint32_t> &ends = found[detail::threadNumber()].value;
#pragma omp for schedule(static, 8192)
    for (std::int64_t fi = 0; fi < nf; ++fi) {
      const auto &f = m.face[fi];
      if (f.IsD()) continue;
      const int r = zones.faceRegion[fi];
      if (r == kZone) continue;
      for (int i = 0; i < 3; ++i) {
        const auto *g = f.cFFp(i);
        if (g == &f || labels.edge[&f][i] == EdgeLabel::Smooth) continue;
        if (zones.faceRegion[vcg::tri::Index(m, g)] != r) continue;
        if (angleBetween(labels.normal[&f], labels.normal[g]) <= minAngleRad) continue;
        ends.push_back(std::uint32_t(vcg::tri::Index(m, f.cV(i))));
        ends.push_back(std::uint32_t(vcg::tri::Index(m, f.cV((i + 1) % 3))));
      }
    }
  }
  std::vector<char> crease(m.vert.size(), 0);
  for (const auto &ends : found)
    for (const std::uint32_t v : ends.value) crease[v] = 1;
  return openFacesAround(vf, crease, zones);
}

}  // namespace edge_sharpener
