// Extended method, after placement: the zone vertices beside a sharpened
// edge moved onto their region's plane (or a neighbouring region's, where
// that one cannot take them).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "../options.h"
#include "../report.h"
#include "../util/geometry.h"
#include "../util/qef.h"
#include "../util/vertex_faces.h"
#include "zones.h"

namespace edge_sharpener {

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

/// The planes a zone vertex v may be projected onto, in the order they are
/// tried: its own region's, then those of the other regions found near it
/// (SupportPlanes::nearby, closest first). \return how many were written.
inline int projectionPlanes(const SupportPlanes &support, std::size_t v,
                            std::array<const Plane *, 4> &planes) {
  int count = 0;
  planes[count++] = &support.plane(v);
  if (v < support.nearby.size())
    for (const std::uint32_t u : support.nearby[v]) {
      if (u == SupportPlanes::kNoVertex) break;
      if (support.plane(u).normal.SquaredNorm() > 0) planes[count++] = &support.plane(u);
    }
  return count;
}

/// Whether a point moved from `from` to `to` lies no farther (beyond
/// `tolerance`) from any of the first `count` planes than it did: a zone
/// vertex inside a corner, off all its planes, may land on a neighbour's
/// plane only where that leaves it as near the others. Zero normals are
/// skipped. Pure.
inline bool noFartherFromPlanes(const std::array<const Plane *, 4> &planes, int count,
                                const Vec3 &from, const Vec3 &to, double tolerance) {
  for (int i = 0; i < count; ++i) {
    const Plane &pl = *planes[i];
    if (pl.normal.SquaredNorm() == 0) continue;
    if (std::abs(pl.normal * (to - pl.point)) > std::abs(pl.normal * (from - pl.point)) + tolerance)
      return false;
  }
  return true;
}

}  // namespace detail

/// Moves each labelled zone vertex (an original vertex outside every region)
/// that borders a sharpened edge (`nearSharpEdge`) onto its region's plane,
/// the surface it samples: marching cubes and similar samplers leave such
/// vertices on the rounded band. A move longer
/// than `opt.extended.maxProjectionFactor` x the vertex's mean edge length, or one
/// that would flip an incident face or create an angle below the
/// degenerate threshold, is not made. Then the planes of the other regions
/// near it are tried, closest first, where the move leaves the vertex no
/// farther from any of its planes (detail::noFartherFromPlanes): a voxel
/// remesher's vertex in a convex corner's cell lies off all three faces,
/// and once the corner is restored its own plane would fold a face, while
/// another face's plane takes it. Last, the lines where its own plane meets
/// each of the others (their QEF, where it has rank two): a vertex on the
/// restored edge itself, which either plane alone would carry across the new
/// vertices on that line. A vertex no plane or line takes stays (counted in
/// stats.projectionsRejected;
/// the moves the guards leave are counted at the end, from VertexMoves).
/// Region vertices never move.
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
    const Vec3 p = positionOf(&m.vert[v]);
    std::array<const Plane *, 4> planes;
    const int planeCount = detail::projectionPlanes(zones.support, v, planes);
    // A move below the mesh's float resolution changes nothing: not counted.
    if (vcg::Point3<Scalar>::Construct(projectOntoPlane(*planes[0], p)) == m.vert[v].cP()) continue;
    const double maxStep =
        detail::maxProjectionStep(m, faces, v, p, opt.extended.maxProjectionFactor);
    const double tolerance = 1e-9 * zones.support.sampleSpacing;
    // A target within the step bound that folds no face; beyond the vertex's
    // own plane, also no farther from any of its other planes.
    const auto takes = [&](const Vec3 &target, bool ownPlane, std::size_t firstInserted) {
      return (target - p).Norm() <= maxStep &&
             (ownPlane || detail::noFartherFromPlanes(planes, planeCount, p, target, tolerance)) &&
             detail::moveKeepsFaces(m, faces, v, target, opt.degenerateAngleRad, firstInserted);
    };
    std::optional<Vec3> chosen;
    for (int i = 0; i < planeCount && !chosen; ++i) {
      const Vec3 target = projectOntoPlane(*planes[i], p);
      if (takes(target, /*ownPlane=*/i == 0, /*firstInserted=*/0)) chosen = target;
    }
    for (int i = 1; i < planeCount && !chosen; ++i) {
      const QefSolution line = solveQef({*planes[0], *planes[i]}, {}, p);
      if (line.rank == 2 && takes(line.point, /*ownPlane=*/false, originalCount))
        chosen = line.point;
    }
    if (!chosen) {
      ++stats.projectionsRejected;
      continue;
    }
    m.vert[v].P() = vcg::Point3<Scalar>::Construct(*chosen);
    ++moved;
  }
  return moved;
}

}  // namespace edge_sharpener
