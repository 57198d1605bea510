// Stage 5: moves each inserted vertex onto the intersection of the planes
// extrapolated from the adjacent smooth regions (paper, Figures 5 and 6),
// or keeps it at rest for one of the paper's degenerate cases; in the
// extended method, an edge vertex whose flank bends away goes onto the
// flanks as curved surfaces (detail::onCurvedFlanks).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "options.h"
#include "subdivision.h"
#include "util/curved_flank.h"
#include "util/statistics.h"

namespace edge_sharpener {

/// The unit "support" normal of every vertex: the sum of the normals of its
/// incident red triangles weighted by the triangle's angle at the vertex
/// (paper: "as weights, we use the angle between the two edges of the
/// incident triangle that meet at A"). Zero where no red triangle touches it.
/// With `wanted`, only the vertices v with (*wanted)[v] != 0 get theirs (the
/// same values, bit for bit); the others get zero.
template <class MeshType>
std::vector<Vec3> computeSupportNormals(MeshType &m, MeshLabels<MeshType> &labels,
                                        const std::vector<char> *wanted = nullptr) {
  std::vector<Vec3> normal(m.vert.size(), Vec3(0, 0, 0));
  for (auto &f : m.face) {
    if (f.IsD() || labels.face[&f] != FaceLabel::Red) continue;
    std::size_t vi[3];
    bool any = false;
    for (int i = 0; i < 3; ++i) {
      vi[i] = vcg::tri::Index(m, f.cV(i));
      any |= !wanted || (*wanted)[vi[i]];
    }
    if (!any) continue;
    const Vec3 p[3] = {positionOf(f.cV(0)), positionOf(f.cV(1)), positionOf(f.cV(2))};
    for (int i = 0; i < 3; ++i) {
      if (wanted && !(*wanted)[vi[i]]) continue;
      const double w = cornerAngle(p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
      normal[vi[i]] += labels.normal[&f] * w;
    }
  }
  for (auto &n : normal) {
    const double len = n.Norm();
    n = len > 1e-12 ? n / len : Vec3(0, 0, 0);
  }
  return normal;
}

/// One support plane and, for the extended method, how the region it was
/// fitted to departs from it there.
struct SupportFit {
  Plane plane{Vec3(0, 0, 0), Vec3(0, 0, 0)};  ///< zero normal: no plane
  /// Largest angle between the plane's normal and the normals of the region
  /// faces it was fitted to (extended method).
  double spreadRad = 0;
  /// Scatter of the fitted faces' normals and centroids about the plane
  /// (geometry.h: extrapolationBend), and of their normal deviations.
  CrossScatter3 normalScatter, pointScatter, normalSelfScatter;

  /// A plane without measures.
  static SupportFit of(const Plane &plane, double spreadRad = 0) {
    SupportFit fit;
    fit.plane = plane;
    fit.spreadRad = spreadRad;
    return fit;
  }
};

/// The plane extrapolated from the smooth region next to each original
/// vertex (zero normal: none), and how curved that region is there.
/// Sparse: only the vertices near a feature have a plane, and zone vertices
/// share their anchor's, so each vertex holds an index into `fits`.
struct SupportPlanes {
  static constexpr std::uint32_t kNoFit = ~std::uint32_t(0);
  /// Per vertex: its entry in `fits`, or kNoFit.
  std::vector<std::uint32_t> fitOf;
  std::vector<SupportFit> fits;
  /// Extended method: the fits carry spread and scatters (placement's
  /// curvature tests read them); false for the paper's method.
  bool measured = false;
  /// Extended method: the region each vertex's plane belongs to (-1: none)...
  std::vector<int> region;
  /// ...and, for vertices next to the feature zone, vertices holding the
  /// planes of up to three other regions found nearby (closest first;
  /// kNoVertex pads). Empty for the paper's method.
  static constexpr std::uint32_t kNoVertex = ~std::uint32_t(0);
  std::vector<std::array<std::uint32_t, 3>> nearby;
  /// Extended method: per region, its own plane where it is one
  /// (planarRegionPlanes; zero normal: not a plane). Empty: none.
  std::vector<Plane> regionPlanes;
  /// Extended method: the input's sample spacing (median edge length);
  /// 0 for the paper's method.
  double sampleSpacing = 0;

  /// n vertices without a plane.
  void reset(std::size_t n) {
    fitOf.assign(n, kNoFit);
    fits.clear();
  }
  /// Vertex v's plane and measures (all zero when it has none).
  const SupportFit &fit(std::size_t v) const {
    static const SupportFit none{};
    return fitOf[v] == kNoFit ? none : fits[fitOf[v]];
  }
  const Plane &plane(std::size_t v) const { return fit(v).plane; }
  /// Vertex v takes a new entry.
  void setFit(std::size_t v, const SupportFit &f) {
    fitOf[v] = std::uint32_t(fits.size());
    fits.push_back(f);
  }
  /// Vertex `to` takes the plane and measures of `from`.
  void shareFit(std::size_t to, std::size_t from) { fitOf[to] = fitOf[from]; }
};

/// The paper's support planes: through each original vertex, orthogonal to
/// its support normal (a zero normal where no red triangle touches it).
/// Only the vertices of chamfer and corner faces get a normal - the only
/// planes placement reads (the sources of the inserted vertices); the others
/// get a zero one. \pre runSixFilters() ran.
template <class MeshType>
SupportPlanes paperSupportPlanes(MeshType &m, MeshLabels<MeshType> &labels) {
  std::vector<char> wanted(m.vert.size(), 0);
  for (auto &f : m.face) {
    const FaceLabel label = labels.face[&f];
    if (f.IsD() || (label != FaceLabel::Chamfer && label != FaceLabel::Corner)) continue;
    for (int i = 0; i < 3; ++i) wanted[vcg::tri::Index(m, f.cV(i))] = 1;
  }
  const std::vector<Vec3> normal = computeSupportNormals(m, labels, &wanted);
  SupportPlanes support;
  support.reset(normal.size());
  for (std::size_t i = 0; i < normal.size(); ++i)
    if (wanted[i]) support.setFit(i, SupportFit::of(Plane{positionOf(&m.vert[i]), normal[i]}));
  return support;
}

namespace detail {

/// Pairs of flanks that meet at an inserted vertex: AB on an edge, AB BC CA
/// at a corner (pair i is planes i and (i + 1) % originalCount).
inline int flankPairCount(const InsertedVertexSource &src) {
  return src.originalCount == 2 ? 1 : 3;
}

/// Whether a flank's region, curving across the feature as measured where
/// its plane was fitted (a blend, a coarse cylinder's facets), leaves that
/// plane before reaching `target` by more than opt.extended.maxBendFraction x the
/// vertex's displacement (geometry.h: extrapolationBend).
inline bool flankBendsAway(const InsertedVertexSource &src, const Plane *planes,
                           const SupportPlanes &support, const SharpenOptions &opt,
                           const Vec3 &target) {
  const double allowed = opt.extended.maxBendFraction * (target - src.rest).Norm();
  // An edge vertex: the bend is measured across the edge only.
  const Vec3 edge = src.originalCount == 2 ? planes[0].normal ^ planes[1].normal : Vec3(0, 0, 0);
  const double edgeLength = edge.Norm();
  for (int i = 0; i < src.originalCount; ++i) {
    const std::size_t v = src.original[i];
    Vec3 w = target - planes[i].point;
    w -= planes[i].normal * (planes[i].normal * w);
    if (edgeLength > 0) w -= edge * ((edge * w) / (edgeLength * edgeLength));
    const double d = w.Norm();
    if (!(d > 0)) continue;
    // Below this spread the regression mostly sees marching-cubes noise,
    // unless the normals follow position cleanly (a finely sampled curve).
    const SupportFit &fit = support.fit(v);
    if (fit.spreadRad < opt.extended.minBendSpreadRad &&
        curveFitQuality(fit.normalScatter, fit.pointScatter, fit.normalSelfScatter, w / d) <
            opt.extended.minBendFitQuality)
      continue;
    if (extrapolationBend(fit.normalScatter, fit.pointScatter, w / d, d) > allowed) return true;
  }
  return false;
}

/// An edge vertex whose flank bends away before its target (flankBendsAway
/// found it, and the move is short enough that this only marks it:
/// veto::bendOnlyMarks) is moved from between its planes onto the curve
/// where its two flanks meet as curved surfaces (util/curved_flank.h: each
/// fit's plane bent by the shape operator its faces' normals show). Planes
/// extrapolated from a convex curved flank meet beyond its edge: a torus'
/// rim restored that way lies outside the solid. A flank whose region is a
/// plane (planarRegionPlanes) stays flat: there the normals follow the
/// sampler, not the shape. The curved point is taken only as a correction:
/// no farther from the planes' point than that lies from rest.
inline void onCurvedFlanks(const InsertedVertexSource &src, const Plane *planes,
                           const SupportPlanes &support, Vec3 &target) {
  if (src.originalCount != 2 || !support.measured) return;
  Vec3 edge = planes[0].normal ^ planes[1].normal;
  if (!(edge.Norm() > 0)) return;
  edge /= edge.Norm();
  CurvedFlank flank[2];
  for (int i = 0; i < 2; ++i) {
    const std::size_t s = src.original[i];
    const SupportFit &fit = support.fit(s);
    const bool planar = s < support.region.size() &&
                        regionPlaneOf(support.regionPlanes, support.region[s]) != nullptr;
    flank[i] = planar ? curvedFlank(planes[i], {}, {})
                      : curvedFlank(planes[i], fit.normalScatter, fit.pointScatter,
                                    planes[i].normal ^ edge);
  }
  if (!flank[0].curved() && !flank[1].curved()) return;
  const double spacing = support.sampleSpacing > 0 ? support.sampleSpacing : 1.0;
  const auto bent = onBothFlanks(flank[0], flank[1], target, 1e-7 * spacing);
  if (bent && (*bent - target).Norm() <= (target - src.rest).Norm()) target = *bent;
}

/// At a corner, whether the flanks of any pair of its planes, meeting along
/// their own line (the corner's edge through that pair), bend away before
/// reaching it: a corner where a flat face meets two facets of one coarse
/// cylinder passes the three-plane test while each edge-like pair overshoots.
inline bool cornerPairBendsAway(const InsertedVertexSource &src, const Plane *planes,
                                const SupportPlanes &support, const SharpenOptions &opt) {
  if (src.originalCount != 3) return false;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    InsertedVertexSource pair = src;
    pair.originalCount = 2;
    pair.original = {src.original[i], src.original[j], 0};
    const Plane pairPlanes[2] = {planes[i], planes[j]};
    const auto onLine = closestPointOnPlanePairLine(pairPlanes[0], pairPlanes[1], src.rest,
                                                    opt.paper.parallelAngleRad);
    if (onLine && flankBendsAway(pair, pairPlanes, support, opt, *onLine)) return true;
  }
  return false;
}

/// Whether `found(u)` holds for a vertex u that the sources list nearby
/// (SupportPlanes::nearby) and whose region is none of the sources' own
/// (a third region: an intermediate facet, a corner's third face).
template <class Found>
bool anyNearbyThirdRegion(const InsertedVertexSource &src, const SupportPlanes &support,
                          Found &&found) {
  const int n = src.originalCount;
  const auto isFlank = [&](int region) {
    for (int i = 0; i < n; ++i)
      if (support.region[src.original[i]] == region) return true;
    return false;
  };
  for (int i = 0; i < n; ++i)
    for (std::uint32_t u : support.nearby[src.original[i]]) {
      if (u == SupportPlanes::kNoVertex) break;
      if (!isFlank(support.region[u]) && found(u)) return true;
    }
  return false;
}

/// Whether `target` passes, by more than opt.extended.intermediatePlaneTolerance x the
/// vertex's displacement, through the plane of a region found near the
/// sources whose normal lies between two flanks' (a facet of a coarse curve,
/// a strip of a blend): the planes' line or corner would cut through it.
inline bool passesIntermediateRegion(const InsertedVertexSource &src, const Plane *planes,
                                     const SupportPlanes &support, const SharpenOptions &opt,
                                     const Vec3 &target) {
  const double allowed = opt.extended.intermediatePlaneTolerance * (target - src.rest).Norm();
  const int n = src.originalCount;
  Vec3 normalSum(0, 0, 0);
  for (int i = 0; i < n; ++i) normalSum += planes[i].normal;
  return anyNearbyThirdRegion(src, support, [&](std::uint32_t u) {
    const Plane &l = support.plane(u);
    bool between = false;
    for (int a = 0; a < flankPairCount(src); ++a)
      between |= normalBetween(planes[a].normal, planes[(a + 1) % n].normal, l.normal,
                               opt.extended.intermediateSlackRad);
    return between && passageBeyondPlane(normalSum, l, src.rest, target) > allowed;
  });
}

}  // namespace detail

/// What placement does differently per method, chosen once by each method's
/// pipeline (sharpen_impl.h).
struct PlacementPolicy {
  /// The paper's settings as placement applies them. At a saddle corner,
  /// where a concave edge meets convex ones, the chamfer edges near the
  /// corner lie between a concave and a convex side too: the paper cannot
  /// tell them from a step between two surfaces and keeps them at rest. The
  /// auto method turns the convexity check off and judges them by its own
  /// tests instead (the planes' apex and distance, the flanks' bends, the
  /// evidence of the whole feature).
  PaperSettings paper;
  /// The extended method's vetoes (veto::) and its own-plane placement.
  bool vetoes = false;
  /// A move the bend test would refuse moves when at most this many sample
  /// spacings long, left to its feature's evidence (auto; 0: refused).
  double bentMoveSpacings = 0;
  /// The edge-length check's bound, times the input's longest edge.
  double edgeLengthFactor = 1.0;

