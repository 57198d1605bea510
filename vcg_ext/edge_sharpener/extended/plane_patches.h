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

/// Per face: its unit normal (zero: deleted or degenerate) and area, in
/// single precision (angles and weights only; the planes are fitted in double).
struct PatchFaces {
  std::vector<vcg::Point3f> unitNormal;
  std::vector<float> area;

  Vec3 normal(std::size_t fi) const { return Vec3::Construct(unitNormal[fi]); }
};

template <class MeshType>
PatchFaces patchFaces(const MeshType &m) {
  const std::size_t nf = m.face.size();
  PatchFaces faces{std::vector<vcg::Point3f>(nf, vcg::Point3f(0, 0, 0)), std::vector<float>(nf, 0)};
  for (std::size_t fi = 0; fi < nf; ++fi) {
    if (m.face[fi].IsD()) continue;
    const Vec3 n = faceAreaNormal(m, fi);
    if (!(n.Norm() > 0)) continue;
    faces.area[fi] = float(n.Norm());
    faces.unitNormal[fi] = vcg::Point3f::Construct(n / n.Norm());
  }
  return faces;
}

/// The faces across face fi's three edges (-1: a border).
template <class MeshType>
std::array<std::int64_t, 3> facesAcross(const MeshType &m, std::size_t fi) {
  std::array<std::int64_t, 3> faces{-1, -1, -1};
  for (int k = 0; k < 3; ++k)
    if (const auto *g = m.face[fi].cFFp(k); g != &m.face[fi])
      faces[k] = std::int64_t(vcg::tri::Index(m, g));
  return faces;
}

/// Per face, the largest angle its normal turns to a neighbour's (pi: a face
/// with no area): how flat the surface is around it.
template <class MeshType>
std::vector<float> largestTurns(const MeshType &m, const PatchFaces &faces) {
  std::vector<float> turn(m.face.size(), float(M_PI));
  for (std::size_t fi = 0; fi < m.face.size(); ++fi) {
    if (!(faces.area[fi] > 0)) continue;
    double largest = 0;
    for (const std::int64_t g : facesAcross(m, fi))
      if (g >= 0) largest = std::max(largest, angleBetween(faces.normal(fi), faces.normal(g)));
    turn[fi] = float(largest);
  }
  return turn;
}

/// The faces, flattest first; ties in face order (deterministic).
inline std::vector<std::uint32_t> flattestFirst(const std::vector<float> &turn) {
  std::vector<std::uint32_t> order(turn.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return turn[a] < turn[b]; });
  return order;
}

/// Visit stamps of walks over the faces: a face is new to a walk until it
/// is visited. One array serves every walk, with no clearing in between.
struct FaceWalks {
  std::vector<std::uint32_t> seen;  // the last walk that looked at a face
  std::uint32_t walk = 0;

  explicit FaceWalks(std::size_t faceCount) : seen(faceCount, 0) {}
  void start() { ++walk; }
  /// Whether face f is new to this walk; it is not afterwards.
  bool visit(std::size_t f) {
    if (seen[f] == walk) return false;
    seen[f] = walk;
    return true;
  }
};

/// The patches found so far: per face its patch (or kZone), per patch its
/// faces and plane (no faces and a zero plane: given back or dropped).
struct PatchSet {
  std::vector<int> patch;
  std::vector<char> maySeed;  // a face given back seeds no patch
  std::vector<std::vector<std::uint32_t>> members;
  std::vector<Plane> planes;
  FaceWalks walks;

  explicit PatchSet(std::size_t faceCount)
      : patch(faceCount, kZone), maySeed(faceCount, 1), walks(faceCount) {}
};

/// A patch as it grows: its faces, its plane, and the area-weighted sums of
/// its faces' centroids and normals its plane is refitted from.
struct GrowingPatch {
  std::vector<std::uint32_t> faces;
  Plane plane;
  Vec3 centreSum, normalSum;
  double areaSum, fittedArea;
};

template <class MeshType>
GrowingPatch seedPatch(const MeshType &m, const PatchFaces &faces, std::uint32_t seed) {
  GrowingPatch p;
  p.faces = {seed};
  p.plane = Plane{faceCentre(m, seed), faces.normal(seed)};
  p.centreSum = p.plane.point * faces.area[seed], p.normalSum = p.plane.normal * faces.area[seed];
  p.areaSum = faces.area[seed], p.fittedArea = faces.area[seed];
  return p;
}

