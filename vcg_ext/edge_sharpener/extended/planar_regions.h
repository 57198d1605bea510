// Extended method: the regions that are planes. Placement fits a region's
// plane next to the feature (fitRegionPlane: two face rings of a border
// vertex), where a reconstruction (Screened Poisson, a scan's fusion) rounds
// the region into the feature. A region that is a plane away from its
// features, in its core, gives placement that plane instead
// (placement.h: detail::onRegionPlanes).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "../rulebook.h"
#include "../util/fast_topology.h"
#include "../util/geometry.h"
#include "../util/parallel.h"
#include "../util/vertex_faces.h"
#include "zones.h"

namespace edge_sharpener {

namespace detail {

/// An orthonormal pair spanning the plane of unit normal n.
inline std::array<Vec3, 2> inPlaneBasis(const Vec3 &n) {
  Vec3 u = std::abs(n[0]) < 0.9 ? Vec3(1, 0, 0) ^ n : Vec3(0, 1, 0) ^ n;
  u.Normalize();
  return {u, n ^ u};
}

/// The principal axes of a point set's spread in a plane: the eigenvectors
/// of its second moments (xx, xy, yy) in the basis `b`, major axis first.
inline std::array<Vec3, 2> principalAxes(const std::array<Vec3, 2> &b, double xx, double xy,
                                         double yy) {
  const double angle = 0.5 * std::atan2(2 * xy, xx - yy);
  const Vec3 major = b[0] * std::cos(angle) + b[1] * std::sin(angle);
  const Vec3 minor = b[0] * -std::sin(angle) + b[1] * std::cos(angle);
  return {major, minor};
}

/// Hops from the feature zone (vertices touching a zone face, or of no
/// single region) through region vertices, capped at `cap`.
template <class MeshType>
std::vector<int> hopsFromZone(const MeshType &m, const VertexFaceTable &vf,
                              const FeatureZones &zones, const std::vector<char> &touchesZone,
                              int cap) {
  const std::size_t nv = m.vert.size();
  std::vector<int> hops(nv, cap);
  std::deque<std::uint32_t> queue;
  for (std::size_t v = 0; v < nv; ++v)
    if (touchesZone[v] || zones.vertexLabel[v] < 0) {
      hops[v] = 0;
      queue.push_back(std::uint32_t(v));
    }
  while (!queue.empty()) {
    const std::uint32_t v = queue.front();
    queue.pop_front();
    if (hops[v] + 1 >= cap) continue;
    forEachNeighbour(m, vf, v, [&](std::size_t u) {
      if (hops[u] > hops[v] + 1) {
        hops[u] = hops[v] + 1;
        queue.push_back(std::uint32_t(u));
      }
    });
  }
  return hops;
}

/// One region's core, accumulated face by face (area-weighted).
struct CoreMoments {
  int faces = 0;
  double area = 0;
  Vec3 normalSum{0, 0, 0}, centroidSum{0, 0, 0};
  double distance2 = 0, xx = 0, xy = 0, yy = 0;  // about the plane, in its basis
  std::array<Vec3, 4> halfNormals{Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 0)};

