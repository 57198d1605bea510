// The extended method's detection: smooth regions segmented into separate
// surfaces, and a feature zone of any width between them whose vertices are
// labelled with the surface they belong to.
//
// The paper's filters find a chamfer only where it is one triangle wide and
// every vertex next to it is red. Marching cubes leaves bands two or more
// triangles wide and whole corner patches whose vertices are not red. Here the
// smooth part is split into regions (the paper's "global approach": triangles
// connected through smooth edges), thin corridors are returned to the zone,
// so are region contacts and internal creases (a region that leaked around
// the fading end of a feature), and each zone vertex takes the label of the
// nearby region whose local plane it lies closest to. An edge whose endpoints
// carry different labels, or one label with planes 45 degrees apart, crosses
// a sharp edge; a face with three labels contains a corner. The split and the
// placement then follow the paper, with planes fitted to each region near
// the feature instead of one vertex's normal.
#pragma once

#include <algorithm>
#include <array>
#include <cstring>
#include <deque>
#include <vector>

#include "filters.h"
#include "geometry.h"
#include "mesh_labels.h"
#include "options.h"
#include "parallel.h"
#include "placement.h"
#include "report.h"
#include "sampling_grid.h"
#include "vertex_faces.h"

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
  SamplingGrid samplingGrid;     ///< the input's marching-cubes grid, if it has one
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

/// Returns to the zone every region face incident to a marked vertex.
/// \return the number of faces returned.
inline std::size_t openFacesAround(const VertexFaceTable &vf, const std::vector<char> &marked,
                                   FeatureZones &zones) {
  std::size_t opened = 0;
  for (std::size_t v = 0; v < marked.size(); ++v) {
    if (!marked[v]) continue;
    for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v); ++fi)
      if (zones.faceRegion[*fi] != kZone) {
        zones.faceRegion[*fi] = kZone;
        ++opened;
      }
  }
  return opened;
}

/// Returns to the zone every region face with a vertex shared by two or more
/// regions. Where two regions touch directly the chamfer was swallowed by
/// their growth (its edges passed the smooth test); opening the contact
/// turns it back into a zone to sharpen.
/// \return the number of faces returned to the zone.
template <class MeshType>
std::size_t openRegionContacts(const MeshType &m, const VertexFaceTable &vf, FeatureZones &zones) {
  const std::int64_t nv = std::int64_t(m.vert.size());
  std::vector<char> contact(nv, 0);
#pragma omp parallel for schedule(static, 8192) if (nv > kParallelMin)
  for (std::int64_t v = 0; v < nv; ++v) {
    int seen = kZone;
    for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v); ++fi) {
      const int r = zones.faceRegion[*fi];
      if (r == kZone) continue;
      if (seen == kZone) seen = r;
      if (seen != r) contact[v] = 1;
    }
  }
  return openFacesAround(vf, contact, zones);
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

/// Whether two planes of one region stand for different surfaces: both are
/// set and they turn by more than `featureAngleRad` (a region that leaked
/// around a fading feature). A non-positive angle disables the test.
inline bool planesTurnApart(const Vec3 &na, const Vec3 &nb, double featureAngleRad) {
  return featureAngleRad > 0 && na.SquaredNorm() > 0 && nb.SquaredNorm() > 0 &&
         angleBetween(na, nb) > featureAngleRad;
}

/// Whether two labelled vertices sit on different surfaces: different
/// regions, or one region whose planes there turn by more than
/// `featureAngleRad` (a region that leaked around a fading feature).
inline bool differentSurfaces(const FeatureZones &zones, std::size_t a, std::size_t b,
                              double featureAngleRad) {
  const int la = zones.vertexLabel[a], lb = zones.vertexLabel[b];
  if (la < 0 || lb < 0) return false;
  if (la != lb) return true;
  return planesTurnApart(zones.support.plane(a).normal, zones.support.plane(b).normal,
                         featureAngleRad);
}

/// A region's plane near one vertex, and how the region departs from it
/// (placement.h: SupportFit).
using RegionPlaneFit = SupportFit;

/// How fitRegionPlane() fits: face rings, trim angle, and (strict plane
/// guard) the seed away from the zone.
struct PlaneFitSettings {
  int rings = 2;       ///< SharpenOptions::supportRings
  double trimRad = 0;  ///< SharpenOptions::fitTrimAngleRad
  /// SharpenOptions::fitSeedFlatAngleRad (0: off); needs `nearZone`.
  double seedFlatRad = 0;
  /// Per vertex: 1 when it has a zone face; null when not seeding.
  const std::vector<char> *nearZone = nullptr;

  static PlaneFitSettings from(const SharpenOptions &opt, const std::vector<char> &nearZone) {
    return {opt.supportRings, opt.fitTrimAngleRad, opt.fitSeedFlatAngleRad,
            opt.fitSeedFlatAngleRad > 0 ? &nearZone : nullptr};
  }
};