/// Adds face g to the sums; the plane is refitted to them each time the
/// area doubles (often enough to follow the patch, seldom enough to stay
/// cheap).
template <class MeshType>
void addToPatch(const MeshType &m, const PatchFaces &faces, std::uint32_t g, GrowingPatch &p) {
  p.faces.push_back(g);
  p.centreSum += faceCentre(m, g) * faces.area[g];
  p.normalSum += faces.normal(g) * faces.area[g];
  p.areaSum += faces.area[g];
  if (p.areaSum > 2 * p.fittedArea) {
    p.plane = Plane{p.centreSum / p.areaSum, p.normalSum / p.normalSum.Norm()};
    p.fittedArea = p.areaSum;
  }
}

/// Whether face g turns little from `plane` and its vertices lie within
/// `maxDistance` of it.
template <class MeshType>
bool joinsPatch(const MeshType &m, const PatchFaces &faces, std::uint32_t g, const Plane &plane,
                double maxTurnRad, double maxDistance) {
  if (angleBetween(faces.normal(g), plane.normal) > maxTurnRad) return false;
  for (int k = 0; k < 3; ++k)
    if (std::abs(plane.normal * (positionOf(m.face[g].cV(k)) - plane.point)) > maxDistance)
      return false;
  return true;
}

/// Patch `id` grown breadth-first from `seed` over the faces no patch holds,
/// each face looked at once; its faces are labelled `id` in `set`.
template <class MeshType>
GrowingPatch growPatch(const MeshType &m, const PatchFaces &faces, std::uint32_t seed, int id,
                       double maxDistance, const PlanePatchSettings &s, PatchSet &set) {
  set.walks.start();
  GrowingPatch p = seedPatch(m, faces, seed);
  set.patch[seed] = id;
  set.walks.visit(seed);
  std::deque<std::uint32_t> queue{seed};
  while (!queue.empty()) {
    const std::uint32_t fi = queue.front();
    queue.pop_front();
    for (const std::int64_t g : facesAcross(m, fi)) {
      if (g < 0 || set.patch[g] != kZone || !(faces.area[g] > 0) || !set.walks.visit(g)) continue;
      if (!joinsPatch(m, faces, std::uint32_t(g), p.plane, s.maxTurnRad, maxDistance)) continue;
      set.patch[g] = id;
      queue.push_back(std::uint32_t(g));
      addToPatch(m, faces, std::uint32_t(g), p);
    }
  }
  return p;
}

/// Whether grown patch `p` stays: large enough, and a plane by the regions'
/// tests once fitted by least squares (fitPatchPlane; its plane is then
/// that fit). A patch too small is given back without being fitted.
template <class MeshType>
bool settlePatch(const MeshType &m, const PatchFaces &faces, double spacing,
                 const PlanePatchSettings &s, GrowingPatch &p) {
  if (!(p.areaSum >= s.minAreaSpacings2 * spacing * spacing)) return false;
  p.plane = fitPatchPlane(m, p.faces, faces.area, p.normalSum, s.trimRmsFactor);
  return patchIsPlane(m, p.faces, p.plane, spacing, s.planarity);
}

/// A patch's faces back to the zone, its plane zeroed.
inline void givePatchBack(PatchSet &set, std::size_t id) {
  for (const std::uint32_t g : set.members[id]) set.patch[g] = kZone;
  set.members[id].clear();
  set.planes[id] = Plane{Vec3(0, 0, 0), Vec3(0, 0, 0)};
}