  CoreMoments &operator+=(const CoreMoments &o) {
    faces += o.faces;
    area += o.area;
    normalSum += o.normalSum;
    centroidSum += o.centroidSum;
    distance2 += o.distance2;
    xx += o.xx, xy += o.xy, yy += o.yy;
    for (int k = 0; k < 4; ++k) halfNormals[k] += o.halfNormals[k];
    return *this;
  }
};

/// Whether a core (its moments `c`: area, distances about its plane, the
/// normals of its halves) is a plane: its faces within `s.maxRmsSpacings`
/// RMS of it, its halves turned by at most `s.maxBendRad`.
inline bool coreIsPlane(const CoreMoments &c, double spacing, const PlanarRegionSettings &s) {
  const double rms = std::sqrt(c.distance2 / c.area);
  const double bend = std::max(angleBetween(c.halfNormals[0], c.halfNormals[1]),
                               angleBetween(c.halfNormals[2], c.halfNormals[3]));
  return rms <= s.maxRmsSpacings * spacing && bend <= s.maxBendRad;
}

/// Adds visit(moments of r, r, face) over the core faces into `core`: fixed
/// blocks of faces (in face order) summed on every core, each block's sums
/// per region then added in block order (the same sums for any thread count).
template <class Visit>
void sumOverCoreFaces(const std::vector<std::uint32_t> &coreFaces,
                      const std::vector<int> &faceRegion, std::vector<CoreMoments> &core,
                      Visit &&visit) {
  constexpr std::size_t kBlock = 16384;
  const std::int64_t blocks = std::int64_t((coreFaces.size() + kBlock - 1) / kBlock);
  std::vector<std::vector<std::pair<int, CoreMoments>>> partial(blocks);
#pragma omp parallel if (blocks > 2)
  {
    std::vector<int> slot(core.size(), -1);  // a region's entry in the block's list
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t b = 0; b < blocks; ++b) {
      auto &sums = partial[b];
      const std::size_t end = std::min(coreFaces.size(), std::size_t(b + 1) * kBlock);
      for (std::size_t j = std::size_t(b) * kBlock; j < end; ++j) {
        const std::uint32_t fi = coreFaces[j];
        const int r = faceRegion[fi];
        if (slot[r] < 0) {
          slot[r] = int(sums.size());
          sums.emplace_back(r, CoreMoments{});
        }
        visit(sums[slot[r]].second, r, fi);
      }
      for (const auto &entry : sums) slot[entry.first] = -1;
    }
  }
  for (const auto &sums : partial)
    for (const auto &[r, c] : sums) core[r] += c;
}

/// The region faces whose vertices all lie at least `coreHops` from the
/// zone, in face order.
template <class MeshType>
std::vector<std::uint32_t> coreFaces(const MeshType &m, const FeatureZones &zones,
                                     const std::vector<int> &hops, int coreHops) {
  const auto inCore = [&](std::int64_t fi) {
    const auto &f = m.face[fi];
    if (zones.faceRegion[fi] < 0 || f.IsD()) return false;
    for (int k = 0; k < 3; ++k)
      if (hops[vcg::tri::Index(m, f.cV(k))] < coreHops) return false;
    return true;
  };
  return indicesWhere(std::int64_t(m.face.size()), inCore, kParallelMin);
}

}  // namespace detail

