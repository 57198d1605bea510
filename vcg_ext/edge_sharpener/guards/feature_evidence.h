// The auto method's evidence guard: a feature is sharpened whole or not at
// all. A feature is one chamfer strip between two regions (its inserted
// vertices joined through the input vertices they come from) or a cluster of
// corner vertices. Along a real sharp edge of a remeshed solid, placement's
// tests agree (the paper's degenerate cases, the extended method's vetoes)
// and the samples beside the edge lie on the planes its flanks extrapolate.
// Where many of the tests refuse, or a sample lies far off its plane, the
// flanks are not what placement assumed (a blend, a curved face, a thin
// wall), and the moves the tests let through are the least trustworthy: the
// feature stays as it was (do no harm), as does one too short to be a
// feature. Where the tests refuse a large part of all the moves, the input
// is not a chamfered sampling of sharp edges at all (a depth scan's fused
// surface), and where the moves mostly slide along the input instead of
// lifting it to an edge, the input is already sharp: nothing moves. A
// smooth part made of planes (surface_measures.h) may refuse more before
// that: its refusals come from its shape, which the per-feature evidence
// judges feature by feature.
#pragma once

#include <vcg/complex/complex.h>
#include <vcg/space/distance3.h>
#include <vcg/space/triangle3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <optional>
#include <vector>
// (vcglib's algorithm headers, included below, need complex.h first)

#include "../options.h"
#include "../placement.h"
#include "../report.h"
#include "../subdivision.h"
#include "../util/disjoint_sets.h"
#include "../util/fillet_fit.h"
#include "../util/non_manifold.h"
#include "../util/qef.h"
#include "../util/statistics.h"
#include "../util/vertex_faces.h"
#include "box_hash_grid.h"
#include "element_snapshot.h"
#include "surface_measures.h"
#include "vertex_moves.h"