/// Per vertex: 1 when one of its faces is a zone face.
template <class MeshType>
std::vector<char> verticesTouchingZone(const MeshType &m, const VertexFaceTable &vf,
                                       const FeatureZones &zones) {
  const std::int64_t nv = std::int64_t(m.vert.size());
  std::vector<char> touches(nv, 0);
#pragma omp parallel for schedule(static, 8192) if (nv > kParallelMin)
  for (std::int64_t v = 0; v < nv; ++v)
    for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v) && !touches[v]; ++fi)
      touches[v] = zones.faceRegion[*fi] == kZone;
  return touches;
}

namespace detail {

/// A face of a region plane fit: unit normal, centroid, area, and whether no
/// vertex of it touches the zone.
struct FittedFace {
  Vec3 normal, centroid;
  double area;
  bool awayFromZone;
};

/// The faces of region `r` within `s.rings` face rings of v, with their
/// area-weighted sums (faces of zero area count in the sums only).
struct RegionFaces {
  std::vector<FittedFace> faces;
  Vec3 normalSum{0, 0, 0}, centroidSum{0, 0, 0};
  double areaSum = 0;
};

/// Collects the faces of region `r` within `s.rings` face rings of v,
/// marking each visited face with `stampValue` in `stamp`.
template <class MeshType>
RegionFaces collectRegionFaces(const MeshType &m, const VertexFaceTable &vf,
                               const FeatureZones &zones, std::size_t v, int r,
                               const PlaneFitSettings &s, std::vector<int> &stamp, int stampValue) {
  RegionFaces out;
  std::vector<std::size_t> frontier{v}, next;
  for (int ring = 0; ring < s.rings && !frontier.empty(); ++ring) {
    next.clear();
    for (std::size_t w : frontier)
      for (const std::uint32_t *fi = vf.begin(w); fi != vf.end(w); ++fi) {
        if (zones.faceRegion[*fi] != r || stamp[*fi] == stampValue) continue;
        stamp[*fi] = stampValue;
        const auto &f = m.face[*fi];
        const Vec3 p0 = positionOf(f.cV(0)), p1 = positionOf(f.cV(1)), p2 = positionOf(f.cV(2));
        const Vec3 n = (p1 - p0) ^ (p2 - p0);  // twice the area times the unit normal
        const double area = n.Norm();
        out.normalSum += n;
        bool away = s.nearZone != nullptr;
        for (int k = 0; k < 3 && away; ++k) away = !(*s.nearZone)[vcg::tri::Index(m, f.cV(k))];
        if (area > 0) out.faces.push_back(FittedFace{n / area, (p0 + p1 + p2) / 3.0, area, away});
        out.centroidSum += (p0 + p1 + p2) * (area / 3.0);
        out.areaSum += area;
        for (int k = 0; k < 3; ++k) next.push_back(vcg::tri::Index(m, f.cV(k)));
      }
    frontier.swap(next);
  }
  return out;
}

/// The mean normal of the faces away from the zone when those turn from it
/// by at most `flatRad` (the faces next to the zone may be a strip of the
/// chamfer the region absorbed); else `normal` unchanged.
inline Vec3 seedAwayFromZone(const std::vector<FittedFace> &faces, const Vec3 &normal,
                             double flatRad) {
  Vec3 awaySum(0, 0, 0);
  for (const FittedFace &f : faces)
    if (f.awayFromZone) awaySum += f.normal * f.area;
  bool flat = awaySum.Norm() > 0;
  for (const FittedFace &f : faces)
    flat = flat && (!f.awayFromZone || angleBetween(awaySum, f.normal) <= flatRad);
  return flat ? awaySum / awaySum.Norm() : normal;
}

/// Refits the plane without the faces more than `trimRad` away from its
/// normal (the border of a region often holds a few faces of the chamfer);
/// drops them from `in` when some remain.
inline void trimTurnedFaces(RegionFaces &in, double trimRad, Plane &plane) {
  Vec3 n2(0, 0, 0), c2(0, 0, 0);
  double a2 = 0;
  std::vector<FittedFace> kept;
  for (const FittedFace &f : in.faces)
    if (angleBetween(plane.normal, f.normal) <= trimRad) {
      n2 += f.normal * f.area;
      c2 += f.centroid * f.area;
      a2 += f.area;
      kept.push_back(f);
    }
  if (a2 > 0 && n2.Norm() > 0) {
    plane = Plane{c2 / a2, n2 / n2.Norm()};
    in.faces.swap(kept);
    in.areaSum = a2;
  }
}

/// The spread of the fitted faces around fit.plane (placement reads it to
/// tell a curved region from a flat one).
inline void measureSpread(const std::vector<FittedFace> &faces, double areaSum,
                          RegionPlaneFit &fit) {
  for (const FittedFace &f : faces) {
    fit.spreadRad = std::max(fit.spreadRad, angleBetween(fit.plane.normal, f.normal));
    fit.normalScatter.add(f.normal - fit.plane.normal, f.centroid - fit.plane.point, f.area);
    fit.pointScatter.add(f.centroid - fit.plane.point, f.centroid - fit.plane.point, f.area);
    fit.normalSelfScatter.add(f.normal - fit.plane.normal, f.normal - fit.plane.normal, f.area);
  }
  fit.normalScatter.scale(1.0 / areaSum);
  fit.pointScatter.scale(1.0 / areaSum);
  fit.normalSelfScatter.scale(1.0 / areaSum);
}

}  // namespace detail