  static PlacementPolicy paperMethod(const SharpenOptions &opt) {
    return {opt.paper, false, 0, 1.0};
  }
  static PlacementPolicy extendedMethod(const SharpenOptions &opt) {
    return {opt.paper, true, 0, opt.extended.extendedEdgeLengthFactor};
  }
  static PlacementPolicy autoMethod(const SharpenOptions &opt) {
    PaperSettings paper = opt.paper;
    paper.convexityCheck = false;
    return {paper, true, opt.rules.vertex.maxBentMoveSpacings,
            opt.extended.extendedEdgeLengthFactor};
  }
};

/// The paper's placement of one inserted vertex (section 3, Figures 5 and 6)
/// between its source vertices' support planes: the point of the planes'
/// line nearest the rest position (a chamfer edge) or the three planes'
/// common point (a corner), or one of the paper's degenerate cases.
/// \return the outcome and, for Placement::Moved, the target in `target`.
inline Placement paperPlacement(const InsertedVertexSource &src, const Plane *planes,
                                const PaperSettings &paper, Vec3 &target) {
  if (paper.convexityCheck) {
    const double flat = std::sin(paper.parallelAngleRad);
    for (int i = 0; i < detail::flankPairCount(src); ++i) {
      const int j = (i + 1) % src.originalCount;
      if (classifyChamferEdge(planes[i], planes[j], flat) == EdgeConvexity::Mixed)
        return Placement::MixedConvexity;
    }
  }
  if (src.originalCount == 2) {
    auto x = closestPointOnPlanePairLine(planes[0], planes[1], src.rest, paper.parallelAngleRad);
    if (!x) return Placement::ParallelPlanes;
    target = *x;
  } else {
    auto x = intersectThreePlanes(planes[0], planes[1], planes[2], paper.parallelAngleRad);
    if (!x) return Placement::CoplanarNormals;
    target = *x;
  }
  return Placement::Moved;
}

namespace detail {

/// The largest angle between the fitted planes of `src`'s sources and their
/// regions' own planes (SupportPlanes::regionPlanes), over the sources whose
/// region is a plane; -1 where none is.
inline double ownPlaneTurnRad(const InsertedVertexSource &src, const SupportPlanes &support) {
  double turn = -1;
  for (int i = 0; i < src.originalCount; ++i) {
    const std::size_t s = src.original[i];
    if (const Plane *own = regionPlaneOf(support.regionPlanes, support.region[s]))
      turn = std::max(turn, angleBetween(own->normal, support.plane(s).normal));
  }
  return turn;
}

}  // namespace detail

/// Per pair of regions an edge runs between, the median turn of its edge
/// vertices' fitted planes from their regions' own planes
/// (detail::ownPlaneTurnRad): a reconstruction rounds a sharp edge about
/// alike along its length, and turns the fits next to it about alike.
class OwnPlaneTurns {
 public:
  OwnPlaneTurns() = default;
  OwnPlaneTurns(const SplitPlan &plan, const SupportPlanes &support) {
    if (support.regionPlanes.empty()) return;
    std::unordered_map<std::uint64_t, std::vector<double>> turns;
    for (const InsertedVertexSource &src : plan.inserted) {
      const double turn = src.originalCount == 2 ? detail::ownPlaneTurnRad(src, support) : -1;
      if (turn >= 0) turns[key(src, support)].push_back(turn);
    }
    for (auto &[pair, values] : turns) median_[pair] = detail::medianOf(values);
  }
  /// The median turn (radians) of the edge whose vertex `src` is; -1 where
  /// none is known (a corner vertex, a region that is no plane).
  double typicalRad(const InsertedVertexSource &src, const SupportPlanes &support) const {
    if (src.originalCount != 2 || median_.empty()) return -1;
    const auto it = median_.find(key(src, support));
    return it == median_.end() ? -1 : it->second;
  }

