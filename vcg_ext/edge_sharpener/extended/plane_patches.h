// Auto method, on a rough input left whole: planes grown face by face,
// independent of the feature zones' segmentation. A fused scan rounds its
// edges so smoothly that the segmentation can merge two faces of a solid
// into one region across the edge, which is then no plane
// (planarRegionPlanes); grown from its flattest faces, each face is a patch
// of its own, and flattenPlanarRegions reads the patches as it reads the
// regions.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <numeric>
#include <vector>

#include "../util/geometry.h"
#include "../util/vertex_faces.h"
#include "planar_regions.h"
#include "zones.h"

namespace edge_sharpener {

/// How growPlanePatches grows and keeps a patch.
struct PlanePatchSettings {
  /// A face joins when its normal turns from the patch's plane by less than
  /// a feature's angle (the auto method's minFeatureAngleRad)...
  double maxTurnRad = 20.0 * M_PI / 180.0;
  /// ...and its vertices lie within this distance of the plane (in sample
  /// spacings): the noise of a scan's face, not the bulge beside its edges.
  double maxDistanceSpacings = 0.5;
  /// A patch smaller than this (in square sample spacings) tells nothing:
  /// the bulge beside an edge is itself nearly flat for a few samples.
  double minAreaSpacings2 = 60.0;
  /// A patch's plane is fitted again without its faces farther from it than
  /// this multiple of their RMS distance (fitPlaneTrimmed).
  double trimRmsFactor = 1.5;
  /// A kept patch is a plane by the regions' tests (RMS distance, bend).
  PlanarRegionSettings planarity;
  /// A patch stays only when another within `pairRings` face rings of it
  /// meets it at a feature's angle or more: the faces of a solid meet at
  /// edges, while pieces of a curved surface bend gently into each other.
  double pairAngleRad = 20.0 * M_PI / 180.0;
  int pairRings = kFlattenCornerRings;
};

/// The patches: FeatureZones labels as flattenPlanarRegions reads them
/// (faceRegion: the patch or kZone; vertexLabel: the patch holding most of a
/// vertex's face area, or kZone; inRegion: a vertex of some patch's face)
/// and, per patch, its plane (a zero normal: dropped).
struct PlanePatches {
  FeatureZones labels;
  std::vector<Plane> planes;