/// The plane of region `r` near vertex v: through the area-weighted centroid,
/// and orthogonal to the area-weighted normal, of the region's faces within
/// `s.rings` face rings of v (zero normal when v touches no face of r),
/// refitted without the faces more than `s.trimRad` away from that normal (0:
/// no refit), with the spread of the fitted faces around it (placement reads
/// it to tell a curved region from a flat one). With `s.seedFlatRad`, the
/// trim is centred on the mean normal of the fitted faces that touch no zone
/// vertex when those turn by at most that angle: the faces next to the zone
/// may be a strip of the chamfer the region absorbed.
template <class MeshType>
RegionPlaneFit fitRegionPlane(const MeshType &m, const VertexFaceTable &vf,
                              const FeatureZones &zones, std::size_t v, int r,
                              const PlaneFitSettings &s, std::vector<int> &stamp, int stampValue) {
  detail::RegionFaces collected =
      detail::collectRegionFaces(m, vf, zones, v, r, s, stamp, stampValue);
  RegionPlaneFit fit;
  fit.plane.point = positionOf(&m.vert[v]);
  const double len = collected.normalSum.Norm();
  if (!(collected.areaSum > 0) || !(len > 0)) return fit;
  fit.plane = Plane{collected.centroidSum / collected.areaSum, collected.normalSum / len};
  if (s.seedFlatRad > 0)
    fit.plane.normal = detail::seedAwayFromZone(collected.faces, fit.plane.normal, s.seedFlatRad);
  if (s.trimRad > 0) detail::trimTurnedFaces(collected, s.trimRad, fit.plane);
  detail::measureSpread(collected.faces, collected.areaSum, fit);
  return fit;
}

/// Returns to the zone the region faces around the zone's border that turn
/// away from their region's plane, fitted there as labelZoneVertices() fits
/// it, by more than `maxTurnRad`: a strip of chamfer faces whose edges passed
/// the smooth test grew into the region and tilts the plane fitted across it.
/// Every fit reads the regions as they were before this stage (one ring of
/// faces is returned, never more).
/// \pre segmentRegions() ran (and the opening stages, when enabled).
/// \return the number of faces returned to the zone.
template <class MeshType>
std::size_t returnTurnedBorderFaces(const MeshType &m, const MeshLabels<MeshType> &labels,
                                    const VertexFaceTable &vf, const SharpenOptions &opt,
                                    double maxTurnRad, FeatureZones &zones) {
  const std::vector<char> touchesZone = verticesTouchingZone(m, vf, zones);
  const PlaneFitSettings fitSettings = PlaneFitSettings::from(opt, touchesZone);
  std::vector<std::uint32_t> border;
  for (std::size_t v = 0; v < m.vert.size(); ++v)
    if (touchesZone[v]) border.push_back(std::uint32_t(v));
  // Every fit reads the regions as they are before this stage, so the border
  // vertices are independent: on every core, each thread with its own visit
  // stamps and its own list of turned faces.
  const std::int64_t count = std::int64_t(border.size());
  const int threads = count >= 256 ? detail::maxThreads() : 1;
  std::vector<std::vector<int>> stamps(threads);
  std::vector<detail::PerThread<std::vector<std::uint32_t>>> turnedBy(threads);
#pragma omp parallel num_threads(threads)
  {
    const int t = detail::threadNumber();
    std::vector<int> &stamp = stamps[t];
    int stampValue = 0;  // one per fit of this thread
    std::vector<int> regionsAtVertex;
#pragma omp for schedule(dynamic, 64)
    for (std::int64_t k = 0; k < count; ++k) {
      if (stamp.empty()) stamp.assign(m.face.size(), -1);
      const std::size_t v = border[k];
      regionsAtVertex.clear();
      for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v); ++fi) {
        const int r = zones.faceRegion[*fi];
        if (r != kZone &&
            std::find(regionsAtVertex.begin(), regionsAtVertex.end(), r) == regionsAtVertex.end())
          regionsAtVertex.push_back(r);
      }
      for (std::size_t i = 0; i < regionsAtVertex.size(); ++i) {
        const int r = regionsAtVertex[i];
        const RegionPlaneFit fit =
            fitRegionPlane(m, vf, zones, v, r, fitSettings, stamp, stampValue++);
        if (fit.plane.normal.SquaredNorm() == 0) continue;
        for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v); ++fi)
          if (zones.faceRegion[*fi] == r &&
              angleBetween(labels.normal[&m.face[*fi]], fit.plane.normal) > maxTurnRad)
            turnedBy[t].value.push_back(*fi);
      }
    }
  }
  std::vector<char> turned(m.face.size(), 0);
  for (const auto &list : turnedBy)
    for (const std::uint32_t f : list.value) turned[f] = 1;
  std::size_t returned = 0;
  for (std::size_t f = 0; f < turned.size(); ++f)
    if (turned[f]) {
      zones.faceRegion[f] = kZone;
      ++returned;
    }
  return returned;
}

