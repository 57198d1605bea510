// Extended method: the plane of a region near one vertex (fitted to the
// region's faces within a few rings, trimmed of the chamfer faces it
// absorbed), and the input's sample spacing.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "../options.h"
#include "../util/geometry.h"
#include "../util/parallel.h"
#include "zones.h"

namespace edge_sharpener {

/// A region's plane near one vertex, and how the region departs from it
/// (placement.h: SupportFit).
using RegionPlaneFit = SupportFit;

/// How fitRegionPlane() fits: face rings and trim angle.
struct PlaneFitSettings {
  int rings = 2;       ///< SharpenOptions::supportRings
  double trimRad = 0;  ///< SharpenOptions::fitTrimAngleRad

  static PlaneFitSettings from(const SharpenOptions &opt) {
    return {opt.extended.supportRings, opt.extended.fitTrimAngleRad};
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

/// A face of a region plane fit: unit normal, centroid, area.
struct FittedFace {
  Vec3 normal, centroid;
  double area;
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
        if (area > 0) out.faces.push_back(FittedFace{n / area, (p0 + p1 + p2) / 3.0, area});
        out.centroidSum += (p0 + p1 + p2) * (area / 3.0);
        out.areaSum += area;
        for (int k = 0; k < 3; ++k) next.push_back(vcg::tri::Index(m, f.cV(k)));
      }
    frontier.swap(next);
  }
  return out;
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
/// it to tell a curved region from a flat one).
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
  if (s.trimRad > 0) detail::trimTurnedFaces(collected, s.trimRad, fit.plane);
  detail::measureSpread(collected.faces, collected.areaSum, fit);
  return fit;
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

}  // namespace edge_sharpener