/// Per region: its plane when the region is one (PlanarRegionSettings), else
/// a zero normal. `touchesZone`: per vertex, whether a zone face is among its
/// faces; `spacing`: the sample spacing.
template <class MeshType>
std::vector<Plane> planarRegionPlanes(const MeshType &m, const VertexFaceTable &vf,
                                      const FeatureZones &zones,
                                      const std::vector<char> &touchesZone, double spacing,
                                      const PlanarRegionSettings &s) {
  int regions = 0;
  for (const int r : zones.faceRegion) regions = std::max(regions, r + 1);
  const Plane none{Vec3(0, 0, 0), Vec3(0, 0, 0)};
  std::vector<Plane> plane(regions, none);
  if (regions == 0 || !(spacing > 0)) return plane;
  const std::vector<int> hops = detail::hopsFromZone(m, vf, zones, touchesZone, s.coreHops);
  std::vector<detail::CoreMoments> core(regions);
  std::vector<std::array<Vec3, 2>> basis(regions), axes(regions);
  // The core faces, in face order; then three passes over them: the plane;
  // the distances and the extent's moments about it; the normals of the halves.
  const std::vector<std::uint32_t> coreFaces = detail::coreFaces(m, zones, hops, s.coreHops);
  const auto forEachCoreFace = [&](auto &&visit) {
    detail::sumOverCoreFaces(
        coreFaces, zones.faceRegion, core, [&](detail::CoreMoments &c, int r, std::uint32_t fi) {
          const auto &f = m.face[fi];
          const Vec3 p0 = positionOf(f.cV(0)), p1 = positionOf(f.cV(1)), p2 = positionOf(f.cV(2));
          visit(c, plane[r], r, (p1 - p0) ^ (p2 - p0), (p0 + p1 + p2) / 3.0);
        });
  };
  forEachCoreFace([](detail::CoreMoments &c, const Plane &, int, const Vec3 &n, const Vec3 &x) {
    const double area = n.Norm();
    ++c.faces;
    c.area += area;
    c.normalSum += n;
    c.centroidSum += x * area;
  });
  for (int r = 0; r < regions; ++r) {
    const detail::CoreMoments &c = core[r];
    if (c.faces < s.minCoreFaces || !(c.area > 0) || !(c.normalSum.Norm() > 0)) continue;
    plane[r] = Plane{c.centroidSum / c.area, c.normalSum / c.normalSum.Norm()};
    basis[r] = detail::inPlaneBasis(plane[r].normal);
  }
  forEachCoreFace([&](detail::CoreMoments &c, const Plane &p, int r, const Vec3 &n, const Vec3 &x) {
    if (p.normal.SquaredNorm() == 0) return;
    const double area = n.Norm();
    const Vec3 d = x - p.point;
    const double h = d * p.normal, u = d * basis[r][0], w = d * basis[r][1];
    c.distance2 += h * h * area;
    c.xx += u * u * area, c.xy += u * w * area, c.yy += w * w * area;
  });
  for (int r = 0; r < regions; ++r)
    if (plane[r].normal.SquaredNorm() > 0)
      axes[r] = detail::principalAxes(basis[r], core[r].xx, core[r].xy, core[r].yy);
  forEachCoreFace([&](detail::CoreMoments &c, const Plane &p, int r, const Vec3 &n, const Vec3 &x) {
    if (p.normal.SquaredNorm() == 0) return;
    for (int k = 0; k < 2; ++k) c.halfNormals[2 * k + ((x - p.point) * axes[r][k] > 0)] += n;
  });
  for (int r = 0; r < regions; ++r)
    if (plane[r].normal.SquaredNorm() > 0 && !detail::coreIsPlane(core[r], spacing, s))
      plane[r] = none;
  return plane;
}

/// +1 when the faces of the closed mesh `m` face outwards (its signed
/// volume is positive), else -1: the side of a plane that is outside.
template <class MeshType>
int outwardSign(const MeshType &m) {
  double volume6 = 0;
  for (const auto &f : m.face)
    if (!f.IsD()) volume6 += positionOf(f.cV(0)) * (positionOf(f.cV(1)) ^ positionOf(f.cV(2)));
  return volume6 >= 0 ? 1 : -1;
}

namespace detail {

/// The vertices zones labels (a vertex added since has no label).
template <class MeshType>
std::size_t labelledVertices(const MeshType &m, const FeatureZones &zones) {
  return std::min({zones.vertexLabel.size(), zones.inRegion.size(), m.vert.size()});
}

/// Whether `target`, on region r's plane, lies on the region's face: on the
/// side of every other planar region's plane labelling a vertex of `around`
/// where region r's own vertices of `around` lie (their centre). False when
/// `around` holds none of them.
template <class MeshType>
bool onRegionFace(const MeshType &m, const FeatureZones &zones,
                  const std::vector<Plane> &regionPlanes, int r, const Vec3 &target,
                  const std::vector<std::size_t> &around) {
  const std::size_t nv = labelledVertices(m, zones);
  Vec3 ownSum(0, 0, 0);
  int own = 0;
  for (const std::size_t u : around)
    if (u < nv && zones.inRegion[u] && zones.vertexLabel[u] == r)
      ownSum += positionOf(&m.vert[u]), ++own;
  if (own == 0) return false;
  const Vec3 ownCentre = ownSum / double(own);
  for (const std::size_t u : around) {
    const int other = u < nv ? zones.vertexLabel[u] : kZone;
    const Plane *otherPlane = other != r ? regionPlaneOf(regionPlanes, other) : nullptr;
    if (otherPlane && !onSideOf(*otherPlane, target, ownCentre)) return false;
  }
  return true;
}

/// The planes of the planar regions that have own vertices in `around`,
/// turned to face outwards (`outward`: outwardSign). Empty when two of them
/// meet at a concave edge there (the centre of one's own vertices of
/// `around` lies outside the other's plane by more than `slack`): beside a
/// concave edge the solid reaches beyond each plane.
template <class MeshType>
std::vector<Plane> convexPlanesAround(const MeshType &m, const FeatureZones &zones,
                                      const std::vector<Plane> &regionPlanes,
                                      const std::vector<std::size_t> &around, int outward,
                                      double slack) {
  const std::size_t nv = labelledVertices(m, zones);
  std::vector<int> regions;
  std::vector<Vec3> centres;
  std::vector<int> counts;
  for (const std::size_t u : around) {
    if (u >= nv || !zones.inRegion[u] || !regionPlaneOf(regionPlanes, zones.vertexLabel[u]))
      continue;
    const int r = zones.vertexLabel[u];
    const auto k = std::size_t(std::find(regions.begin(), regions.end(), r) - regions.begin());
    if (k == regions.size())
      regions.push_back(r), centres.emplace_back(0, 0, 0), counts.push_back(0);
    centres[k] += positionOf(&m.vert[u]);
    ++counts[k];
  }
  std::vector<Plane> planes;
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const Plane &plane = *regionPlaneOf(regionPlanes, regions[k]);
    planes.push_back(Plane{plane.point, plane.normal * double(outward)});
    centres[k] /= double(counts[k]);
  }
  for (std::size_t a = 0; a < planes.size(); ++a)
    for (std::size_t b = 0; b < planes.size(); ++b)
      if (a != b && planes[b].normal * (centres[a] - planes[b].point) > slack) return {};
  return planes;
}

