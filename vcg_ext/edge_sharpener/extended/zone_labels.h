// Extended method: each zone vertex labelled with the nearby region whose
// plane it lies closest to, the regions near each labelled vertex, and the
// chamfer edges and corner faces those labels give, in the paper's labels.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <limits>
#include <vector>

#include "../options.h"
#include "../report.h"
#include "../util/mesh_labels.h"
#include "../util/parallel.h"
#include "planar_regions.h"
#include "plane_fit.h"
#include "segmentation.h"
#include "zones.h"

namespace edge_sharpener {

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
      detail::forEachRing(m, vf, v, rings, stamp, v, frontier, next, [&](const auto &ring) {
        for (std::size_t u : ring) {
          if (n == 3 || !hasPlane(u) || support.region[u] == support.region[v]) continue;
          bool known = false;
          for (int i = 0; i < n; ++i) known |= support.region[found[i]] == support.region[u];
          if (!known) found[n++] = std::uint32_t(u);
        }
        return n < 3;
      });
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
    const int label = regionAtVertex(vf, zones, v);
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
/// `opt.extended.labelSlackHops` of the first, at most `opt.extended.maxLabelHops` away.
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
    if (c.hops >= opt.extended.maxLabelHops) continue;
    forEachNeighbour(m, vf, v, [&, c = c](std::size_t u) {
      const std::uint32_t slot = zoneSlot[u];
      if (slot == kNotZone) return;
      auto &list = cand.list[slot];
      std::uint8_t &n = cand.count[slot];
      if (n == kMaxLabelCandidates) return;
      if (n > 0 && c.hops + 1 > list[0].hops + opt.extended.labelSlackHops) return;
      // One candidate per surface: a region that leaked around a fading
      // feature offers one per plane direction.
      for (std::uint8_t i = 0; i < n; ++i)
        if (list[i].region == c.region &&
            !planesTurnApart(zones.support.plane(list[i].anchor).normal,
                             zones.support.plane(c.anchor).normal,
                             opt.extended.sameRegionFeatureAngleRad))
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
/// `opt.extended.labelSlackHops` of the closest one, at most `opt.extended.maxLabelHops` away)
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
  detail::fitPlanesAtZone(m, vf, fitted, PlaneFitSettings::from(opt), zones);
  if (opt.extended.regionPlanes) {
    zones.support.regionPlanes =
        planarRegionPlanes(m, vf, zones, touchesZone, zones.support.sampleSpacing, {});
    for (const Plane &p : zones.support.regionPlanes)
      stats.planarRegions += p.normal.SquaredNorm() > 0;
  }
  const detail::ZoneCandidates cand = detail::offerRegions(m, vf, opt, zones, fitted, zone);
  detail::labelByNearestPlane(m, zone, cand, zones, stats);
  collectNearbyRegions(m, vf, zones, opt.extended.supportRings);
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

}  // namespace edge_sharpener