/// The patches grown from each flat enough face no patch holds, flattest
/// first. A patch that does not stay gives its faces back, and they seed
/// no other.
template <class MeshType>
PatchSet growPatches(const MeshType &m, const PatchFaces &faces, const std::vector<float> &turn,
                     double spacing, const PlanePatchSettings &s) {
  PatchSet set(m.face.size());
  const double maxDistance = s.maxDistanceSpacings * spacing;
  for (const std::uint32_t seed : flattestFirst(turn)) {
    if (set.patch[seed] != kZone || !set.maySeed[seed] || !(faces.area[seed] > 0) ||
        turn[seed] > s.maxTurnRad)
      continue;
    const int id = int(set.planes.size());
    GrowingPatch p = growPatch(m, faces, seed, id, maxDistance, s, set);
    const bool stays = settlePatch(m, faces, spacing, s, p);
    set.planes.push_back(p.plane);
    set.members.push_back(std::move(p.faces));
    if (stays) continue;
    for (const std::uint32_t g : set.members[id]) set.maySeed[g] = 0;
    givePatchBack(set, id);
  }
  return set;
}

/// Whether another patch within s.pairRings face rings of patch `id` meets
/// it at a feature's angle or more (the faces of a solid meet at edges).
template <class MeshType>
bool hasPartnerNearby(const MeshType &m, int id, const PlanePatchSettings &s, PatchSet &set) {
  const Vec3 &n = set.planes[id].normal;
  std::vector<std::uint32_t> front = set.members[id], next;
  set.walks.start();
  for (const std::uint32_t g : front) set.walks.visit(g);
  bool partnered = false;
  for (int ring = 0; ring < s.pairRings && !partnered && !front.empty(); ++ring) {
    next.clear();
    for (const std::uint32_t f : front)
      for (const std::int64_t g : facesAcross(m, f)) {
        if (g < 0 || !set.walks.visit(g)) continue;
        next.push_back(std::uint32_t(g));
        const int q = set.patch[g];
        if (q >= 0 && q != id && angleBetween(set.planes[q].normal, n) >= s.pairAngleRad)
          partnered = true;
      }
    front.swap(next);
  }
  return partnered;
}

/// Drops the patches with no partner at an edge nearby, until none is
/// dropped (a dropped patch may have been another's only partner).
template <class MeshType>
void dropUnpartneredPatches(const MeshType &m, const PlanePatchSettings &s, PatchSet &set) {
  for (bool dropped = true; dropped;) {
    dropped = false;
    std::vector<char> partnered(set.planes.size(), 0);
    for (int id = 0; id < int(set.planes.size()); ++id)
      if (!set.members[id].empty()) partnered[id] = hasPartnerNearby(m, id, s, set);
    for (std::size_t id = 0; id < set.planes.size(); ++id)
      if (!set.members[id].empty() && !partnered[id]) {
        givePatchBack(set, id);
        dropped = true;
      }
  }
}

/// The area of vertex v's faces in patch p.
inline double patchAreaAt(const VertexFaceTable &vf, std::size_t v, const std::vector<int> &patch,
                          const std::vector<float> &area, int p) {
  double sum = 0;
  for (const std::uint32_t *g = vf.begin(v); g != vf.end(v); ++g)
    if (patch[*g] == p) sum += area[*g];
  return sum;
}

/// The patches as FeatureZones labels (PlanePatches::labels).
inline FeatureZones patchLabels(const VertexFaceTable &vf, std::size_t vertexCount,
                                const std::vector<float> &area, std::vector<int> patch) {
  FeatureZones z;
  z.vertexLabel.assign(vertexCount, kZone);
  z.inRegion.assign(vertexCount, 0);
  for (std::size_t v = 0; v < vertexCount; ++v) {
    double most = 0;
    for (const std::uint32_t *fi = vf.begin(v); fi != vf.end(v); ++fi) {
      const int p = patch[*fi];
      if (p < 0) continue;
      z.inRegion[v] = 1;
      const double sum = patchAreaAt(vf, v, patch, area, p);
      if (sum > most) most = sum, z.vertexLabel[v] = p;
    }
  }
  z.faceRegion = std::move(patch);
  return z;
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
  const detail::PatchFaces faces = detail::patchFaces(m);
  const std::vector<float> turn = detail::largestTurns(m, faces);
  detail::PatchSet set = detail::growPatches(m, faces, turn, spacing, s);
  detail::dropUnpartneredPatches(m, s, set);
  PlanePatches out;
  out.planes = std::move(set.planes);
  out.labels = detail::patchLabels(vf, m.vert.size(), faces.area, std::move(set.patch));
  return out;
}

}  // namespace edge_sharpener