namespace edge_sharpener {

/// One feature: inserted vertices joined through shared source vertices.
/// A sharp edge's feature holds the inserted vertices between the same two
/// regions; a corner's, those with three sources.
struct Feature {
  bool corner = false;
  std::size_t vertices = 0;  ///< inserted vertices still in the mesh
  std::size_t moved = 0;     ///< of those, placed on their planes
  /// How far its farthest source vertex lies from its own plane, in sample
  /// spacings. A remeshed sharp edge's samples lie on the planes its flanks
  /// extrapolate, up to the sampler's rounding along the edge; where a
  /// blend, a curved face or a thin wall meets the edge, some lie far off.
  double maxOffPlane = 0;
  /// The distance from their planes (sample spacings) within which nine in
  /// ten of its source vertices lie: near 0 where the sampler put its
  /// samples on the surface, whatever a few samples where it meets another
  /// part do.
  double offPlaneQ90 = 0;
  /// ...and within which half of them lie: near 0 too where a sampler
  /// rounds only the samples nearest the edge, large along a blend or a
  /// bevel.
  double offPlaneMedian = 0;
  /// Edge features: the median angle (radians, planeMeetingAngle) at which
  /// its vertices' two flank planes meet; pi/2 where none has both planes.
  double flankAngleRad = M_PI / 2;
  /// Edge features: the median angle (radians, lineAngleToSurface) between
  /// the line its vertices' flank planes meet on and its chamfer; 0 where
  /// none has both planes.
  double lineChamferAngleRad = 0;
  /// Of its moved vertices, those whose target lies nearer another sheet of
  /// the input's surface than the faces around its sources (crossesSheet).
  std::size_t crossed = 0;
  /// The median lift of its moves (moveLift; 1 when none moved): near 0
  /// where its vertices only slide along the input, already sharp there.
  double medianLift = 1;
  /// Edge features: the fillet fitted to its sources across the edge
  /// (fitFillet): its width across and the RMS of their distances to it, in
  /// sample spacings; 0 where none has both planes...
  double filletWidthSpacings = 0;
  double filletRmsSpacings = 0;
  double wedgeRmsSpacings = 0;  ///< ...and to the sharp wedge
  /// ...whether the edge is concave, its two flanks' mean normals...
  bool concave = false;
  std::array<Vec3, 2> flankNormals{Vec3(0, 0, 0), Vec3(0, 0, 0)};
  /// ...and the fillet width the sampler leaves at the edges it meets alike
  /// (measurePeerRounding): where the feature's own is wider by more than
  /// the ambiguous width, the arc is the surface's, not the sampler's.
  double peerFilletWidthSpacings = 0;
  std::size_t filletSamples = 0;  ///< the sources the fillet was fitted to
};

/// The angle (radians, in [0, pi/2]) at which two planes of unit normals
/// `a` and `b` meet: small for a shallow crease (normals nearly alike) and
/// for a knife edge (normals nearly opposite), where the line they meet on
/// moves most with an error in either plane. Pure.
inline double planeMeetingAngle(const Vec3 &a, const Vec3 &b) {
  return std::acos(std::min(std::abs(a * b), 1.0));
}

/// How far a move lifts its vertex off the input's surface, as a fraction of
/// the move's length: the target's distance to the nearest of `triangles`
/// (the input faces around the vertex's sources) over |target - rest|. Near
/// 1 where a chamfer is cut back to the edge its flanks meet at (the target
/// lies beyond every input face); near 0 where the move slides along the
/// input's surface (the input is already sharp there, and the move only
/// bends a curved face). 1 for a move of no length. Pure.
inline double moveLift(const Vec3 &target, const Vec3 &rest,
                       const std::vector<vcg::Triangle3<double>> &triangles) {
  const double length = (target - rest).Norm();
  if (!(length > 0) || triangles.empty()) return 1;
  return std::min(length, distanceToTriangles(target, triangles)) / length;
}

/// The input's surface, for measuring lifts after the subdivision: each input
/// vertex's faces (`facesOf`, built before the split) and each input face's
/// three vertices (`faceVertices`), at the vertices' rest positions.
struct InputSurface {
  const VertexFaceTable &facesOf;
  const std::vector<std::array<std::uint32_t, 3>> &faceVertices;
};

/// Groups the inserted vertices into features. `regionOf` gives each source
/// vertex's region (-1: none): an edge vertex's feature is the connected set
/// of edge vertices between the same two regions, a corner vertex's the
/// connected set of corner vertices. Where four or more regions meet, a
/// chamfered corner also holds edges between regions that touch only at the
/// corner (a pyramid's apex: its opposite faces): an edge set each of whose
/// vertices shares a source with a vertex of one corner lies inside that
/// corner's chamfer, and belongs to it. Pure: reads the split plan only.
/// \return per inserted vertex (plan.inserted order) its feature's index.
template <class RegionOf>
std::vector<std::uint32_t> groupFeatures(const SplitPlan &plan, RegionOf &&regionOf,
                                         std::vector<Feature> &features) {
  const std::size_t n = plan.inserted.size();
  const auto keyOf = [&](std::size_t k) -> std::pair<long, long> {
    const InsertedVertexSource &s = plan.inserted[k];
    if (s.originalCount != 2) return {-2, -2};  // corners join corners
    const long a = regionOf(s.original[0]), b = regionOf(s.original[1]);
    return {std::min(a, b), std::max(a, b)};
  };
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  const auto root = [&](std::uint32_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  // Per source vertex, the inserted vertices it sources (few: a chamfer
  // vertex has two or three chamfer edges and corners around it).
  std::vector<std::vector<std::uint32_t>> sourced(plan.originalVertexCount);
  for (std::uint32_t k = 0; k < n; ++k)
    for (int i = 0; i < plan.inserted[k].originalCount; ++i)
      sourced[plan.inserted[k].original[i]].push_back(k);
  for (const auto &list : sourced)
    for (std::size_t i = 0; i < list.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (keyOf(list[i]) == keyOf(list[j])) parent[root(list[i])] = root(list[j]);
  constexpr std::uint32_t kNone = ~std::uint32_t(0);
  {
    // Per edge vertex, the one corner its sources touch (kNone: none;
    // kMany: several), then per edge set, whether all of it touches one.
    constexpr std::uint32_t kMany = kNone - 1;
    const auto isCorner = [&](std::uint32_t k) { return plan.inserted[k].originalCount != 2; };
    std::vector<std::uint32_t> touched(n, kNone);
    for (const auto &list : sourced)
      for (const std::uint32_t a : list)
        for (const std::uint32_t b : list) {
          if (isCorner(a) || !isCorner(b)) continue;
          const std::uint32_t c = root(b);
          touched[a] = touched[a] == kNone || touched[a] == c ? c : kMany;
        }
    constexpr std::uint32_t kUnset = kNone - 2;
    std::vector<std::uint32_t> inside(n, kUnset);  // per edge set's root: its corner
    for (std::uint32_t k = 0; k < n; ++k) {
      if (isCorner(k)) continue;
      std::uint32_t &c = inside[root(k)];
      c = c == kUnset ? touched[k] : (c == touched[k] ? c : kMany);
    }
    for (std::uint32_t r = 0; r < n; ++r)
      if (inside[r] < kUnset) parent[r] = root(inside[r]);
  }
  std::vector<std::uint32_t> id(n, kNone), feature(n);
  features.clear();
  for (std::uint32_t k = 0; k < n; ++k) {
    std::uint32_t &r = id[root(k)];
    if (r == kNone) {
      r = std::uint32_t(features.size());
      features.emplace_back();
    }
    feature[k] = r;
    features[r].corner = features[r].corner || plan.inserted[k].originalCount != 2;
  }
  return feature;
}

/// The length the guard's distances are measured in: the sample spacing, or
/// 1 where none was measured.
inline double spacingUnit(const SupportPlanes &support) {
  return support.sampleSpacing > 0 ? support.sampleSpacing : 1.0;
}

/// How far source vertex `s` lies from its plane at its rest position, in
/// sample spacings; 0 where it has no plane.
template <class MeshType>
double offPlaneSpacings(const SupportPlanes &support, const VertexMoves<MeshType> &moves,
                        std::size_t s) {
  const Plane &pl = support.plane(s);
  if (pl.normal.SquaredNorm() == 0) return 0;
  return std::abs(pl.normal * (moves.exactRest(s) - pl.point)) / spacingUnit(support);
}

/// Per feature, how far each of its source vertices with a plane lies from
/// it (offPlaneSpacings), each (feature, source) pair once: a source serves
/// several of a feature's vertices. Sources of inserted vertices no longer in
/// the mesh do not count.
template <class MeshType>
std::vector<std::vector<double>> sourceOffPlanes(const MeshType &m,
                                                 const VertexMoves<MeshType> &moves,
                                                 const SupportPlanes &support,
                                                 const std::vector<std::uint32_t> &featureOf,
                                                 std::size_t featureCount) {
  const SplitPlan &plan = moves.plan();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> sources;
  for (std::size_t k = 0; k < featureOf.size(); ++k) {
    if (m.vert[moves.firstInserted() + k].IsD()) continue;
    for (int i = 0; i < plan.inserted[k].originalCount; ++i) {
      const std::size_t s = plan.inserted[k].original[i];
      if (support.plane(s).normal.SquaredNorm() > 0)
        sources.emplace_back(featureOf[k], std::uint32_t(s));
    }
  }
  std::sort(sources.begin(), sources.end());
  sources.erase(std::unique(sources.begin(), sources.end()), sources.end());
  std::vector<std::vector<double>> offPlane(featureCount);
  for (const auto &[c, s] : sources) offPlane[c].push_back(offPlaneSpacings(support, moves, s));
  return offPlane;
}

/// Per edge feature, the fillet fitted across it (Feature::filletWidthSpacings,
/// ::filletRmsSpacings, ::concave, ::flankNormals, ::filletSamples): each of
/// its sources once, as a cross-section sample between its own plane and the
/// plane of the other source of an inserted vertex it serves. Sources of
/// inserted vertices no longer in the mesh do not count.
template <class MeshType>
void measureFilletFits(const MeshType &m, const VertexMoves<MeshType> &moves,
                       const SupportPlanes &support, const std::vector<std::uint32_t> &featureOf,
                       std::vector<Feature> &features) {
  const SplitPlan &plan = moves.plan();
  const double unit = spacingUnit(support);
  struct Sample {
    std::uint32_t feature, source;
    double own, other;  // signed distances from the two planes, along their normals
    bool operator<(const Sample &o) const {
      return feature != o.feature ? feature < o.feature : source < o.source;
    }
  };
  std::vector<Sample> samples;
  std::vector<std::vector<double>> cosines(features.size());
  std::vector<std::array<Vec3, 2>> normalSums(features.size(), {Vec3(0, 0, 0), Vec3(0, 0, 0)});
  for (std::size_t k = 0; k < featureOf.size(); ++k) {
    const InsertedVertexSource &source = plan.inserted[k];
    const std::uint32_t c = featureOf[k];
    if (m.vert[moves.firstInserted() + k].IsD() || source.originalCount != 2 || features[c].corner)
      continue;
    const Plane *planes[2] = {&support.plane(source.original[0]),
                              &support.plane(source.original[1])};
    if (planes[0]->normal.SquaredNorm() == 0 || planes[1]->normal.SquaredNorm() == 0) continue;
    cosines[c].push_back(planes[0]->normal * planes[1]->normal);
    // Each flank's normals summed apart: the one nearer the first seen first.
    std::array<Vec3, 2> &sum = normalSums[c];
    const Vec3 &first = sum[0].SquaredNorm() > 0 ? sum[0] : planes[0]->normal;
    const bool swap = planes[1]->normal * first > planes[0]->normal * first;
    sum[0] += planes[swap ? 1 : 0]->normal;
    sum[1] += planes[swap ? 0 : 1]->normal;
    for (int i = 0; i < 2; ++i) {
      const Vec3 p = moves.exactRest(source.original[i]);
      const Plane &own = *planes[i], &other = *planes[1 - i];
      samples.push_back({c, std::uint32_t(source.original[i]), own.normal * (p - own.point) / unit,
                         other.normal * (p - other.point) / unit});
    }
  }
  std::stable_sort(samples.begin(), samples.end());
  samples.erase(std::unique(samples.begin(), samples.end(),
                            [](const Sample &a, const Sample &b) { return !(a < b) && !(b < a); }),
                samples.end());
  for (std::size_t from = 0; from < samples.size();) {
    const std::uint32_t c = samples[from].feature;
    std::size_t to = from;
    std::vector<double> others;
    while (to < samples.size() && samples[to].feature == c) others.push_back(samples[to++].other);
    Feature &f = features[c];
    // A convex edge's sources lie inside the other flank's plane, a
    // concave edge's outside it; the fillet rounds that side.
    f.concave = detail::medianOf(others) > 0;
    const double side = f.concave ? 1.0 : -1.0;
    std::vector<CrossSectionSample> section;
    for (std::size_t i = from; i < to; ++i)
      section.push_back({side * samples[i].own, side * samples[i].other});
    const double cosNormals = detail::medianOf(cosines[c]);
    const FilletFit fit = fitFillet(section, cosNormals, FeatureRules::kMaxFilletRadiusSpacings,
                                    FeatureRules::kFilletRadiusStepSpacings);
    f.filletWidthSpacings = filletWidth(fit.radius, cosNormals);
    f.filletRmsSpacings = fit.rms;
    f.wedgeRmsSpacings = fit.wedgeRms;
    f.filletSamples = section.size();
    for (int i = 0; i < 2; ++i) f.flankNormals[i] = normalSums[c][i].Normalize();
    from = to;
  }
}

/// Whether a fillet fits an edge feature's samples (fitFillet, measured by
/// measureFilletFits): their RMS distance to it within
/// FeatureRules::kFilletFitRmsSpacings. Pure.
inline bool filletFits(const Feature &f) {
  return !f.corner && f.filletSamples > 0 &&
         f.filletRmsSpacings <= FeatureRules::kFilletFitRmsSpacings;
}

/// Per edge feature whose samples a fillet fits (filletFits), the fillet width the sampler
/// leaves at the edges it meets alike (Feature::peerFilletWidthSpacings): the
/// lower quartile, weighted by samples, of the widths of the edge features
/// of its side (convex or concave) that a fillet fits too and a grid meets
/// alike (gridEquivalentEdges), itself included. A sampler rounds such edges
/// the same up to where they lie between its nodes; a designed fillet only
/// widens some. Pure.
inline void measurePeerRounding(std::vector<Feature> &features) {
  const double minCos = std::cos(FeatureRules::kGridAlikeAngleRad);
  // The sorted absolute components of each normal, which the cube's
  // symmetries keep: a quick test before trying them.
  const auto sortedAbs = [](const Vec3 &n) {
    std::array<double, 3> a{std::abs(n[0]), std::abs(n[1]), std::abs(n[2])};
    std::sort(a.begin(), a.end());
    return a;
  };
  const double slack = std::sqrt(2 * (1 - minCos));  // a chord of the angle
  const auto near = [&](const std::array<double, 3> &a, const std::array<double, 3> &b) {
    for (int i = 0; i < 3; ++i)
      if (std::abs(a[i] - b[i]) > slack) return false;
    return true;
  };
  std::vector<std::array<std::array<double, 3>, 2>> keys(features.size());
  for (std::size_t c = 0; c < features.size(); ++c)
    keys[c] = {sortedAbs(features[c].flankNormals[0]), sortedAbs(features[c].flankNormals[1])};
  for (std::size_t c = 0; c < features.size(); ++c) {
    Feature &f = features[c];
    f.peerFilletWidthSpacings = f.filletWidthSpacings;
    if (!filletFits(f)) continue;
    std::vector<std::pair<double, std::size_t>> peers;  // (width, samples)
    std::size_t total = 0;
    for (std::size_t d = 0; d < features.size(); ++d) {
      const Feature &g = features[d];
      if (!filletFits(g) || g.concave != f.concave) continue;
      const bool keysMatch = (near(keys[c][0], keys[d][0]) && near(keys[c][1], keys[d][1])) ||
                             (near(keys[c][0], keys[d][1]) && near(keys[c][1], keys[d][0]));
      if (d != c &&
          (!keysMatch || !gridEquivalentEdges(f.flankNormals[0], f.flankNormals[1],
                                              g.flankNormals[0], g.flankNormals[1], minCos)))
        continue;
      peers.emplace_back(g.filletWidthSpacings, g.filletSamples);
      total += g.filletSamples;
    }
    std::sort(peers.begin(), peers.end());
    std::size_t below = 0;
    for (const auto &[width, samples] : peers) {
      below += samples;
      if (double(below) >= FeatureRules::kPeerRoundingQuantile * double(total)) {
        f.peerFilletWidthSpacings = width;
        break;
      }
    }
  }
}

/// Counts, per feature, its inserted vertices still in the mesh and those
/// placed on their planes (Feature::vertices, Feature::moved). A vertex
/// moved across a bending flank (MeshLabels::bentFlank) counts as refused:
/// it moves on its feature's evidence, not its own. The inserted vertices
/// flagged in `uncounted` (split plan order) count in neither.
template <class MeshType>
void countFeatureMoves(const MeshType &m, const VertexMoves<MeshType> &moves,
                       const std::vector<std::uint32_t> &featureOf, std::vector<Feature> &features,
                       const std::vector<char> *uncounted = nullptr) {
  for (Feature &f : features) f.vertices = f.moved = 0;
  const std::size_t first = moves.firstInserted();
  const auto &bent = moves.labels().bentFlank;
  for (std::size_t k = 0; k < featureOf.size(); ++k) {
    if (m.vert[first + k].IsD() || (uncounted && k < uncounted->size() && (*uncounted)[k]))
      continue;
    ++features[featureOf[k]].vertices;
    features[featureOf[k]].moved += moves.isMoved(first + k) && !bent[first + k];
  }
}

/// The counts (countFeatureMoves), how far each feature's farthest source
/// vertex lies from its plane, at its rest position (Feature::maxOffPlane),
/// and within what distance nine in ten of them lie (Feature::offPlaneQ90),
/// the median angle between its edge vertices' flanks
/// (Feature::flankAngleRad) and between their line and the chamfer
/// (Feature::lineChamferAngleRad).
template <class MeshType>
void measureFeatures(const MeshType &m, const VertexMoves<MeshType> &moves,
                     const SupportPlanes &support, const std::vector<std::uint32_t> &featureOf,
                     std::vector<Feature> &features) {
  countFeatureMoves(m, moves, featureOf, features);
  const SplitPlan &plan = moves.plan();
  std::vector<std::vector<double>> angles(features.size()), lineAngles(features.size());
  for (std::size_t k = 0; k < featureOf.size(); ++k) {
    if (m.vert[moves.firstInserted() + k].IsD()) continue;
    if (plan.inserted[k].originalCount == 2) {
      const Vec3 &a = support.plane(plan.inserted[k].original[0]).normal;
      const Vec3 &b = support.plane(plan.inserted[k].original[1]).normal;
      if (a.SquaredNorm() > 0 && b.SquaredNorm() > 0) {
        angles[featureOf[k]].push_back(planeMeetingAngle(a, b));
        const Vec3 &chamfer = plan.inserted[k].chamferNormal;
        if (chamfer.SquaredNorm() > 0)
          lineAngles[featureOf[k]].push_back(lineAngleToSurface(a, b, chamfer));
      }
    }
  }
  std::vector<std::vector<double>> offPlane =
      sourceOffPlanes(m, moves, support, featureOf, features.size());
  for (std::size_t c = 0; c < features.size(); ++c) {
    features[c].maxOffPlane =
        offPlane[c].empty() ? 0 : *std::max_element(offPlane[c].begin(), offPlane[c].end());
    features[c].offPlaneQ90 = detail::quantileOf(offPlane[c], FeatureRules::kOnPlaneQuantile);
    features[c].offPlaneMedian = detail::quantileOf(offPlane[c], FeatureRules::kMedianQuantile);
    features[c].flankAngleRad = angles[c].empty() ? M_PI / 2 : detail::medianOf(angles[c]);
    features[c].lineChamferAngleRad = lineAngles[c].empty() ? 0 : detail::medianOf(lineAngles[c]);
  }
  measureFilletFits(m, moves, support, featureOf, features);
  measurePeerRounding(features);
}

/// Per inserted vertex (split plan order), the lift of its move (moveLift,
/// against the input faces around its sources); -1 where it did not move.
template <class MeshType>
std::vector<double> liftsOfMoves(const MeshType &m, const VertexMoves<MeshType> &moves,
                                 const InputSurface &input) {
  const SplitPlan &plan = moves.plan();
  std::vector<double> lifts(plan.inserted.size(), -1.0);
  std::vector<vcg::Triangle3<double>> around;
  for (std::size_t k = 0; k < plan.inserted.size(); ++k) {
    const std::size_t v = moves.firstInserted() + k;
    if (m.vert[v].IsD() || !moves.isMoved(v)) continue;
    around.clear();
    for (int i = 0; i < plan.inserted[k].originalCount; ++i) {
      const std::size_t s = plan.inserted[k].original[i];
      for (const std::uint32_t *f = input.facesOf.begin(s); f != input.facesOf.end(s); ++f) {
        const auto &t = input.faceVertices[*f];
        around.emplace_back(moves.exactRest(t[0]), moves.exactRest(t[1]), moves.exactRest(t[2]));
      }
    }
    lifts[k] = moveLift(positionOf(&m.vert[v]), plan.inserted[k].rest, around);
  }
  return lifts;
}

/// Whether a move's target, `ownDistance` from the input faces around its
/// sources, lies nearer another input face (at `otherDistance`, of unit
/// normal `otherNormal`) on the far side of a wall or a gap: a face turned
/// more than 120 degrees from the sources' outward normal `ownNormal`. The
/// target has then crossed the input's medial axis: the sampler cannot have
/// resolved an edge that close to another sheet of the surface (a thin
/// wall, a narrow slot). Pure.
inline bool crossesSheet(double ownDistance, const Vec3 &ownNormal, double otherDistance,
                         const Vec3 &otherNormal) {
  return otherDistance < ownDistance && otherNormal * ownNormal < FeatureRules::kOtherSheetMaxCos;
}

/// Counts, per feature, its moved inserted vertices whose target crosses to
/// another sheet of the input (crossesSheet; Feature::crossed). A target's
/// distance to the input faces around its sources is its move's lift times
/// its length (`lifts`: liftsOfMoves). The input is the mesh's faces at
/// their vertices' rest positions; one pass over them finds the faces near
/// each target (forEachBoxOverlap). `stillExtent` bounds a face's extent
/// (the longest input edge; infinity: unknown).
template <class MeshType>
void countSheetCrossings(const MeshType &m, const VertexMoves<MeshType> &moves,
                         const SupportPlanes &support, const std::vector<double> &lifts,
                         const std::vector<std::uint32_t> &featureOf, double stillExtent,
                         std::vector<Feature> &features) {
  for (Feature &f : features) f.crossed = 0;
  const SplitPlan &plan = moves.plan();
  struct Query {
    std::uint32_t k;
    Vec3 target, normal;
    double ownDistance;
  };
  std::vector<Query> queries;
  std::vector<detail::FaceBox> boxes;
  for (std::size_t k = 0; k < plan.inserted.size(); ++k) {
    const std::size_t v = moves.firstInserted() + k;
    if (lifts[k] < 0 || m.vert[v].IsD()) continue;  // not moved
    Vec3 normal(0, 0, 0);
    for (int i = 0; i < plan.inserted[k].originalCount; ++i)
      normal += support.plane(plan.inserted[k].original[i]).normal;
    const Vec3 target = positionOf(&m.vert[v]);
    const double own = lifts[k] * (target - plan.inserted[k].rest).Norm();
    if (!(normal.Norm() > 1e-9) || !(own > 0)) continue;
    queries.push_back({std::uint32_t(k), target, normal / normal.Norm(), own});
    detail::FaceBox box(target);
    for (int c = 0; c < 3; ++c) box.lo[c] -= own, box.hi[c] += own;
    boxes.push_back(box);
  }
  if (queries.empty()) return;
  std::vector<char> away(m.vert.size(), 0);
  for (std::size_t v = 0; v < m.vert.size(); ++v) away[v] = !m.vert[v].IsD() && !moves.isAtRest(v);
  const auto restBox = [&](std::size_t v) { return detail::FaceBox(moves.exactRest(v)); };
  std::vector<detail::PerThread<std::vector<std::uint32_t>>> crossing(detail::maxThreads());
  detail::forEachBoxOverlap(
      m, boxes, restBox, away, stillExtent, [&](int thread, std::uint32_t q, std::uint32_t gi) {
        const auto &g = m.face[gi];
        const vcg::Triangle3<double> t(moves.exactRest(vcg::tri::Index(m, g.cV(0))),
                                       moves.exactRest(vcg::tri::Index(m, g.cV(1))),
                                       moves.exactRest(vcg::tri::Index(m, g.cV(2))));
        Vec3 n = (t.cP(1) - t.cP(0)) ^ (t.cP(2) - t.cP(0));
        const double area2 = n.Norm();
        if (!(area2 > 0)) return;
        n /= area2;
        if (n * queries[q].normal >= FeatureRules::kOtherSheetMaxCos) return;  // cheap test first
        double d;
        Vec3 closest;
        vcg::TrianglePointDistance(t, queries[q].target, d, closest);
        if (crossesSheet(queries[q].ownDistance, queries[q].normal, d, n))
          crossing[thread].value.push_back(q);
      });
  std::vector<char> crossed(queries.size(), 0);
  for (const auto &list : crossing)
    for (std::uint32_t q : list.value) crossed[q] = 1;
  for (std::size_t q = 0; q < queries.size(); ++q)
    features[featureOf[queries[q].k]].crossed += crossed[q];
}

/// The median lift of the moves (liftsOfMoves; 1 when nothing moved). On a
/// chamfered sampling the moves lift the surface to its sharp edges (near
/// 1); on a model already sharp they slide along it (near 0).
inline double medianLift(const std::vector<double> &lifts) {
  std::vector<double> moved;
  for (double l : lifts)
    if (l >= 0) moved.push_back(l);
  return moved.empty() ? 1.0 : detail::medianOf(moved);
}

/// Each feature's median lift (Feature::medianLift) from the lifts of the
/// moves (liftsOfMoves, split plan order; `featureOf` the same order).
inline void measureFeatureLifts(const std::vector<double> &lifts,
                                const std::vector<std::uint32_t> &featureOf,
                                std::vector<Feature> &features) {
  std::vector<std::vector<double>> of(features.size());
  for (std::size_t k = 0; k < lifts.size(); ++k) of[featureOf[k]].push_back(lifts[k]);
  for (std::size_t c = 0; c < features.size(); ++c) features[c].medianLift = medianLift(of[c]);
}

/// Whether the mesh is sampled exactly on its surface: its median edge
/// feature that moved, weighted by its new vertices, has nine in ten of its
/// source vertices within opt.rules.mesh.exactSamplingSpacings of their planes (a
/// remesher that casts or reprojects its vertices onto the input). A
/// sampler that cuts its own chamfers (marching cubes, a voxel remesher)
/// leaves most features' samples measurably off near the edge. Pure.
inline bool sampledExactly(const std::vector<Feature> &features, const SharpenOptions &opt) {
  if (!(opt.rules.mesh.exactSamplingSpacings > 0)) return false;
  std::vector<std::pair<double, std::size_t>> q90;  // (offPlaneQ90, new vertices)
  std::size_t total = 0;
  for (const Feature &f : features)
    if (!f.corner && f.moved > 0) {
      q90.emplace_back(f.offPlaneQ90, f.vertices);
      total += f.vertices;
    }
  if (total == 0) return false;
  std::sort(q90.begin(), q90.end());
  std::size_t below = 0;
  for (const auto &[q, vertices] : q90) {
    below += vertices;
    if (2 * below >= total) return q <= opt.rules.mesh.exactSamplingSpacings;
  }
  return false;
}

/// Whether a sample `offPlaneSpacings` from its plane is a point of the
/// surface rather than the sampler's cut: on a mesh sampled exactly
/// (sampledExactly), farther than opt.rules.feature.onPlaneSpacings. Pure.
inline bool offPlaneIsSurface(double offPlaneSpacings, const SharpenOptions &opt,
                              bool exactSampling) {
  return exactSampling && opt.rules.feature.onPlaneSpacings > 0 &&
         offPlaneSpacings > opt.rules.feature.onPlaneSpacings;
}

/// Whether an edge feature's samples lie on one arc (filletFits; the sharp
/// wedge does not fit them as closely) wider by more than
/// opt.rules.feature.designedFilletMarginSpacings than the arcs the sampler
/// leaves at the edges it meets alike (Feature::peerFilletWidthSpacings): a
/// fillet of the surface, not the sampler's rounding. Pure.
inline bool isDesignedFillet(const Feature &f, const SharpenOptions &opt) {
  const double margin = opt.rules.feature.designedFilletMarginSpacings;
  return margin > 0 && filletFits(f) && f.wedgeRmsSpacings > FeatureRules::kFilletFitRmsSpacings &&
         f.filletWidthSpacings > f.peerFilletWidthSpacings + margin;
}

/// The judgement of one feature on its own evidence (Verdict::Restored, or
/// the first rule it fails, in this order): on a mesh sampled exactly
/// (sampledExactly), half of its samples off their planes (the surface runs
/// there: a designed bevel or blend), or, on any mesh, its samples on an arc
/// wider than the sampler's (isDesignedFillet: a designed fillet); too short
/// to be a feature; an edge whose flanks meet at too shallow an angle, or on
/// a line that crosses its chamfer instead of running along it; one of its
/// samples far off the plane its flank extrapolates, unless nine in ten of
/// them lie on their planes, or half of them do and none lies much farther,
/// both bounds times the sine of the angle its flanks meet at (then only the
/// far samples' new vertices stay at rest: EvidenceGuard::vertexIsWeak); most
/// of its vertices refused by the other tests. Pure.
inline Verdict judgeFeature(const Feature &f, const SharpenOptions &opt,
                            bool exactSampling = false) {
  const FeatureRules &rule = opt.rules.feature;
  if (offPlaneIsSurface(f.offPlaneMedian, opt, exactSampling) || isDesignedFillet(f, opt))
    return Verdict::OnTheSurface;
  if (!f.corner && f.vertices < std::size_t(rule.minFeatureVertices)) return Verdict::TooShort;
  if (!f.corner && f.flankAngleRad < rule.minFeatureAngleRad) return Verdict::ShallowAngle;
  if (!f.corner && rule.maxFeatureLineChamferAngleRad > 0 &&
      f.lineChamferAngleRad > rule.maxFeatureLineChamferAngleRad)
    return Verdict::LineAcrossChamfer;
  const bool sampledOnItsPlanes = rule.onPlaneSpacings > 0 && f.offPlaneQ90 <= rule.onPlaneSpacings;
  // The line two planes meet on moves by their errors over the sine of the
  // angle between them: an acute edge allows its samples less.
  const double sine = f.corner ? 1.0 : std::sin(f.flankAngleRad);
  const bool mostlyOnItsPlanes = rule.medianOnPlaneSpacings > 0 &&
                                 f.offPlaneMedian <= rule.medianOnPlaneSpacings * sine &&
                                 f.maxOffPlane <= rule.maxMedianOnPlaneOffSpacings * sine;
  if (f.maxOffPlane > rule.maxFeatureOffPlaneSpacings && !sampledOnItsPlanes && !mostlyOnItsPlanes)
    return Verdict::OffItsPlanes;
  if (double(f.vertices - f.moved + f.crossed) >
      rule.maxFeatureFallbackFraction * double(f.vertices))
    return Verdict::MostlyRefused;
  return Verdict::Restored;
}

/// Whether one new vertex of a feature kept has too little evidence of its
/// own for its move (sendBack): a source vertex `sourceOffPlaneSpacings`
/// from its plane, beyond the feature's bound (such a sample does not vouch
/// for the vertices it sources; Feature::offPlaneQ90), or, for an edge
/// vertex, beyond the long-move bound when the move is longer than
/// `longMoveSpacings`: a flank's misfit grows along the extrapolation to the
/// line two planes meet on. A corner's point is pinned by three planes, and
/// an acute corner's move is long by its shape; left alone among sharpened
/// edges it would be a notch. On a mesh sampled exactly (sampledExactly),
/// a source off its plane beyond opt.rules.feature.onPlaneSpacings is a point of the
/// surface and vouches for none of them. Both in sample spacings. Pure.
inline bool vertexEvidenceIsWeak(double moveSpacings, double sourceOffPlaneSpacings, bool corner,
                                 const SharpenOptions &opt, bool exactSampling = false) {
  if (offPlaneIsSurface(sourceOffPlaneSpacings, opt, exactSampling)) return true;
  if (sourceOffPlaneSpacings > opt.rules.feature.maxFeatureOffPlaneSpacings) return true;
  return !corner && opt.rules.vertex.longMoveSpacings > 0 &&
         moveSpacings > opt.rules.vertex.longMoveSpacings &&
         sourceOffPlaneSpacings > opt.rules.vertex.maxLongMoveOffPlaneSpacings;
}

/// Of the inserted vertices of the features placement moved at all, the
/// fraction the tests refused. On a remeshed solid the tests agree nearly
/// everywhere; where they refuse a large part of the moves, the input is not
/// a chamfered sampling of planes meeting at sharp edges (a scan's fused
/// noise, a model already sharp, a smooth shape) and nothing is trusted.
inline double refusedFraction(const std::vector<Feature> &features) {
  std::size_t vertices = 0, moved = 0;
  for (const Feature &f : features)
    if (f.moved > 0) {
      vertices += f.vertices;
      moved += f.moved;
    }
  return vertices == 0 ? 0.0 : double(vertices - moved) / double(vertices);
}

/// The refused fraction above which nothing is sharpened: the bound for a
/// smooth part made of planes (surface_measures.h) where the input's noise
/// is at most `maxSmoothNoiseSpacings` and its planar share at least
/// `minPlanarAreaFraction`, else the general one.
inline double refusedBound(const SurfaceMeasures &surface, const SharpenOptions &opt) {
  const bool smoothPlanes = opt.rules.mesh.maxSmoothNoiseSpacings > 0 &&
                            surface.noiseSpacings <= opt.rules.mesh.maxSmoothNoiseSpacings &&
                            surface.planarFraction >= opt.rules.mesh.minPlanarAreaFraction;
  return smoothPlanes
             ? std::max(opt.rules.mesh.maxRefusedFraction, opt.rules.mesh.maxRefusedFractionSmooth)
             : opt.rules.mesh.maxRefusedFraction;
}

/// Whether the moves mostly slide along the input instead of lifting it
/// (their median `lift`, medianLift): a model already sharp. Pure.
inline bool mostlyAlreadySharp(double lift, const SharpenOptions &opt) {
  return lift < opt.rules.mesh.minMedianLift;
}

/// Whether feature `f` is left as already sharp on a mesh whose moves mostly
/// slide (the median `lift` of all of them) but which is not left whole (a
/// mesh sampled exactly, sharp in part: meshEvidenceIsWeak): its own moves
/// slide too (Feature::medianLift). Pure.
inline bool leftAsAlreadySharp(const Feature &f, double lift, const SharpenOptions &opt) {
  return mostlyAlreadySharp(lift, opt) && mostlyAlreadySharp(f.medianLift, opt);
}

/// Whether the mesh as a whole shows too little evidence to sharpen any of
/// it: the tests refused too many of the moves (refusedFraction, against
/// refusedBound), or the model is already sharp (mostlyAlreadySharp). A mesh
/// sampled exactly on its surface (sampledExactly) may be sharp in part: its
/// sampler puts vertices on the edges it meets (a remesher casting them onto
/// the input does at convex edges) and leaves the others chamfered, so there
/// each feature is judged by its own lift (featureVerdicts). Pure.
inline bool meshEvidenceIsWeak(double refused, double lift, const SurfaceMeasures &surface,
                               const SharpenOptions &opt, bool exactSampling = false) {
  return refused > refusedBound(surface, opt) || (mostlyAlreadySharp(lift, opt) && !exactSampling);
}

/// Per inserted vertex (split plan order): whether it lies on a face outside
/// the user's selection (HeldFaces::unselected), where it stays at rest;
/// empty without a selection.
inline std::vector<char> verticesOutsideSelection(const SplitPlan &plan, const HeldFaces &held) {
  if (held.unselected.empty()) return {};
  std::vector<char> outside(plan.inserted.size(), 0);
  for (const SplitFace &face : plan.faces) {
    if (!held.outsideSelection(face.face)) continue;
    for (const int k : face.edgeVertex)
      if (k >= 0) outside[k] = 1;
    if (face.centerVertex >= 0) outside[face.centerVertex] = 1;
  }
  return outside;
}

/// Of `featureCount` features, those with new vertices both inside and
/// outside the user's selection (`outside`: verticesOutsideSelection).
inline std::size_t featuresCutBySelection(const std::vector<char> &outside,
                                          const std::vector<std::uint32_t> &featureOf,
                                          std::size_t featureCount) {
  if (outside.empty()) return 0;
  std::vector<char> side(featureCount, 0);
  for (std::size_t k = 0; k < outside.size(); ++k) side[featureOf[k]] |= outside[k] ? 2 : 1;
  return std::size_t(std::count(side.begin(), side.end(), 3));
}

/// Whether a feature judged `v` on its own was left for placement's reasons
/// only (its planes' line crosses its chamfer, or placement refused most of
/// its moves), so that a corner patch may take it (EvidenceGuard::
/// findCornerPatches): the line of two faces that touch only at a corner
/// runs off the solid past it.
inline bool placementLeft(Verdict v) {
  return v == Verdict::LineAcrossChamfer || v == Verdict::MostlyRefused;
}

/// Per feature, its verdict: every feature's Verdict::MeshEvidenceWeak when
/// the mesh as a whole shows too little evidence (meshEvidenceIsWeak with the
/// moves' median `lift`), else its own (judgeFeature, on a mesh sampled
/// exactly or not); a corner one of whose edges is left, CornerOfWeakEdge (a
/// corner is where its edges meet); a feature one of whose new vertices lies
/// on an edge from a vertex `held` pins (a vertex of a face held at a
/// non-manifold spot), AtNonManifoldSpot (restoring it would bend that face);
/// a feature all of whose new vertices lie on faces outside the user's
/// selection (verticesOutsideSelection), OutsideSelection;
/// a feature placement could not restore on its own (LineAcrossChamfer,
/// MostlyRefused) that `cornerPatch` joins to a corner (EvidenceGuard::
/// findCornerPatches), judged with it; and, on a mesh sampled exactly and mostly
/// sharp already, a feature whose own moves slide along it, AlreadySharp
/// (Feature::medianLift; its moves that lift are judged one by one,
/// EvidenceGuard::keptMoves).
inline std::vector<Verdict> featureVerdicts(const SplitPlan &plan,
                                            const std::vector<Feature> &features,
                                            const std::vector<std::uint32_t> &featureOf,
                                            double lift, const SurfaceMeasures &surface,
                                            const SharpenOptions &opt, bool exactSampling = false,
                                            const HeldFaces &held = {},
                                            const std::vector<char> &cornerPatch = {}) {
  if (meshEvidenceIsWeak(refusedFraction(features), lift, surface, opt, exactSampling))
    return std::vector<Verdict>(features.size(), Verdict::MeshEvidenceWeak);
  std::vector<Verdict> verdict(features.size());
  for (std::size_t c = 0; c < features.size(); ++c) {
    verdict[c] = judgeFeature(features[c], opt, exactSampling);
    if (c < cornerPatch.size() && cornerPatch[c] && placementLeft(verdict[c]))
      verdict[c] = Verdict::Restored;
  }
  for (std::size_t k = 0; k < plan.inserted.size() && !held.empty(); ++k)
    for (int i = 0; i < plan.inserted[k].originalCount; ++i)
      if (held.pins(plan.inserted[k].original[i]))
        verdict[featureOf[k]] = Verdict::AtNonManifoldSpot;
  if (const std::vector<char> outside = verticesOutsideSelection(plan, held); !outside.empty()) {
    std::vector<char> inside(features.size(), 0);
    for (std::size_t k = 0; k < plan.inserted.size(); ++k)
      if (!outside[k]) inside[featureOf[k]] = 1;
    for (std::size_t c = 0; c < features.size(); ++c)
      if (!inside[c]) verdict[c] = Verdict::OutsideSelection;
  }
  // An edge feature's weakness reaches the corner features around its sources;
  // an edge already sharp is no evidence against the corner it runs into.
  std::vector<char> weakSource(plan.originalVertexCount, 0);
  for (std::size_t k = 0; k < plan.inserted.size(); ++k)
    if (!features[featureOf[k]].corner && isLeft(verdict[featureOf[k]]))
      for (int i = 0; i < plan.inserted[k].originalCount; ++i)
        weakSource[plan.inserted[k].original[i]] = 1;
  for (std::size_t k = 0; k < plan.inserted.size(); ++k)
    if (features[featureOf[k]].corner && verdict[featureOf[k]] == Verdict::Restored)
      for (int i = 0; i < plan.inserted[k].originalCount; ++i)
        if (weakSource[plan.inserted[k].original[i]])
          verdict[featureOf[k]] = Verdict::CornerOfWeakEdge;
  for (std::size_t c = 0; c < features.size(); ++c)
    if (verdict[c] == Verdict::Restored && leftAsAlreadySharp(features[c], lift, opt))
      verdict[c] = Verdict::AlreadySharp;
  return verdict;
}

/// The count of each verdict (SharpenReport's evidence.verdicts).
inline std::array<std::size_t, kVerdictCount> countVerdicts(const std::vector<Verdict> &verdicts) {
  std::array<std::size_t, kVerdictCount> count{};
  for (const Verdict v : verdicts) ++count[static_cast<int>(v)];
  return count;
}

/// The auto method's guard. The features are grouped once, from the split
/// plan and the regions (they do not change); their evidence is measured
/// after placement (revertWeakFeatures) and their moves counted again after
/// the cleanup and the intersection guard (leaveMeshIfGuardsRefused).
template <class MeshType>
class EvidenceGuard {
 public:
  /// \pre placement (and the extended refinement) has run.
  EvidenceGuard(MeshType &m, VertexMoves<MeshType> &moves, const SupportPlanes &support,
                const InputSurface &input, const SurfaceMeasures &surface, double longestInputEdge,
                const SharpenOptions &opt, const HeldFaces &held)
      : m_(m),
        moves_(moves),
        support_(support),
        input_(input),
        surface_(surface),
        longestInputEdge_(longestInputEdge),
        opt_(opt),
        held_(held) {
    const auto regionOf = [&](std::size_t v) -> long {
      return v < support.region.size() ? support.region[v] : -1;
    };
    featureOf_ = groupFeatures(moves.plan(), regionOf, features_);
    outsideSelection_ = verticesOutsideSelection(moves.plan(), held);
  }

  /// What the guard judges from the placement: each feature measured
  /// (features()), each move's lift (liftsOfMoves), and which features are
  /// left and why (featureVerdicts), with the counts of the report.
  struct Judgement {
    EvidenceStats stats;
    std::vector<double> lifts;
    std::vector<Verdict> verdicts;  ///< per feature
    bool left(std::size_t c) const { return isLeft(verdicts[c]); }
    bool alreadySharp(std::size_t c) const { return verdicts[c] == Verdict::AlreadySharp; }
  };

  /// One inserted vertex's own evidence, in sample spacings: how far it is
  /// from rest, and how far its farthest source lies from its plane.
  struct VertexEvidence {
    double moveSpacings = 0;
    double sourceOffPlaneSpacings = 0;
    bool corner = false;
  };
  VertexEvidence vertexEvidence(std::size_t k) const {
    const InsertedVertexSource &source = moves_.plan().inserted[k];
    VertexEvidence e;
    for (int i = 0; i < source.originalCount; ++i)
      e.sourceOffPlaneSpacings = std::max(e.sourceOffPlaneSpacings,
                                          offPlaneSpacings(support_, moves_, source.original[i]));
    const std::size_t v = moves_.firstInserted() + k;
    e.moveSpacings = (positionOf(&m_.vert[v]) - source.rest).Norm() / spacingUnit(support_);
    e.corner = source.originalCount != 2;
    return e;
  }

  /// Whether inserted vertex `k` (split plan order), in a feature not weak,
  /// goes back to rest on its own evidence (vertexEvidence,
  /// vertexEvidenceIsWeak).
  bool vertexIsWeak(std::size_t k) const {
    const VertexEvidence e = vertexEvidence(k);
    return vertexEvidenceIsWeak(e.moveSpacings, e.sourceOffPlaneSpacings, e.corner, opt_,
                                exactSampling_);
  }
  Judgement judge() {
    Judgement out;
    EvidenceStats &stats = out.stats;
    measureFeatures(m_, moves_, support_, featureOf_, features_);
    stats.features = features_.size();
    stats.refusedFraction = refusedFraction(features_);
    stats.refusedBound = refusedBound(surface_, opt_);
    out.lifts = liftsOfMoves(m_, moves_, input_);
    stats.medianLift = medianLift(out.lifts);
    measureFeatureLifts(out.lifts, featureOf_, features_);
    stats.noiseSpacings = surface_.noiseSpacings;
    stats.planarFraction = surface_.planarFraction;
    exactSampling_ = sampledExactly(features_, opt_);
    stats.exactSampling = exactSampling_;
    stats.wholeMeshLeft =
        meshEvidenceIsWeak(stats.refusedFraction, stats.medianLift, surface_, opt_, exactSampling_);
    if (!stats.wholeMeshLeft)
      countSheetCrossings(m_, moves_, support_, out.lifts, featureOf_, longestInputEdge_,
                          features_);
    findCornerPatches();
    std::vector<char> joined(features_.size(), 0);
    for (const CornerPatch &patch : patches_)
      if (!patch.edges.empty())
        for (const std::uint32_t c : featuresOf(patch)) joined[c] = 1;
    out.verdicts = featureVerdicts(moves_.plan(), features_, featureOf_, stats.medianLift, surface_,
                                   opt_, exactSampling_, held_, joined);
    // The edges joined to corners stand or fall with them.
    for (const CornerPatch &patch : patches_)
      if (!patch.edges.empty() && !patchRestored(patch, out.verdicts))
        leavePatchFeatures(patch, out.verdicts,
                           [&](std::uint32_t c, Verdict v) { out.verdicts[c] = v; });
    stats.verdicts = countVerdicts(out.verdicts);
    stats.cutBySelection = featuresCutBySelection(outsideSelection_, featureOf_, features_.size());
    for (std::size_t c = 0; c < features_.size(); ++c) {
      if (!out.left(c) || features_[c].moved == 0) continue;
      ++stats.weakFeatures;
      stats.alreadySharpFeatures +=
          !stats.wholeMeshLeft && leftAsAlreadySharp(features_[c], stats.medianLift, opt_);
    }
    return out;
  }

  /// Sends back to rest every move of the features whose evidence is weak
  /// (featureVerdicts), and of the other features' vertices whose own evidence
  /// is weak (vertexIsWeak): their inserted vertices (as Placement::WeakEvidence)
  /// and the zone vertices projected beside them (keptMoves). Of a feature
  /// already sharp (leftAsAlreadySharp) only the moves that slide go back: a
  /// move that lifts its vertex off the input cuts back a chamfer the sampler
  /// left in a feature otherwise sharp, as at a saddle corner where a
  /// remesher casting its vertices onto the input bridged a concave edge's
  /// end. Runs before the cleanup: a
  /// feature left as it was is never touched by the cleanup's collapses and
  /// flips, so its faces are the input's exactly.
  EvidenceStats revertWeakFeatures() {
    const Judgement judged = judge();
    verdicts_ = judged.verdicts;
    EvidenceStats stats = judged.stats;
    const SplitPlan &plan = moves_.plan();
    placeCornerPatches(judged.verdicts);
    const std::vector<char> kept = keptMoves(judged);
    const std::size_t first = moves_.firstInserted();
    for (std::size_t k = 0; k < plan.inserted.size(); ++k)
      if (!m_.vert[first + k].IsD() && !kept[k]) sendBackWithSources(k, stats);
    return stats;
  }

  /// Per inserted vertex (split plan order), whether its move stays: its
  /// feature is not weak and its own evidence is not (vertexIsWeak), unless it
  /// went to a corner placed whole, whose point all its regions' planes
  /// vouch for (cornerPoint): a patch is kept or given up whole. Of a
  /// feature already sharp (Judgement::alreadySharp) the moves that lift
  /// their vertex off the input stay (their own lift at least the median
  /// bound: mostlyAlreadySharp), and so does the corner vertex of a face one
  /// of whose edge vertices stays so: the edge it restores runs into that
  /// corner. Those moves rest on their own evidence only: of the vertices
  /// that can part two crossing faces as far out, the intersection guard
  /// sends them back first (retreatFirst). The others of such a feature
  /// slide along the input, sharp there already (slidingVertex_).
  std::vector<char> keptMoves(const Judgement &judged) {
    const SplitPlan &plan = moves_.plan();
    const std::size_t count = plan.inserted.size(), first = moves_.firstInserted();
    std::vector<char> kept(count, 0), lifting(count, 0), placedWhole(count, 0);
    for (const CornerPatch &patch : patches_)
      for (const std::uint32_t k : patch.members) placedWhole[k] = 1;
    slidingVertex_.assign(count, 0);
    retreatFirst_.assign(m_.vert.size(), 0);
    const auto sharpAlready = [&](std::size_t k) { return judged.alreadySharp(featureOf_[k]); };
    const auto outside = [&](std::size_t k) {
      return !outsideSelection_.empty() && outsideSelection_[k];
    };
    for (std::size_t k = 0; k < count; ++k) {
      if (m_.vert[first + k].IsD()) continue;
      // Not moved (lift -1): placement left it, nothing to cut back there.
      lifting[k] = judged.lifts[k] >= 0 && !mostlyAlreadySharp(judged.lifts[k], opt_);
      kept[k] = (sharpAlready(k) ? lifting[k] : !judged.left(featureOf_[k])) &&
                (placedWhole[k] || !vertexIsWeak(k)) && !outside(k);
    }
    for (const SplitFace &face : plan.faces) {
      const int corner = face.centerVertex;
      if (corner < 0 || kept[corner] || !sharpAlready(corner) || judged.lifts[corner] < 0 ||
          vertexIsWeak(corner))
        continue;
      for (const int e : face.edgeVertex)
        if (e >= 0 && sharpAlready(e) && lifting[e] && kept[e]) kept[corner] = 1;
    }
    for (std::size_t k = 0; k < count; ++k) {
      if (m_.vert[first + k].IsD()) continue;
      slidingVertex_[k] = outside(k);  // at rest by the user's choice: not refused
      if (!sharpAlready(k)) continue;
      slidingVertex_[k] = slidingVertex_[k] || (!kept[k] && !lifting[k]);
      retreatFirst_[first + k] = kept[k];
    }
    return kept;
  }

  /// The vertices whose moves the intersection guard sends back first
  /// (keptMoves), by vertex index; empty before revertWeakFeatures().
  const std::vector<char> &retreatFirst() const { return retreatFirst_; }

  /// The vertices of the corners placed whole (placeCornerPatches) and not
  /// given up, by vertex index: the guards give such a corner up whole, with
  /// what the cleanup merged into it (removeDegenerateTriangles).
  std::vector<char> placedWholeVertices() const {
    std::vector<char> whole(m_.vert.size(), 0);
    for (const CornerPatch &patch : patches_)
      for (const std::uint32_t k : patch.members) whole[moves_.firstInserted() + k] = 1;
    return whole;
  }

  /// After the cleanup and the intersection guard: when they refused so
  /// many of the moves left that the mesh as a whole shows too little
  /// evidence (refusedFraction), the mesh returns to `beforeGuards` with
  /// every vertex at rest, the input's surface exactly (their collapses and
  /// flips undone). \return whether it did.
  bool leaveMeshIfGuardsRefused(const ElementSnapshot<MeshType> &beforeGuards,
                                EvidenceStats &stats) {
    countFeatureMoves(m_, moves_, featureOf_, features_, &slidingVertex_);
    const double refused = refusedFraction(features_);
    if (!(refused > refusedBound(surface_, opt_))) return false;
    beforeGuards.restore(m_, moves_.labels());
    stats.refusedFraction = refused;
    stats.wholeMeshLeft = true;
    const std::size_t end = moves_.firstInserted() + moves_.plan().inserted.size();
    for (std::size_t v = 0; v < end; ++v) {
      if (m_.vert[v].IsD() || !moves_.hasRest(v) || !moves_.isMoved(v)) continue;
      const bool inserted = moves_.isInserted(v);
      moves_.sendBack(v, inserted ? Placement::WeakEvidence : Placement::Original);
      ++(inserted ? stats.reverted : stats.zoneReverted);
    }
    stats.weakFeatures = features_.size();
    stats.verdicts = {};
    stats.verdicts[static_cast<int>(Verdict::MeshEvidenceWeak)] = features_.size();
    stats.cutBySelection = 0;
    verdicts_.assign(features_.size(), Verdict::MeshEvidenceWeak);
    return true;
  }

  /// Every feature as the report lists it, with its verdict (final once the
  /// guards have run); by feature index.
  std::vector<FeatureRecord> records() const {
    const SplitPlan &plan = moves_.plan();
    std::vector<FeatureRecord> out(features_.size());
    std::vector<std::vector<double>> widths(features_.size());
    for (std::size_t c = 0; c < features_.size(); ++c) {
      out[c].corner = features_[c].corner;
      out[c].verdict = c < verdicts_.size() ? verdicts_[c] : Verdict::Restored;
      out[c].flankAngleRad = features_[c].corner ? 0 : features_[c].flankAngleRad;
    }
    for (std::size_t k = 0; k < plan.inserted.size(); ++k) {
      const InsertedVertexSource &s = plan.inserted[k];
      ++out[featureOf_[k]].newVertices;
      if (s.originalCount == 2)
        widths[featureOf_[k]].push_back(
            (moves_.exactRest(s.original[0]) - moves_.exactRest(s.original[1])).Norm() /
            spacingUnit(support_));
    }
    for (std::size_t c = 0; c < features_.size(); ++c)
      if (!widths[c].empty()) out[c].widthSpacings = detail::medianOf(widths[c]);
    for (const SplitFace &face : plan.faces) {
      std::array<std::uint32_t, 4> splitBy{};
      std::size_t n = 0;
      for (const int k :
           {face.edgeVertex[0], face.edgeVertex[1], face.edgeVertex[2], face.centerVertex})
        if (k >= 0 &&
            std::find(splitBy.begin(), splitBy.begin() + n, featureOf_[k]) == splitBy.begin() + n)
          splitBy[n++] = featureOf_[k];
      for (std::size_t i = 0; i < n; ++i) out[splitBy[i]].faces.push_back(face.face);
    }
    return out;
  }

  /// Per face of the mesh as it is now (before compaction), the verdict it
  /// takes (verdictRank): that of the features of its inserted vertices;
  /// else, for an input face given back whole, that of the features that
  /// split it; else kNoVerdict. \pre `features` is records(), by feature index.
  FaceVerdicts outputFaceVerdicts(const std::vector<FeatureRecord> &features,
                                  std::size_t inputFaceCount) const {
    const FaceVerdicts input = featureFaceVerdicts(features, inputFaceCount);
    const std::size_t first = moves_.firstInserted(), count = moves_.plan().inserted.size();
    FaceVerdicts out(m_.face.size(), kNoVerdict);
    for (std::size_t f = 0; f < m_.face.size(); ++f) {
      const auto &face = m_.face[f];
      if (face.IsD()) continue;
      for (int j = 0; j < 3; ++j) {
        const std::size_t v = vcg::tri::Index(m_, face.cV(j));
        if (v < first || v >= first + count) continue;
        out[f] = firstVerdict(out[f], std::int8_t(features[featureOf_[v - first]].verdict));
      }
      if (out[f] == kNoVerdict && f < input.size()) out[f] = input[f];
    }
    return out;
  }

  /// The features and each inserted vertex's feature (for the study).
  const std::vector<Feature> &features() const { return features_; }
  const std::vector<std::uint32_t> &featureOf() const { return featureOf_; }

 private:
  /// One corner where three or more regions meet, placed whole: a corner
  /// feature, and the edges beside it that placement could not restore on
  /// their own (placementLeft: not edges but parts of the corner, as a
  /// pyramid's two opposite faces, or a hexagonal pyramid's faces two apart,
  /// touch only at its apex). All its new vertices go to the one point all
  /// their sources' planes determine.
  struct CornerPatch {
    std::vector<std::uint32_t> edges;
    std::vector<std::uint32_t> corners;
    Vec3 point{0, 0, 0};
    /// The new vertices it would place (findCornerPatches).
    std::vector<std::uint32_t> vertices;
    std::vector<std::uint32_t> members;  ///< of those, placed there (placeCornerPatches)
    std::vector<Vec3> before;            ///< ...and where placement had put them
    std::vector<Placement> placedBefore;
    bool refused = false;  ///< cornerPatchRefused found the cleanup refused it
  };

  /// The planes of the regions of the sources of `members` (inserted
  /// vertices), each region weighing alike: its own plane where it is one,
  /// else the planes fitted at its sources, shared out.
  struct RegionPlanes {
    std::vector<Plane> planes;
    std::vector<double> weights;
    std::size_t regions = 0;
  };
  RegionPlanes regionPlanesOf(const std::vector<std::uint32_t> &members) const {
    const SplitPlan &plan = moves_.plan();
    std::vector<std::uint32_t> sources;
    for (const std::uint32_t k : members)
      for (int i = 0; i < plan.inserted[k].originalCount; ++i)
        sources.push_back(plan.inserted[k].original[i]);
    std::sort(sources.begin(), sources.end());
    sources.erase(std::unique(sources.begin(), sources.end()), sources.end());
    const auto regionOf = [&](std::uint32_t v) -> long {
      return v < support_.region.size() ? support_.region[v] : -1;
    };
    std::vector<long> regions;
    for (const std::uint32_t v : sources)
      if (regionOf(v) >= 0) regions.push_back(regionOf(v));
    std::sort(regions.begin(), regions.end());
    regions.erase(std::unique(regions.begin(), regions.end()), regions.end());
    RegionPlanes out;
    out.regions = regions.size();
    for (const long r : regions) {
      if (const Plane *own = regionPlaneOf(support_.regionPlanes, int(r))) {
        out.planes.push_back(*own);
        out.weights.push_back(1.0);
        continue;
      }
      const std::size_t first = out.planes.size();
      for (const std::uint32_t v : sources)
        if (regionOf(v) == r && support_.plane(v).normal.SquaredNorm() > 0)
          out.planes.push_back(support_.plane(v));
      for (std::size_t i = first; i < out.planes.size(); ++i)
        out.weights.push_back(1.0 / double(out.planes.size() - first));
    }
    return out;
  }

  /// Whether inserted vertex `k` rests within ExtendedSettings::
  /// maxDisplacementSpacings of every plane in `planes`: a sampler cuts a
  /// corner a sample or two deep, measured across its faces (along an acute
  /// tip's axis the cut reaches farther).
  bool withinCorner(std::uint32_t k, const std::vector<Plane> &planes) const {
    const Vec3 &rest = moves_.plan().inserted[k].rest;
    const double bound = opt_.extended.maxDisplacementSpacings * spacingUnit(support_);
    for (const Plane &pl : planes)
      if (std::abs(pl.normal * (rest - pl.point)) > bound) return false;
    return true;
  }

  /// The point the planes of the regions of the sources of `members`
  /// (regionPlanesOf) determine, when they fix one: the QEF of dual
  /// contouring with rank three (util/qef.h), every plane passing within
  /// FeatureRules::maxFeatureOffPlaneSpacings of it, every member within the
  /// corner's reach (withinCorner).
  std::optional<Vec3> cornerPoint(const std::vector<std::uint32_t> &members) const {
    const SplitPlan &plan = moves_.plan();
    Vec3 center(0, 0, 0);
    for (const std::uint32_t k : members) center += plan.inserted[k].rest;
    center /= double(members.size());
    const RegionPlanes corner = regionPlanesOf(members);
    if (corner.regions < 3 || corner.planes.empty()) return std::nullopt;
    const QefSolution solution = solveQef(corner.planes, corner.weights, center);
    if (solution.rank != 3) return std::nullopt;
    const double unit = spacingUnit(support_);
    for (const Plane &pl : corner.planes)
      if (std::abs(pl.normal * (solution.point - pl.point)) >
          opt_.rules.feature.maxFeatureOffPlaneSpacings * unit)
        return std::nullopt;
    for (const std::uint32_t k : members)
      if (!withinCorner(k, corner.planes)) return std::nullopt;
    return solution.point;
  }

  /// Finds the corner patches (CornerPatch): the corner features restored on
  /// their own, with the edges beside them that may be part of a corner
  /// (placementLeft) and lie within reach of them, and the corners such
  /// edges share sources with, joined through their sources, where their
  /// planes fix one point (cornerPoint); and every other corner feature
  /// restored on its own whose vertices agree on one.
  void findCornerPatches() {
    patches_.clear();
    const SplitPlan &plan = moves_.plan();
    ownVerdicts_.resize(features_.size());
    for (std::size_t c = 0; c < features_.size(); ++c)
      ownVerdicts_[c] = judgeFeature(features_[c], opt_, exactSampling_);
    const std::vector<Verdict> &own = ownVerdicts_;
    verticesOf_.assign(features_.size(), {});
    for (std::size_t k = 0; k < plan.inserted.size(); ++k)
      if (!m_.vert[moves_.firstInserted() + k].IsD())
        verticesOf_[featureOf_[k]].push_back(std::uint32_t(k));
    const auto candidate = [&](std::size_t c) {
      return placementLeft(own[c]) || (features_[c].corner && own[c] == Verdict::Restored);
    };
    // An edge joins a corner when each of its vertices is within the reach
    // of the corner's own planes.
    std::vector<std::vector<Plane>> cornerPlanes(features_.size());
    for (std::size_t c = 0; c < features_.size(); ++c)
      if (features_[c].corner && candidate(c))
        cornerPlanes[c] = regionPlanesOf(verticesOf_[c]).planes;
    const auto withinReach = [&](std::size_t edge, std::size_t corner) {
      for (const std::uint32_t k : verticesOf_[edge])
        if (!withinCorner(k, cornerPlanes[corner])) return false;
      return true;
    };
    std::vector<std::vector<std::uint32_t>> featuresAt(plan.originalVertexCount);
    for (std::size_t c = 0; c < features_.size(); ++c)
      if (candidate(c))
        for (const std::uint32_t k : verticesOf_[c])
          for (int i = 0; i < plan.inserted[k].originalCount; ++i) {
            // Once per feature: a source serves several of a feature's vertices.
            std::vector<std::uint32_t> &at = featuresAt[plan.inserted[k].original[i]];
            if (at.empty() || at.back() != c) at.push_back(std::uint32_t(c));
          }
    detail::DisjointSets cluster(features_.size());
    std::vector<char> clustered(features_.size(), 0);
    for (const std::vector<std::uint32_t> &at : featuresAt)
      for (const std::uint32_t e : at)
        for (const std::uint32_t d : at)
          if (!features_[e].corner && features_[d].corner && withinReach(e, d)) {
            cluster.join(e, d);
            clustered[e] = clustered[d] = 1;
          }
    std::vector<std::vector<std::uint32_t>> byRoot(features_.size());
    for (std::size_t c = 0; c < features_.size(); ++c)
      if (clustered[c]) byRoot[cluster.find(std::uint32_t(c))].push_back(std::uint32_t(c));
    std::vector<char> cornerTaken(features_.size(), 0);
    for (const std::vector<std::uint32_t> &group : byRoot) {
      CornerPatch patch;
      bool restoredCorner = false;
      for (const std::uint32_t c : group) {
        (features_[c].corner ? patch.corners : patch.edges).push_back(c);
        restoredCorner = restoredCorner || (features_[c].corner && own[c] == Verdict::Restored);
      }
      if (!restoredCorner) continue;
      patch.vertices = membersOf(patch);
      const std::optional<Vec3> point = cornerPoint(patch.vertices);
      if (!point) continue;
      patch.point = *point;
      for (const std::uint32_t d : patch.corners) cornerTaken[d] = 1;
      patches_.push_back(std::move(patch));
    }
    for (std::size_t c = 0; c < features_.size(); ++c) {
      if (cornerTaken[c] || !features_[c].corner || verticesOf_[c].size() < 2 ||
          own[c] != Verdict::Restored)
        continue;
      // The vertices placement moved, each to the corner of its own three
      // planes, and those it kept at rest between regions that are planes
      // (their fits near the corner see its other faces, the regions' own
      // planes do not): one point for them all where it agrees with each
      // move placement made.
      CornerPatch patch;
      patch.corners.push_back(std::uint32_t(c));
      std::vector<std::uint32_t> moved, members;
      for (const std::uint32_t k : verticesOf_[c]) {
        if (moves_.isMoved(moves_.firstInserted() + k))
          moved.push_back(k);
        else if (!sourcesOnOwnPlanes(k))
          continue;
        members.push_back(k);
      }
      if (moved.empty() || members.size() < 2) continue;
      const std::optional<Vec3> point = cornerPoint(members);
      if (!point) continue;
      bool agrees = true;
      for (const std::uint32_t k : moved)
        agrees =
            agrees && (positionOf(&m_.vert[moves_.firstInserted() + k]) - *point).Norm() <=
                          opt_.rules.feature.maxFeatureOffPlaneSpacings * spacingUnit(support_);
      if (!agrees) continue;
      patch.point = *point;
      patch.vertices = std::move(members);
      patches_.push_back(std::move(patch));
    }
  }

  /// Whether every source of inserted vertex `k` lies in a region that is a
  /// plane (SupportPlanes::regionPlanes).
  bool sourcesOnOwnPlanes(std::uint32_t k) const {
    const InsertedVertexSource &src = moves_.plan().inserted[k];
    for (int i = 0; i < src.originalCount; ++i) {
      const std::uint32_t s = src.original[i];
      if (s >= support_.region.size() || !regionPlaneOf(support_.regionPlanes, support_.region[s]))
        return false;
    }
    return true;
  }

  /// The new vertices of a patch's features.
  std::vector<std::uint32_t> membersOf(const CornerPatch &patch) const {
    std::vector<std::uint32_t> members;
    for (const std::uint32_t e : patch.edges)
      members.insert(members.end(), verticesOf_[e].begin(), verticesOf_[e].end());
    for (const std::uint32_t d : patch.corners)
      members.insert(members.end(), verticesOf_[d].begin(), verticesOf_[d].end());
    return members;
  }

  /// The features of `patch`, its edges then its corners.
  static std::vector<std::uint32_t> featuresOf(const CornerPatch &patch) {
    std::vector<std::uint32_t> out = patch.edges;
    out.insert(out.end(), patch.corners.begin(), patch.corners.end());
    return out;
  }

  /// Leaves a patch with edges as without it: each of its features restored
  /// in `verdicts` through the patch (`relabel`) goes back to the verdict of
  /// its own evidence, a corner restored on its own to CornerOfWeakEdge (its
  /// edges are left).
  template <class Relabel>
  void leavePatchFeatures(const CornerPatch &patch, const std::vector<Verdict> &verdicts,
                          Relabel relabel) const {
    for (const std::uint32_t c : featuresOf(patch)) {
      if (verdicts[c] != Verdict::Restored) continue;
      const Verdict own = ownVerdicts_[c];
      relabel(c, own == Verdict::Restored ? Verdict::CornerOfWeakEdge : own);
    }
  }

  /// Whether every feature of `patch` is restored.
  static bool patchRestored(const CornerPatch &patch, const std::vector<Verdict> &verdicts) {
    for (const std::uint32_t e : patch.edges)
      if (verdicts[e] != Verdict::Restored) return false;
    for (const std::uint32_t d : patch.corners)
      if (verdicts[d] != Verdict::Restored) return false;
    return true;
  }

  /// Moves the vertices of every corner patch restored (findCornerPatches)
  /// to its point.
  void placeCornerPatches(const std::vector<Verdict> &verdicts) {
    using Scalar = typename MeshType::ScalarType;
    const std::size_t first = moves_.firstInserted();
    for (CornerPatch &patch : patches_) {
      if (!patchRestored(patch, verdicts)) continue;
      patch.members = patch.vertices;
      for (const std::uint32_t k : patch.members) {
        auto &v = m_.vert[first + k];
        patch.before.push_back(positionOf(&v));
        patch.placedBefore.push_back(moves_.labels().placement[first + k]);
        v.P() = vcg::Point3<Scalar>::Construct(patch.point);
        moves_.labels().placement[first + k] = Placement::Moved;
      }
    }
  }

 public:
  /// Whether the degenerate cleanup or the intersection guard sent back a
  /// vertex of a corner patch (placeCornerPatches): the faces around the
  /// corner's point could not all be made valid, and a patch goes whole or
  /// not at all.
  bool cornerPatchRefused() {
    bool any = false;
    for (CornerPatch &patch : patches_) any = (patch.refused = refused(patch)) || any;
    return any;
  }

  /// Gives up every corner patch the cleanup refused (as cornerPatchRefused
  /// found, before the mesh was taken back to the snapshot before it): a
  /// corner feature alone goes back to placement's own targets, one vertex at
  /// a time; a patch with an edge is left as it came (its edge
  /// LineAcrossChamfer, its corners CornerOfWeakEdge, as without the patch),
  /// its vertices and their sources at rest. \pre the mesh is as
  /// revertWeakFeatures() left it.
  void leaveRefusedCornerPatches(EvidenceStats &stats) {
    using Scalar = typename MeshType::ScalarType;
    const std::size_t first = moves_.firstInserted();
    const auto relabel = [&](std::uint32_t c, Verdict v) {
      if (verdicts_[c] != Verdict::Restored) return;
      ++stats.weakFeatures;
      verdicts_[c] = v;
    };
    for (CornerPatch &patch : patches_) {
      if (!patch.refused) continue;
      if (patch.edges.empty()) {
        for (std::size_t j = 0; j < patch.members.size(); ++j) {
          m_.vert[first + patch.members[j]].P() = vcg::Point3<Scalar>::Construct(patch.before[j]);
          moves_.labels().placement[first + patch.members[j]] = patch.placedBefore[j];
        }
      } else {
        leavePatchFeatures(patch, verdicts_, [&](std::uint32_t c, Verdict v) { relabel(c, v); });
        for (const std::uint32_t k : patch.members) sendBackWithSources(k, stats);
      }
      patch.members.clear();
      patch.refused = false;
    }
    stats.verdicts = countVerdicts(verdicts_);
  }

 private:
  /// Sends inserted vertex `k` (split plan order) back to rest as
  /// Placement::WeakEvidence, and the zone vertices projected beside it (its
  /// sources), counting both in `stats`.
  void sendBackWithSources(std::size_t k, EvidenceStats &stats) {
    const std::size_t first = moves_.firstInserted();
    if (moves_.isMoved(first + k)) {
      moves_.sendBack(first + k, Placement::WeakEvidence);
      ++stats.reverted;
    }
    const InsertedVertexSource &source = moves_.plan().inserted[k];
    for (int i = 0; i < source.originalCount; ++i) {
      const std::size_t v = source.original[i];
      if (!m_.vert[v].IsD() && moves_.isMoved(v)) {
        moves_.sendBack(v, Placement::Original);
        ++stats.zoneReverted;
      }
    }
  }

  /// Whether the cleanup or the intersection guard sent back a vertex of
  /// `patch` it placed.
  bool refused(const CornerPatch &patch) const {
    const std::size_t first = moves_.firstInserted();
    for (const std::uint32_t k : patch.members)
      if (!m_.vert[first + k].IsD() &&
          (moves_.labels().placement[first + k] == Placement::DegenerateRevert ||
           moves_.labels().placement[first + k] == Placement::IntersectionRevert))
        return true;
    return false;
  }

  std::vector<CornerPatch> patches_;                    ///< findCornerPatches
  std::vector<std::vector<std::uint32_t>> verticesOf_;  ///< per feature: its inserted vertices
  std::vector<Verdict> ownVerdicts_;  ///< per feature: judgeFeature on its own (findCornerPatches)
  MeshType &m_;
  VertexMoves<MeshType> &moves_;
  const SupportPlanes &support_;
  InputSurface input_;
  SurfaceMeasures surface_;
  double longestInputEdge_;
  const SharpenOptions &opt_;
  const HeldFaces &held_;
  std::vector<Feature> features_;
  std::vector<std::uint32_t> featureOf_;
  bool exactSampling_ = false;          ///< sampledExactly, set by judge()
  std::vector<Verdict> verdicts_;       ///< per feature, set by revertWeakFeatures()
  std::vector<char> outsideSelection_;  ///< verticesOutsideSelection (empty: no selection)
  /// Per inserted vertex: in a feature already sharp, its own move slides,
  /// or it lies outside the user's selection (set by keptMoves). Such a
  /// vertex is neither moved nor refused (the input is sharp there, or the
  /// user chose): the count after the guards leaves it out.
  std::vector<char> slidingVertex_;
  std::vector<char> retreatFirst_;  ///< keptMoves: by vertex index
};

}  // namespace edge_sharpener