/// The input's sample spacing: the median length of its edges (each edge
/// once: taken from the face with the lower address, or from its only face).
/// \pre FF adjacency.
template <class MeshType>
double medianEdgeLength(const MeshType &m) {
  // Collected on every core (the k-th smallest length does not depend on
  // the order of the list).
  const std::int64_t nf = std::int64_t(m.face.size());
  const int threads = nf > kParallelMin ? detail::maxThreads() : 1;
  std::vector<detail::PerThread<std::vector<float>>> parts(threads);
#pragma omp parallel num_threads(threads)
  {
    std::vector<float> &lengths = parts[detail::threadNumber()].value;
    lengths.reserve(3 * nf / (2 * threads) + 16);
#pragma omp for schedule(static, 8192)
    for (std::int64_t fi = 0; fi < nf; ++fi) {
      const auto &f = m.face[fi];
      if (f.IsD()) continue;
      for (int i = 0; i < 3; ++i)
        if (f.cFFp(i) >= &f)
          lengths.push_back(float((positionOf(f.cV(i)) - positionOf(f.cV((i + 1) % 3))).Norm()));
    }
  }
  std::size_t total = 0;
  for (const auto &part : parts) total += part.value.size();
  if (total == 0) return 0.0;
  // Radix select: non-negative floats order as their bit patterns do, so a
  // histogram of the upper 16 bits finds the bucket of the middle element,
  // and only that bucket is sorted partially.
  const auto bitsOf = [](float x) {
    std::uint32_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  };
  std::vector<std::size_t> count(std::size_t(1) << 16, 0);
  for (const auto &part : parts)
    for (const float x : part.value) ++count[bitsOf(x) >> 16];
  std::size_t rank = total / 2, bucket = 0;
  while (rank >= count[bucket]) rank -= count[bucket++];
  std::vector<float> inBucket;
  inBucket.reserve(count[bucket]);
  for (const auto &part : parts)
    for (const float x : part.value)
      if ((bitsOf(x) >> 16) == bucket) inBucket.push_back(x);
  std::nth_element(inBucket.begin(), inBucket.begin() + rank, inBucket.end());
  return inBucket[rank];
}

/// Fills zones.support.offPlane: how far each labelled vertex lies from its
/// own plane, which placement reads for the strict plane guard
/// (SharpenOptions::maxSourceOffPlaneSpacings). \pre labelZoneVertices() ran.
template <class MeshType>
void measureOffPlane(const MeshType &m, FeatureZones &zones) {
  auto &support = zones.support;
  support.offPlane.assign(m.vert.size(), 0.0);
  for (std::size_t v = 0; v < m.vert.size(); ++v) {
    const Plane &pl = support.plane(v);
    if (pl.normal.SquaredNorm() > 0)
      support.offPlane[v] = std::abs(pl.normal * (positionOf(&m.vert[v]) - pl.point));
  }
}