/// Where flattenPlanarRegions moves vertex `v` that a fused scan bulged
/// beyond a convex edge or corner: the nearest point behind the planes of
/// the planar regions around it (convexPlanesAround, at least two: one plane
/// alone does not show that the solid lies behind it there), when `v` lies
/// outside one of them by more than `minMove` and none by more than
/// `maxMove`, and that point lies within twice `maxMove` (planes meeting at
/// an acute edge put it far). Nothing, too, when an own vertex of `v`'s
/// region in `around` lies farther than `maxMove` outside one: the region's
/// own shape (a boss on a face) rises there, not a bulge.
template <class MeshType>
std::optional<Vec3> behindConvexPlanes(const MeshType &m, const FeatureZones &zones,
                                       const std::vector<Plane> &regionPlanes, std::size_t v,
                                       const std::vector<std::size_t> &around, double minMove,
                                       double maxMove, int outward) {
  const std::vector<Plane> planes =
      convexPlanesAround(m, zones, regionPlanes, around, outward, minMove);
  if (planes.size() < 2) return std::nullopt;
  const Vec3 p = positionOf(&m.vert[v]);
  const auto farthestOutside = [&](const Vec3 &x) {
    double farthest = -std::numeric_limits<double>::infinity();
    for (const Plane &plane : planes)
      farthest = std::max(farthest, plane.normal * (x - plane.point));
    return farthest;
  };
  const double outside = farthestOutside(p);
  if (!(outside > minMove && outside <= maxMove)) return std::nullopt;
  const int r = zones.vertexLabel[v];
  const std::size_t nv = labelledVertices(m, zones);
  if (r >= 0)
    for (const std::size_t u : around)
      if (u < nv && zones.inRegion[u] && zones.vertexLabel[u] == r &&
          farthestOutside(positionOf(&m.vert[u])) > maxMove)
        return std::nullopt;
  const std::optional<Vec3> target =
      nearestPointBehindPlanes(p, planes, minMove, RoughInputRules::kFlattenParallelAngleRad);
  if (!target || !((*target - p).Norm() <= 2 * maxMove)) return std::nullopt;
  return target;
}

}  // namespace detail