 private:
  static std::uint64_t key(const InsertedVertexSource &src, const SupportPlanes &support) {
    const auto a = std::uint32_t(support.region[src.original[0]]);
    const auto b = std::uint32_t(support.region[src.original[1]]);
    return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
  }
  std::unordered_map<std::uint64_t, double> median_;
};

namespace detail {

/// Moves `target`, the placement between the planes fitted next to the
/// feature, onto the sources' regions' own planes (SupportPlanes::
/// regionPlanes) where every source's region is a plane (at a `bent` vertex,
/// beside a curved flank too: see below) and the placement
/// between those planes lies more than ExtendedSettings::kMinShiftSpacings and at most one
/// sample spacing from `target` (the vetoes judged the move from there),
/// and where each source's fitted plane turns by at most ExtendedSettings::kOwnPlaneMaxTurnRad
/// from its region's: a region can take in a second surface across a crease
/// its sampling blurs (a nut's conical chamfer beside its flat top), and
/// there the fit beside the feature, not the region's core, is the flank.
/// Closer, the fits are as good, and exact planes would make faces along a
/// concave edge coincide exactly, which the cleanup and the intersection
/// guard then undo. Near a corner the fits next to a source see the third
/// face: an edge vertex takes its flanks' own line only where every other
/// region nearby is a plane too, and stops at the corner where that line
/// meets it (keepBeforeEndPlane); a corner vertex only where no fourth
/// region lies nearby. Nor where an edge vertex's fits turn from the own
/// planes more than ExtendedSettings::kOwnPlaneMaxExtraTurnRad beyond its edge's typical turn
/// (`typicalTurnRad`, OwnPlaneTurns; negative: not known): a reconstruction
/// rounds the whole edge alike, while a fit that turns alone sees where the
/// flank runs on into another surface (a fillet at the edge's end), past
/// which the own planes' line runs on straight. A vertex marked `bent` (a
/// flank bends away before its target: detail::onCurvedFlanks) whose other
/// flank's region is no plane takes the own plane of each flank whose region
/// is one, and the curved flanks' point from there: a plane meeting a curved
/// face (a cylinder's cap) is the better estimate of that flank. A region's
/// own plane stands for a flank only where it passes within
/// `maxOffPlaneSpacings` (negative: any distance) of the samples fitted next
/// to the feature; farther, the region is a slightly curved face taken for a
/// plane, and that flank keeps its fit.
inline void onRegionPlanes(const InsertedVertexSource &src, const SupportPlanes &support,
                           const PaperSettings &paper, Vec3 &target, double typicalTurnRad = -1,
                           bool bent = false, double maxOffPlaneSpacings = -1) {
  if (support.regionPlanes.empty()) return;
  const double turn = ownPlaneTurnRad(src, support);
  if (turn < 0 || turn > ExtendedSettings::kOwnPlaneMaxTurnRad) return;
  if (typicalTurnRad >= 0 && turn > typicalTurnRad + ExtendedSettings::kOwnPlaneMaxExtraTurnRad)
    return;
  const auto ownPlane = [&](int region) { return regionPlaneOf(support.regionPlanes, region); };
  // A flank keeps its fitted plane where its region is no plane (only beside
  // a bent flank) or where the region's plane passes far from its samples.
  Plane own[3];
  for (int i = 0; i < src.originalCount; ++i) {
    const Plane fit = support.plane(src.original[i]);
    const Plane *regionPlane = ownPlane(support.region[src.original[i]]);
    if (!regionPlane && !bent) return;
    const bool farFromSamples = regionPlane && maxOffPlaneSpacings >= 0 &&
                                std::abs(regionPlane->normal * (fit.point - regionPlane->point)) >
                                    maxOffPlaneSpacings * support.sampleSpacing;
    own[i] = regionPlane && !farFromSamples ? *regionPlane : fit;
  }
  // An edge vertex's two sources list up to three nearby regions each.
  constexpr int kMaxEnds = 6;
  const Plane *ends[kMaxEnds];
  int endCount = 0;
  const bool blocked = anyNearbyThirdRegion(src, support, [&](std::uint32_t u) {
    const Plane *end = src.originalCount == 2 ? ownPlane(support.region[u]) : nullptr;
    if (!end) return true;
    if (std::find(ends, ends + endCount, end) == ends + endCount) ends[endCount++] = end;
    return false;
  });
  if (blocked) return;
  Vec3 onOwn;
  if (paperPlacement(src, own, paper, onOwn) != Placement::Moved) return;
  if (bent) onCurvedFlanks(src, own, support, onOwn);
  for (int k = 0; k < endCount; ++k) {
    const auto kept = keepBeforeEndPlane(own[0], own[1], *ends[k], onOwn, paper.parallelAngleRad);
    if (!kept) return;
    onOwn = *kept;
  }
  const double shift = (onOwn - target).Norm();
  if (shift > ExtendedSettings::kMinShiftSpacings * support.sampleSpacing &&
      shift <= support.sampleSpacing)
    target = onOwn;
}

}  // namespace detail

/// The extended method's vetoes: each is a named test that keeps an inserted
/// vertex at rest and says why, or lets it move (std::nullopt). A veto whose
/// measures the support planes do not carry lets it move.
namespace veto {

/// The outcome a veto keeps a vertex at rest with, or none.
using Refusal = std::optional<Placement>;

/// A region that turns as much near the feature as the feature itself is a
/// blend or a facetted curve, not the flank of a sharp edge.
inline Refusal regionsTurnLikeABlend(const InsertedVertexSource &src, const Plane *planes,
                                     const SupportPlanes &support, const SharpenOptions &opt) {
  if (!support.measured || !(opt.extended.maxSupportSpreadRatio > 0)) return std::nullopt;
  for (int i = 0; i < detail::flankPairCount(src); ++i) {
    const int j = (i + 1) % src.originalCount;
    const double theta = angleBetween(planes[i].normal, planes[j].normal);
    const double spread =
        std::max(support.fit(src.original[i]).spreadRad, support.fit(src.original[j]).spreadRad);
    if (spread > opt.extended.maxSupportSpreadRatio * theta) return Placement::CurvedSupport;
  }
  return std::nullopt;
}

/// A flank bends away from its plane before the target (detail::flankBendsAway),
/// or, at a corner, before the line of a pair of its planes.
inline Refusal flankBendsAway(const InsertedVertexSource &src, const Plane *planes,
                              const SupportPlanes &support, const SharpenOptions &opt,
                              const Vec3 &target) {
  if (!support.measured || opt.extended.maxBendFraction < 0) return std::nullopt;
  if (detail::flankBendsAway(src, planes, support, opt, target) ||
      detail::cornerPairBendsAway(src, planes, support, opt))
    return Placement::CurvedSupport;
  return std::nullopt;
}

/// The target lies beyond the plane of a region between the flanks
/// (detail::passesIntermediateRegion): the surface turns through facets.
inline Refusal passesIntermediateRegion(const InsertedVertexSource &src, const Plane *planes,
                                        const SupportPlanes &support, const SharpenOptions &opt,
                                        const Vec3 &target) {
  if (support.nearby.empty() || opt.extended.intermediatePlaneTolerance < 0) return std::nullopt;
  if (detail::passesIntermediateRegion(src, planes, support, opt, target))
    return Placement::CurvedSupport;
  return std::nullopt;
}

/// The planes meet higher above the chamfer than their angle allows
/// (geometry.h: chamferApexHeightRatio).
inline Refusal apexTooHigh(const InsertedVertexSource &src, const Plane *planes,
                           const SharpenOptions &opt, const Vec3 &target) {
  if (!(opt.extended.apexHeightFactor > 0)) return std::nullopt;
  for (int i = 0; i < detail::flankPairCount(src); ++i)
    if (chamferApexHeightRatio(planes[i], planes[(i + 1) % src.originalCount], target) >
        opt.extended.apexHeightFactor)
      return Placement::FarFromChamfer;
  return std::nullopt;
}

/// The target lies more than maxDisplacementSpacings sample spacings away.
inline Refusal displacementTooLarge(const InsertedVertexSource &src, const SupportPlanes &support,
                                    const SharpenOptions &opt, const Vec3 &target) {
  if (!(support.sampleSpacing > 0) || !(opt.extended.maxDisplacementSpacings > 0))
    return std::nullopt;
  if ((target - src.rest).Norm() > opt.extended.maxDisplacementSpacings * support.sampleSpacing)
    return Placement::FarFromChamfer;
  return std::nullopt;
}

/// Whether the bend test only marks a vertex (MeshLabels::bentFlank) instead
/// of keeping it at rest, for a move to `target`: in the auto method, a move
/// within VertexRules::maxBentMoveSpacings is left to its feature's evidence
/// (a sampler's rounding, not a curved flank extrapolated far).
inline bool bendOnlyMarks(const InsertedVertexSource &src, const SupportPlanes &support,
                          const PlacementPolicy &policy, const Vec3 &target) {
  return policy.bentMoveSpacings > 0 && support.sampleSpacing > 0 &&
         (target - src.rest).Norm() <= policy.bentMoveSpacings * support.sampleSpacing;
}

/// The vetoes that need the paper's target, in the order they are tried.
/// `bent`: whether the flank bends away, when that alone does not keep the
/// vertex at rest (bendOnlyMarks).
inline Refusal anyAtTarget(const InsertedVertexSource &src, const Plane *planes,
                           const SupportPlanes &support, const SharpenOptions &opt,
                           const PlacementPolicy &policy, const Vec3 &target, bool &bent) {
  if (Refusal v = flankBendsAway(src, planes, support, opt, target)) {
    if (!bendOnlyMarks(src, support, policy, target)) return v;
    bent = true;
  }
  if (Refusal v = passesIntermediateRegion(src, planes, support, opt, target)) return v;
  if (Refusal v = apexTooHigh(src, planes, opt, target)) return v;
  return displacementTooLarge(src, support, opt, target);
}

}  // namespace veto

/// Where the planes put one inserted vertex, before the edge-length check:
/// the paper's placement, and with policy.vetoes the extended method's vetoes.
/// \return the outcome and, for Placement::Moved, the target in `target` and
///         in `bent` whether a flank bends away before it (veto::anyAtTarget).
inline Placement proposePlacement(const InsertedVertexSource &src, const SupportPlanes &support,
                                  const SharpenOptions &opt, const PlacementPolicy &policy,
                                  Vec3 &target, bool &bent,
                                  const OwnPlaneTurns &typicalTurns = {}) {
  bent = false;
  Plane planes[3];
  for (int i = 0; i < src.originalCount; ++i) {
    planes[i] = support.plane(src.original[i]);
    if (planes[i].normal.SquaredNorm() == 0) return Placement::NoSupportPlane;
  }
  if (policy.vetoes)
    if (veto::Refusal v = veto::regionsTurnLikeABlend(src, planes, support, opt)) return *v;
  const Placement paper = paperPlacement(src, planes, policy.paper, target);
  if (!policy.vetoes || paper != Placement::Moved) return paper;
  const Placement outcome =
      veto::anyAtTarget(src, planes, support, opt, policy, target, bent).value_or(Placement::Moved);
  if (outcome == Placement::Moved) {
    if (bent) detail::onCurvedFlanks(src, planes, support, target);
    detail::onRegionPlanes(src, support, policy.paper, target,
                           typicalTurns.typicalRad(src, support), bent,
                           opt.rules.feature.maxFeatureOffPlaneSpacings);
  }
  return outcome;
}

/// Edge-length check (paper, Figure 7): an inserted vertex may not create an
/// edge longer than the longest edge of the input. Offending moved vertices
/// return to rest; repeated until stable, since a return can lengthen an
/// edge to another moved vertex. \return vertices sent back.
template <class MeshType>
std::size_t enforceEdgeLength(MeshType &m, const SplitPlan &plan, MeshLabels<MeshType> &labels,
                              std::vector<Vec3> &insertedPos, double longestEdge) {
  const std::size_t n0 = plan.originalVertexCount;
  const double limit2 = longestEdge * longestEdge;
  const auto pos = [&](const typename MeshType::VertexType *v) {
    const std::size_t i = vcg::tri::Index(m, v);
    return i >= n0 ? insertedPos[i - n0] : positionOf(v);
  };
  std::size_t rejected = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (auto &f : m.face) {
      const FaceLabel label = labels.face[&f];
      if (f.IsD() || (label != FaceLabel::Chamfer && label != FaceLabel::Corner)) continue;
      for (int i = 0; i < 3; ++i) {
        const auto *a = f.cV(i), *b = f.cV((i + 1) % 3);
        const bool aMoved = labels.placement[a] == Placement::Moved;
        const bool bMoved = labels.placement[b] == Placement::Moved;
        if (!aMoved && !bMoved) continue;
        if ((pos(a) - pos(b)).SquaredNorm() <= limit2) continue;
        for (const auto *v : {a, b}) {
          if (labels.placement[v] != Placement::Moved) continue;
          const std::size_t k = vcg::tri::Index(m, v) - n0;
          labels.placement[v] = Placement::EdgeTooLong;
          insertedPos[k] = plan.inserted[k].rest;
          ++rejected;
        }
        changed = true;
      }
    }
  }
  return rejected;
}