/// For every vertex with a plane, finds up to three other regions whose
/// labelled vertices lie within `rings` hops (closest first) and records one
/// vertex of each in zones.support.nearby; placement checks the planes' line
/// against them. Also fills zones.support.region.
template <class MeshType>
void collectNearbyRegions(const MeshType &m, const VertexFaceTable &vf, FeatureZones &zones,
                          int rings) {
  const std::size_t nv = m.vert.size();
  auto &support = zones.support;
  support.region.assign(nv, kZone);
  support.nearby.assign(
      nv, {SupportPlanes::kNoVertex, SupportPlanes::kNoVertex, SupportPlanes::kNoVertex});
  const auto hasPlane = [&](std::size_t v) {
    return zones.vertexLabel[v] >= 0 && support.plane(v).normal.SquaredNorm() > 0;
  };
  std::vector<std::uint32_t> withPlane;
  for (std::size_t v = 0; v < nv; ++v)
    if (hasPlane(v)) {
      support.region[v] = zones.vertexLabel[v];
      withPlane.push_back(std::uint32_t(v));
    }
  // Each vertex writes only its own entry: on every core, each thread with
  // its own visit stamps.
  const std::int64_t count = std::int64_t(withPlane.size());
  const int threads = count >= 256 ? detail::maxThreads() : 1;
  std::vector<std::vector<std::uint32_t>> stamps(threads);
#pragma omp parallel num_threads(threads)
  {
    std::vector<std::uint32_t> &stamp = stamps[detail::threadNumber()];
    std::vector<std::size_t> frontier, next;
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t k = 0; k < count; ++k) {
      if (stamp.empty()) stamp.assign(nv, SupportPlanes::kNoVertex);
      const std::uint32_t v = withPlane[k];
      auto &found = support.nearby[v];
      int n = 0;
      frontier.assign(1, v);
      stamp[v] = v;
      for (int ring = 0; ring < rings && n < 3; ++ring) {
        next.clear();
        for (std::size_t w : frontier)
          detail::forEachNeighbour(m, vf, w, [&](std::size_t u) {
            if (stamp[u] == v) return;
            stamp[u] = v;
            next.push_back(u);
          });
        for (std::size_t u : next) {
          if (n == 3 || !hasPlane(u) || support.region[u] == support.region[v]) continue;
          bool known = false;
          for (int i = 0; i < n; ++i) known |= support.region[found[i]] == support.region[u];
          if (!known) found[n++] = std::uint32_t(u);
        }
        frontier.swap(next);
      }
    }
  }
}

namespace detail {

/// Region vertices take their region (kCrease where several meet), zone
/// vertices kZone; fills zones.vertexLabel and zones.inRegion. Each vertex
/// reads only its own faces, so the loop runs on every core.
template <class MeshType>
void labelRegionVertices(const MeshType &m, const VertexFaceTable &vf, FeatureZones &zones) {
  const std::int64_t count = std::int64_t(m.vert.size());
#pragma omp parallel for schedule(static, 8192) if (count > kParallelMin)
  for (std::int64_t v = 0; v < count; ++v) {
    int label = kZone;
    for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v); ++fi) {
      const int r = zones.faceRegion[*fi];
      if (r == kZone) continue;
      if (label == kZone)
        label = r;
      else if (label != r)
        label = kCrease;
    }
    zones.vertexLabel[v] = label;
    zones.inRegion[v] = label != kZone;
  }
}

/// Fits each region vertex of `fitted` its region's plane there (one fit
/// each, on every core, each thread with its own visit stamps) into
/// zones.support.
template <class MeshType>
void fitPlanesAtZone(const MeshType &m, const VertexFaceTable &vf,
                     const std::vector<std::uint32_t> &fitted, const PlaneFitSettings &fitSettings,
                     FeatureZones &zones) {
  zones.support.fits.resize(fitted.size());
  const std::int64_t fits = std::int64_t(fitted.size());
  const int threads = fits >= 256 ? detail::maxThreads() : 1;
  // Per thread: stamps of the faces a fit has visited (each fit its own value).
  std::vector<std::vector<int>> stamps(threads);
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads)
  for (std::int64_t k = 0; k < fits; ++k) {
    std::vector<int> &stamp = stamps[detail::threadNumber()];
    if (stamp.empty()) stamp.assign(m.face.size(), -1);
    const std::size_t v = fitted[k];
    zones.support.fits[k] =
        fitRegionPlane(m, vf, zones, v, zones.vertexLabel[v], fitSettings, stamp, int(k));
  }
  for (std::size_t k = 0; k < fitted.size(); ++k) zones.support.fitOf[fitted[k]] = std::uint32_t(k);
}

/// A region offered to a zone vertex: its id, the fitted vertex whose plane
/// it offers, and how many hops away that vertex is.
struct LabelCandidate {
  int region;
  std::uint32_t anchor;
  int hops;
};
constexpr std::size_t kMaxLabelCandidates = 4;

/// The regions offered to each vertex of `zone` (same order; up to
/// kMaxLabelCandidates each).
struct ZoneCandidates {
  std::vector<std::array<LabelCandidate, kMaxLabelCandidates>> list;
  std::vector<std::uint8_t> count;
};