/// Moves each vertex labelled with a region that is a plane (`regionPlanes`,
/// from planarRegionPlanes; zero normal: not a plane), a region's own vertex
/// or a zone vertex, onto that plane when it lies outside it (on the side its
/// normal times `outward` points to: outwardSign) by more than `minMove` and
/// at most `maxMove`, and when the point it moves to is on the region's face:
/// on the side of every other region's plane nearby (RoughInputRules::kFlattenRings) where the
/// region's own vertices nearby lie (onSideOf). A fused scan (a TSDF)
/// inflates its planes and bulges them outwards for a few samples beside
/// every edge; the regions' cores fix the planes. A vertex inside its plane
/// stays: a convex blend or bevel lies inside the planes it joins. So do
/// vertices with none of their region's own vertices nearby and vertices
/// farther off (the region's own shape). Beside a convex edge or corner the
/// bulge also rises beyond the other face's plane, or its vertices take the
/// label of a small region that is no plane, or none: a vertex whose place
/// on its own plane lies off its face, and a vertex of no planar region,
/// moves to the nearest point behind the planes of the planar regions
/// around it (RoughInputRules::kFlattenCornerRings; detail::behindConvexPlanes). That point
/// lies nearer every point of the solid behind them than the vertex did.
/// Decided on the positions as they were. `vf`: the faces of each vertex of
/// `m` as it is. `onBetterPlane`: per vertex, 1 when a better estimate of
/// its face's plane has placed it already; it is then not moved onto the
/// plane `zones` labels it with, only behind the convex planes around it
/// (empty: none). \return the number moved.
template <class MeshType>
std::size_t flattenPlanarRegions(MeshType &m, const VertexFaceTable &vf, const FeatureZones &zones,
                                 const std::vector<Plane> &regionPlanes, double minMove,
                                 double maxMove, int outward,
                                 const std::vector<char> &onBetterPlane = {}) {
  using Scalar = typename MeshType::ScalarType;
  const std::int64_t nv = std::int64_t(detail::labelledVertices(m, zones));
  // Contiguous ranges of vertices decided on every core, each range's moves
  // made after all are decided (the same for any thread count).
  const int ranges = nv > kParallelMin ? detail::maxThreads() : 1;
  std::vector<detail::PerThread<std::vector<std::pair<std::size_t, Vec3>>>> movesOf(ranges);
#pragma omp parallel for schedule(static, 1) num_threads(ranges)
  for (int t = 0; t < ranges; ++t) {
    auto &moves = movesOf[t].value;
    std::vector<std::uint32_t> mark(m.vert.size(), 0);
    std::vector<std::size_t> around, ring, next;
    std::uint32_t walk = 0;
    const auto walkAround = [&](std::size_t v, int rings) {
      around.assign(1, v);
      detail::forEachRing(m, vf, v, rings, mark, ++walk, ring, next, [&](const auto &ringVertices) {
        around.insert(around.end(), ringVertices.begin(), ringVertices.end());
        return true;
      });
    };
    for (std::int64_t vi = nv * t / ranges; vi < nv * (t + 1) / ranges; ++vi) {
      const std::size_t v = std::size_t(vi);
      if (m.vert[v].IsD()) continue;
      const int r = zones.vertexLabel[v];
      const bool placed = !onBetterPlane.empty() && onBetterPlane[v];
      if (const Plane *own = placed ? nullptr : regionPlaneOf(regionPlanes, r)) {
        const Vec3 p = positionOf(&m.vert[v]);
        const double offset = own->normal * (p - own->point);
        if (!(outward * offset > minMove && std::abs(offset) <= maxMove)) continue;
        const Vec3 target = p - own->normal * offset;
        walkAround(v, RoughInputRules::kFlattenRings);
        if (detail::onRegionFace(m, zones, regionPlanes, r, target, around)) {
          moves.emplace_back(v, target);
          continue;
        }
      }
      walkAround(v, RoughInputRules::kFlattenCornerRings);
      if (const std::optional<Vec3> target = detail::behindConvexPlanes(
              m, zones, regionPlanes, v, around, minMove, maxMove, outward))
        moves.emplace_back(v, *target);
    }
  }
  std::size_t moved = 0;
  for (const auto &part : movesOf) {
    for (const auto &[v, target] : part.value)
      m.vert[v].P() = vcg::Point3<Scalar>::Construct(target);
    moved += part.value.size();
  }
  return moved;
}

}  // namespace edge_sharpener