/// Stage 5: proposes a position for every inserted vertex, applies the
/// degenerate-case fallbacks, and writes the positions into the mesh; each
/// inserted vertex's outcome is its placement label (counted at the end of
/// sharpening: VertexMoves::countOutcomes). Original vertices are never
/// touched.
/// \pre subdivide() ran with `plan`; `longestEdge` is the input's longest
///      edge; `support` holds one plane per original vertex.
template <class MeshType>
void placeInsertedVertices(MeshType &m, const SplitPlan &plan, MeshLabels<MeshType> &labels,
                           double longestEdge, const SharpenOptions &opt,
                           const PlacementPolicy &policy, const SupportPlanes &support) {
  using Scalar = typename MeshType::ScalarType;
  const std::size_t n0 = plan.originalVertexCount;
  std::vector<Vec3> insertedPos(plan.inserted.size());
  const OwnPlaneTurns typicalTurns(plan, support);
  for (std::size_t k = 0; k < plan.inserted.size(); ++k) {
    insertedPos[k] = plan.inserted[k].rest;
    Vec3 target;
    bool bent = false;
    const Placement p =
        proposePlacement(plan.inserted[k], support, opt, policy, target, bent, typicalTurns);
    if (p == Placement::Moved) insertedPos[k] = target;
    labels.placement[n0 + k] = p;
    labels.bentFlank[n0 + k] = p == Placement::Moved && bent;
  }
  if (opt.edgeLengthCheck)
    enforceEdgeLength(m, plan, labels, insertedPos, policy.edgeLengthFactor * longestEdge);
  for (std::size_t k = 0; k < plan.inserted.size(); ++k)
    m.vert[n0 + k].P() = vcg::Point3<Scalar>::Construct(insertedPos[k]);
}

}  // namespace edge_sharpener