/// Breadth-first waves from every fitted region vertex into the zone; each
/// zone vertex keeps the first arrival of up to four regions, within
/// `opt.labelSlackHops` of the first, at most `opt.maxLabelHops` away.
template <class MeshType>
ZoneCandidates offerRegions(const MeshType &m, const VertexFaceTable &vf, const SharpenOptions &opt,
                            const FeatureZones &zones, const std::vector<std::uint32_t> &fitted,
                            const std::vector<std::uint32_t> &zone) {
  constexpr std::uint32_t kNotZone = ~std::uint32_t(0);
  std::vector<std::uint32_t> zoneSlot(m.vert.size(), kNotZone);
  for (std::size_t k = 0; k < zone.size(); ++k) zoneSlot[zone[k]] = std::uint32_t(k);
  ZoneCandidates cand{std::vector<std::array<LabelCandidate, kMaxLabelCandidates>>(zone.size()),
                      std::vector<std::uint8_t>(zone.size(), 0)};
  std::deque<std::pair<std::uint32_t, LabelCandidate>> queue;
  for (const std::uint32_t v : fitted)
    queue.push_back({v, LabelCandidate{zones.vertexLabel[v], v, 0}});
  while (!queue.empty()) {
    const auto [v, c] = queue.front();
    queue.pop_front();
    if (c.hops >= opt.maxLabelHops) continue;
    forEachNeighbour(m, vf, v, [&, c = c](std::size_t u) {
      const std::uint32_t slot = zoneSlot[u];
      if (slot == kNotZone) return;
      auto &list = cand.list[slot];
      std::uint8_t &n = cand.count[slot];
      if (n == kMaxLabelCandidates) return;
      if (n > 0 && c.hops + 1 > list[0].hops + opt.labelSlackHops) return;
      // One candidate per surface: a region that leaked around a fading
      // feature offers one per plane direction.
      for (std::uint8_t i = 0; i < n; ++i)
        if (list[i].region == c.region &&
            !planesTurnApart(zones.support.plane(list[i].anchor).normal,
                             zones.support.plane(c.anchor).normal, opt.sameRegionFeatureAngleRad))
          return;
      list[n++] = LabelCandidate{c.region, c.anchor, c.hops + 1};
      queue.push_back({std::uint32_t(u), list[n - 1]});
    });
  }
  return cand;
}

/// Gives each zone vertex the offered region whose plane lies nearest, and
/// shares that plane's fit.
template <class MeshType>
void labelByNearestPlane(const MeshType &m, const std::vector<std::uint32_t> &zone,
                         const ZoneCandidates &cand, FeatureZones &zones, ExtendedStats &stats) {
  for (std::size_t k = 0; k < zone.size(); ++k) {
    const std::size_t v = zone[k];
    if (cand.count[k] == 0) continue;
    const Vec3 p = positionOf(&m.vert[v]);
    double best = std::numeric_limits<double>::infinity();
    for (std::uint8_t i = 0; i < cand.count[k]; ++i) {
      const Plane &pl = zones.support.plane(cand.list[k][i].anchor);
      if (pl.normal.SquaredNorm() == 0) continue;
      const double d = std::abs(pl.normal * (p - pl.point));
      if (d < best) {  // ties keep the earlier (closer in hops) candidate
        best = d;
        zones.vertexLabel[v] = cand.list[k][i].region;
        zones.support.shareFit(v, cand.list[k][i].anchor);
      }
    }
    stats.labelledZoneVertices += zones.vertexLabel[v] >= 0;
  }
}

}  // namespace detail

/// Labels every vertex: region vertices with their region (kCrease where
/// several regions meet), zone vertices with the nearby region (within
/// `opt.labelSlackHops` of the closest one, at most `opt.maxLabelHops` away)
/// whose local plane is nearest; fills each labelled vertex's plane.
template <class MeshType>
void labelZoneVertices(const MeshType &m, const VertexFaceTable &vf, const SharpenOptions &opt,
                       FeatureZones &zones, ExtendedStats &stats) {
  const std::size_t nv = m.vert.size();
  zones.vertexLabel.assign(nv, kZone);
  zones.inRegion.assign(nv, 0);
  zones.support.reset(nv);
  zones.support.measured = true;
  const std::vector<char> touchesZone = verticesTouchingZone(m, vf, zones);
  detail::labelRegionVertices(m, vf, zones);
  // Region vertices next to the zone get their region's plane there (in
  // vertex order); zone vertices wait for a label.
  std::vector<std::uint32_t> fitted, zone;
  for (std::size_t v = 0; v < nv; ++v) {
    if (zones.vertexLabel[v] >= 0 && touchesZone[v]) fitted.push_back(std::uint32_t(v));
    if (!zones.inRegion[v] && vf.degree(v) > 0) zone.push_back(std::uint32_t(v));
  }
  stats.zoneVertices += zone.size();
  detail::fitPlanesAtZone(m, vf, fitted, PlaneFitSettings::from(opt, touchesZone), zones);
  const detail::ZoneCandidates cand = detail::offerRegions(m, vf, opt, zones, fitted, zone);
  detail::labelByNearestPlane(m, zone, cand, zones, stats);
  collectNearbyRegions(m, vf, zones, opt.supportRings);
}