  std::size_t count() const {
    return std::size_t(std::count_if(planes.begin(), planes.end(),
                                     [](const Plane &p) { return p.normal.SquaredNorm() > 0; }));
  }
};

namespace detail {

/// A face's centroid, and its normal times its area.
template <class MeshType>
Vec3 faceCentre(const MeshType &m, std::size_t fi) {
  const auto &f = m.face[fi];
  return (positionOf(f.cV(0)) + positionOf(f.cV(1)) + positionOf(f.cV(2))) / 3.0;
}
template <class MeshType>
Vec3 faceAreaNormal(const MeshType &m, std::size_t fi) {
  const auto &f = m.face[fi];
  const Vec3 p0 = positionOf(f.cV(0));
  return ((positionOf(f.cV(1)) - p0) ^ (positionOf(f.cV(2)) - p0)) / 2.0;
}

/// The plane of the faces `members` of `m`: least squares on their centroids,
/// weighted by `area`, trimmed (fitPlaneTrimmed), its normal on the side of
/// `towards`.
template <class MeshType>
Plane fitPatchPlane(const MeshType &m, const std::vector<std::uint32_t> &members,
                    const std::vector<float> &area, const Vec3 &towards, double trimRmsFactor) {
  std::vector<Vec3> centres;
  std::vector<double> weights;
  centres.reserve(members.size());
  weights.reserve(members.size());
  for (const std::uint32_t g : members) {
    centres.push_back(faceCentre(m, g));
    weights.push_back(area[g]);
  }
  return fitPlaneTrimmed(centres, weights, towards, trimRmsFactor);
}

/// Whether the faces `members` of `m` make a plane by the regions' tests
/// (coreIsPlane): their moments about `plane`, the halves split across
/// either principal axis of their extent.
template <class MeshType>
bool patchIsPlane(const MeshType &m, const std::vector<std::uint32_t> &members, const Plane &plane,
                  double spacing, const PlanarRegionSettings &s) {
  CoreMoments c;
  const std::array<Vec3, 2> basis = inPlaneBasis(plane.normal);
  for (const std::uint32_t g : members) {
    const Vec3 d = faceCentre(m, g) - plane.point;
    const double area = faceAreaNormal(m, g).Norm();
    const double h = d * plane.normal, u = d * basis[0], w = d * basis[1];
    c.area += area;
    c.distance2 += h * h * area;
    c.xx += u * u * area, c.xy += u * w * area, c.yy += w * w * area;
  }
  const std::array<Vec3, 2> axes = principalAxes(basis, c.xx, c.xy, c.yy);
  for (const std::uint32_t g : members)
    for (int k = 0; k < 2; ++k)
      c.halfNormals[2 * k + ((faceCentre(m, g) - plane.point) * axes[k] > 0)] +=
          faceAreaNormal(m, g);
  return coreIsPlane(c, spacing, s);
}

}  // namespace detail

/// Planes grown on `m` face by face: from the flattest face not yet taken (the
/// largest turn to its neighbours least), a patch takes the neighbours that
/// turn little from its plane and whose vertices lie near it
/// (PlanePatchSettings), its plane refitted as its area doubles (area-weighted
/// centroid and normal) and, once grown, by least squares (fitPatchPlane: the
/// normals of a scan's faces tilt with its noise). A patch too small or no
/// plane gives its faces back (they seed no other). Then a patch with no
/// other meeting it at an edge's angle nearby is dropped, until none is.
/// `vf`: the faces of each vertex; `spacing`: the sample spacing.
/// Deterministic: faces in order of flatness, ties in face order. \pre the
/// face-face adjacency of `m` is up to date (sharpen() keeps it so).
template <class MeshType>
PlanePatches growPlanePatches(const MeshType &m, const VertexFaceTable &vf, double spacing,
                              const PlanePatchSettings &s) {
  const std::size_t nf = m.face.size(), nv = m.vert.size();
  // Per face: its unit normal (zero: deleted or degenerate) and area, in
  // single precision (angles and weights only; the planes are fitted in double).
  std::vector<vcg::Point3f> unitNormal(nf, vcg::Point3f(0, 0, 0));
  std::vector<float> area(nf, 0);
  for (std::size_t fi = 0; fi < nf; ++fi) {
    if (m.face[fi].IsD()) continue;
    const Vec3 n = detail::faceAreaNormal(m, fi);
    if (!(n.Norm() > 0)) continue;
    area[fi] = float(n.Norm());
    unitNormal[fi] = vcg::Point3f::Construct(n / n.Norm());
  }
  const auto normal = [&](std::size_t fi) { return Vec3::Construct(unitNormal[fi]); };
  // The faces across face fi's three edges (-1: a border).
  const auto across = [&](std::size_t fi) {
    std::array<std::int64_t, 3> faces{-1, -1, -1};
    for (int k = 0; k < 3; ++k)
      if (const auto *g = m.face[fi].cFFp(k); g != &m.face[fi])
        faces[k] = std::int64_t(vcg::tri::Index(m, g));
    return faces;
  };
  std::vector<float> turn(nf, float(M_PI));
  for (std::size_t fi = 0; fi < nf; ++fi) {
    if (!(area[fi] > 0)) continue;
    double largest = 0;
    for (const std::int64_t g : across(fi))
      if (g >= 0) largest = std::max(largest, angleBetween(normal(fi), normal(g)));
    turn[fi] = float(largest);
  }
  std::vector<std::uint32_t> order(nf);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return turn[a] < turn[b]; });

  PlanePatches out;
  std::vector<int> patch(nf, kZone);
  std::vector<std::uint32_t> seen(nf, 0);  // the last walk that looked at a face
  std::vector<char> maySeed(nf, 1);
  std::vector<std::vector<std::uint32_t>> members;
  std::deque<std::uint32_t> queue;
  const double maxDistance = s.maxDistanceSpacings * spacing;
  std::uint32_t walk = 0;
  for (const std::uint32_t seed : order) {
    if (patch[seed] != kZone || !maySeed[seed] || !(area[seed] > 0) || turn[seed] > s.maxTurnRad)
      continue;
    const int id = int(out.planes.size());
    ++walk;
    Plane plane{detail::faceCentre(m, seed), normal(seed)};
    Vec3 centreSum = plane.point * area[seed], normalSum = plane.normal * area[seed];
    double areaSum = area[seed], fittedArea = area[seed];
    std::vector<std::uint32_t> faces{seed};
    patch[seed] = id;
    seen[seed] = walk;
    queue.assign(1, seed);
    const auto joins = [&](std::uint32_t g) {
      if (angleBetween(normal(g), plane.normal) > s.maxTurnRad) return false;
      for (int k = 0; k < 3; ++k)
        if (std::abs(plane.normal * (positionOf(m.face[g].cV(k)) - plane.point)) > maxDistance)
          return false;
      return true;
    };
    while (!queue.empty()) {
      const std::uint32_t fi = queue.front();
      queue.pop_front();
      for (const std::int64_t g : across(fi)) {
        if (g < 0 || patch[g] != kZone || seen[g] == walk || !(area[g] > 0)) continue;
        seen[g] = walk;
        if (!joins(std::uint32_t(g))) continue;
        patch[g] = id;
        faces.push_back(std::uint32_t(g));
        queue.push_back(std::uint32_t(g));
        centreSum += detail::faceCentre(m, g) * area[g];
        normalSum += normal(g) * area[g];
        areaSum += area[g];
        if (areaSum > 2 * fittedArea) {
          plane = Plane{centreSum / areaSum, normalSum / normalSum.Norm()};
          fittedArea = areaSum;
        }
      }
    }
    // A patch too small is given back without being fitted.
    const bool large = areaSum >= s.minAreaSpacings2 * spacing * spacing;
    if (large) plane = detail::fitPatchPlane(m, faces, area, normalSum, s.trimRmsFactor);
    if (!large || !detail::patchIsPlane(m, faces, plane, spacing, s.planarity)) {
      for (const std::uint32_t g : faces) patch[g] = kZone, maySeed[g] = 0;
      plane = Plane{Vec3(0, 0, 0), Vec3(0, 0, 0)};
      faces.clear();
    }
    out.planes.push_back(plane);
    members.push_back(std::move(faces));
  }

  // Drop the patches with no partner at an edge nearby, until none is dropped.
  std::vector<std::uint32_t> front, next;
  for (bool dropped = true; dropped;) {
    dropped = false;
    std::vector<char> partnered(out.planes.size(), 0);
    for (int id = 0; id < int(out.planes.size()); ++id) {
      if (members[id].empty()) continue;
      const Vec3 &n = out.planes[id].normal;
      front = members[id];
      ++walk;
      for (const std::uint32_t g : front) seen[g] = walk;
      for (int ring = 0; ring < s.pairRings && !partnered[id] && !front.empty(); ++ring) {
        next.clear();
        for (const std::uint32_t f : front)
          for (const std::int64_t g : across(f)) {
            if (g < 0 || seen[g] == walk) continue;
            seen[g] = walk;
            next.push_back(std::uint32_t(g));
            const int q = patch[g];
            if (q >= 0 && q != id && angleBetween(out.planes[q].normal, n) >= s.pairAngleRad)
              partnered[id] = 1;
          }
        front.swap(next);
      }
    }
    for (int id = 0; id < int(out.planes.size()); ++id)
      if (!members[id].empty() && !partnered[id]) {
        for (const std::uint32_t g : members[id]) patch[g] = kZone;
        members[id].clear();
        out.planes[id] = Plane{Vec3(0, 0, 0), Vec3(0, 0, 0)};
        dropped = true;
      }
  }

  FeatureZones &z = out.labels;
  z.vertexLabel.assign(nv, kZone);
  z.inRegion.assign(nv, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    double most = 0;
    for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v); ++fi) {
      const int p = patch[*fi];
      if (p < 0) continue;
      z.inRegion[v] = 1;
      double sum = 0;
      for (const std::uint32_t *g = vf.begin(v); g != vf.end(v); ++g)
        if (patch[*g] == p) sum += area[*g];
      if (sum > most) most = sum, z.vertexLabel[v] = p;
    }
  }
  z.faceRegion = std::move(patch);
  return out;
}

}  // namespace edge_sharpener