/// Marks the chamfer edges and faces of the extended method in the paper's
/// labels, so the paper's split plan and subdivision apply unchanged: region
/// faces are red; an edge between two zone faces (or a zone face and the
/// mesh border) whose endpoints sit on different surfaces (differentSurfaces():
/// different region labels, or one region's planes more than
/// `sameRegionFeatureAngleRad` apart) is a chamfer edge; faces with three
/// such edges are corners.
template <class MeshType>
FilterStats markZoneChamfers(MeshType &m, MeshLabels<MeshType> &labels, const FeatureZones &zones,
                             double sameRegionFeatureAngleRad) {
  // One pass over the faces, on every core: the test is symmetric, so each
  // face labels its own side of an edge, and counts the edge from its
  // lower-address face.
  const std::int64_t nf = std::int64_t(m.face.size());
  std::int64_t redFaces = 0, chamferEdges = 0, cornerFaces = 0, chamferFaces = 0;
#pragma omp parallel for schedule(static, 4096) \
    reduction(+ : redFaces, chamferEdges, cornerFaces, chamferFaces) if (nf > kParallelMin)
  for (std::int64_t fi = 0; fi < nf; ++fi) {
    auto &f = m.face[fi];
    if (f.IsD()) continue;
    const bool zone = zones.faceRegion[fi] == kZone;
    EdgeLabels3 edges{EdgeLabel::Gray, EdgeLabel::Gray, EdgeLabel::Gray};
    int blue = 0;
    for (int i = 0; i < 3 && zone; ++i) {
      const auto *g = f.cFFp(i);
      const bool boundary = g == &f;
      if (!boundary && zones.faceRegion[vcg::tri::Index(m, g)] != kZone) continue;
      if (differentSurfaces(zones, vcg::tri::Index(m, f.cV(i)),
                            vcg::tri::Index(m, f.cV((i + 1) % 3)), sameRegionFeatureAngleRad)) {
        edges[i] = EdgeLabel::Chamfer;
        ++blue;
        chamferEdges += boundary || &f < g;
      }
    }
    labels.edge[&f] = edges;
    labels.face[&f] = blue == 3  ? FaceLabel::Corner
                      : blue > 0 ? FaceLabel::Chamfer
                      : zone     ? FaceLabel::Gray
                                 : FaceLabel::Red;
    redFaces += !zone;
    cornerFaces += blue == 3;
    chamferFaces += blue == 1 || blue == 2;
  }
  const std::int64_t nv = std::int64_t(m.vert.size());
  std::int64_t redVertices = 0;
#pragma omp parallel for schedule(static, 8192) reduction(+ : redVertices) if (nv > kParallelMin)
  for (std::int64_t v = 0; v < nv; ++v) {
    labels.vertex[v] = zones.inRegion[v] ? VertexLabel::Red : VertexLabel::Gray;
    redVertices += zones.inRegion[v];
  }
  FilterStats s;
  s.redFaces = std::size_t(redFaces);
  s.redVertices = std::size_t(redVertices);
  s.chamferEdges = std::size_t(chamferEdges);
  s.cornerFaces = std::size_t(cornerFaces);
  s.chamferFaces = std::size_t(chamferFaces);
  return s;
}

namespace detail {

/// The faces after the split of each original vertex v with `candidate(v)`,
/// in increasing order: facesOf[slot[v]] (slot kNone for the others). A face
/// that kept its index holds only vertices of the input face it was (the
/// split puts a child in its parent's slot), so a candidate's faces are
/// among its input faces and among the faces the split appended after them.
struct CandidateFaces {
  static constexpr std::uint32_t kNone = ~std::uint32_t(0);
  std::vector<std::uint32_t> slot;
  std::vector<std::vector<std::uint32_t>> facesOf;
};

template <class MeshType, class Candidate>
CandidateFaces facesOfCandidates(const MeshType &m, const FeatureZones &zones,
                                 std::size_t originalCount, Candidate &&candidate) {
  constexpr std::uint32_t kNone = CandidateFaces::kNone;
  const std::size_t firstNew = zones.faceRegion.size();
  CandidateFaces c;
  c.slot.assign(originalCount, kNone);
  for (std::size_t v = 0; v < originalCount; ++v) {
    if (!candidate(v)) continue;
    c.slot[v] = std::uint32_t(c.facesOf.size());
    auto &list = c.facesOf.emplace_back();
    for (const std::uint32_t *fi = zones.inputFaces.begin(v); fi != zones.inputFaces.end(v); ++fi)
      for (int k = 0; k < 3; ++k)
        if (vcg::tri::Index(m, m.face[*fi].cV(k)) == v) list.push_back(*fi);
  }
  for (std::size_t fi = firstNew; fi < m.face.size(); ++fi)
    for (int k = 0; k < 3; ++k) {
      const std::size_t u = vcg::tri::Index(m, m.face[fi].cV(k));
      if (u < originalCount && c.slot[u] != kNone)
        c.facesOf[c.slot[u]].push_back(std::uint32_t(fi));
    }
  return c;
}

/// The longest move allowed to v (at p): `factor` x the mean length of the
/// edges from v to the other corners of `faces` (each edge as often as a
/// face holds it).
template <class MeshType>
double maxProjectionStep(const MeshType &m, const std::vector<std::uint32_t> &faces, std::size_t v,
                         const Vec3 &p, double factor) {
  double edgeSum = 0;
  int edgeCount = 0;
  for (const std::uint32_t fi : faces)
    for (int k = 0; k < 3; ++k) {
      const std::size_t u = vcg::tri::Index(m, m.face[fi].cV(k));
      if (u == v) continue;
      edgeSum += (positionOf(&m.vert[u]) - p).Norm();
      ++edgeCount;
    }
  return factor * edgeSum / std::max(1, edgeCount);
}

/// Whether moving v to `target` keeps every face of `faces` facing the same
/// way and creates no angle below `degenerateAngleRad` that was not there.
template <class MeshType>
bool moveKeepsFaces(const MeshType &m, const std::vector<std::uint32_t> &faces, std::size_t v,
                    const Vec3 &target, double degenerateAngleRad) {
  for (const std::uint32_t fi : faces) {
    const auto &f = m.face[fi];
    Vec3 q[3], r[3];
    for (int k = 0; k < 3; ++k) {
      q[k] = positionOf(f.cV(k));
      r[k] = vcg::tri::Index(m, f.cV(k)) == v ? target : q[k];
    }
    const Vec3 before = (q[1] - q[0]) ^ (q[2] - q[0]);
    const Vec3 after = (r[1] - r[0]) ^ (r[2] - r[0]);
    const double minBefore = minTriangleAngle(q[0], q[1], q[2]);
    const double minAfter = minTriangleAngle(r[0], r[1], r[2]);
    if (!(before * after > 0 && (minAfter >= degenerateAngleRad || minAfter >= minBefore)))
      return false;
  }
  return true;
}

}  // namespace detail

/// Moves each labelled zone vertex (an original vertex outside every region)
/// that borders a sharpened edge (`nearSharpEdge`) onto its region's plane,
/// the surface it samples: marching cubes and similar samplers leave such
/// vertices on the rounded band. A move longer
/// than `opt.maxProjectionFactor` x the vertex's mean edge length, or one
/// that would flip an incident face or create an angle below the
/// degenerate threshold, is not made. Region vertices never move.
/// \pre the mesh is the one detection labelled (zones.inputFaces), split by
/// subdivide() and changed by nothing else since.
/// \return the number of vertices moved.
template <class MeshType>
std::size_t projectZoneVertices(MeshType &m, const FeatureZones &zones, std::size_t originalCount,
                                const std::vector<char> &nearSharpEdge, const SharpenOptions &opt,
                                ExtendedStats &stats) {
  using Scalar = typename MeshType::ScalarType;
  const detail::CandidateFaces candidates =
      detail::facesOfCandidates(m, zones, originalCount, [&](std::size_t v) {
        return !zones.inRegion[v] && zones.vertexLabel[v] >= 0 && nearSharpEdge[v];
      });
  std::size_t moved = 0;
  for (std::size_t v = 0; v < originalCount; ++v) {
    const std::uint32_t slot = candidates.slot[v];
    if (slot == detail::CandidateFaces::kNone || candidates.facesOf[slot].empty()) continue;
    const std::vector<std::uint32_t> &faces = candidates.facesOf[slot];
    const Plane &pl = zones.support.plane(v);
    const Vec3 p = positionOf(&m.vert[v]);
    const Vec3 target = p - pl.normal * (pl.normal * (p - pl.point));
    const double step = (target - p).Norm();
    // A move below the mesh's float resolution changes nothing: not counted.
    if (vcg::Point3<Scalar>::Construct(target) == m.vert[v].cP()) continue;
    if (step > detail::maxProjectionStep(m, faces, v, p, opt.maxProjectionFactor) ||
        !detail::moveKeepsFaces(m, faces, v, target, opt.degenerateAngleRad)) {
      ++stats.projectionsRejected;
      continue;
    }
    m.vert[v].P() = vcg::Point3<Scalar>::Construct(target);
    stats.maxProjection = std::max(stats.maxProjection, step);
    ++moved;
  }
  stats.projectedVertices = moved;
  return moved;
}

}  // namespace edge_sharpener
