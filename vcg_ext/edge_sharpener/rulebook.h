// The rulebook: every number the methods decide by, named once and grouped
// as the decision is made. The tunable ones are fields of settings structs
// (SharpenOptions::paper, ::extended, ::rules; option_table.h gives each its
// command-line flag, Python keyword and MeshLab name); the fixed ones are
// constants beside them. docs/auto-rules.md explains each in one table row
// (a test keeps the two in step); docs/auto-method-decisions.md tells how
// each was found. Angles in radians.
#pragma once

#include <cmath>
#include <cstddef>
#include <string_view>
#include <vector>

namespace edge_sharpener {

// ===== The paper's degenerate cases (every method) =====

struct PaperSettings {
  /// Keep a new vertex unmoved when its chamfer is bordered by a concave edge
  /// on one side and a convex edge on the other (paper, section 3). The paper
  /// and extended methods; auto judges such moves by its own tests.
  bool convexityCheck = true;
  /// Two planes whose normals are closer than this count as parallel; three
  /// normals whose triple product is below its sine count as coplanar.
  double parallelAngleRad = 1.0 * M_PI / 180.0;
};

// ===== The extended method: detection and each vertex's placement =====
// (the extended and auto methods)

struct ExtendedSettings {
  // --- Detection: smooth regions and the feature zone between them
  /// A smooth region whose vertices are all fewer than this many hops from
  /// its border is a corridor (a regular chamfer band) and joins the zone.
  int minRegionDepth = 1;
  /// Return to the zone the region faces around vertices where two regions
  /// touch (feature_zones.h: openRegionContacts)...
  bool openRegionContacts = true;
  /// ...except the faces of a region that opening would leave without an
  /// interior vertex and that spans at least this many sample spacings (a
  /// narrow facet of a coarse cylinder). 0: such regions open too.
  double minFacetLengthSpacings = 10.0;
  /// Place a feature's new vertices on its flanks' regions' own planes where
  /// those regions are planes away from their features and no other region
  /// is near (planar_regions.h; placement.h: detail::onRegionPlanes).
  bool regionPlanes = true;
  /// Return to the zone the region faces around internal creases (a
  /// non-smooth edge inside one region: feature_zones.h: openInternalCreases)...
  bool openInternalCreases = true;
  /// ...whose face normals turn by more than this angle: below it, a
  /// non-smooth edge inside a region is marching-cubes noise...
  double internalCreaseAngleRad = 20.0 * M_PI / 180.0;
  /// ...and by more than this multiple of the smooth-edge threshold (a
  /// coarse sampling of a curved surface has large angles everywhere).
  double internalCreaseThresholdFactor = 3.0;
  /// Two vertices of one region whose planes turn by more than this angle lie
  /// on different surfaces: a chamfer edge may join them. 0: one region is
  /// one surface.
  double sameRegionFeatureAngleRad = 45.0 * M_PI / 180.0;
  /// Face rings around a region's border vertex used to fit its plane.
  int supportRings = 2;
  /// A region's plane is refitted without its faces turned more than this
  /// from the first fit: a region's border often holds a few faces of the
  /// chamfer. 0: no refit.
  double fitTrimAngleRad = 15.0 * M_PI / 180.0;
  /// A zone vertex considers the regions reaching it within this many hops
  /// of the closest one...
  int labelSlackHops = 2;
  /// ...and none farther than this: a region's plane extrapolated farther
  /// misses a curved surface, while a chamfer band of marching cubes is at
  /// most about 3 hops wide.
  int maxLabelHops = 3;

  // --- Placement: the tests that keep one new vertex at rest
  /// A zone vertex moves onto its region's plane only if the move is at most
  /// this fraction of its mean edge length.
  double maxProjectionFactor = 0.75;
  /// The edge-length check allows edges up to this multiple of the input's
  /// longest edge: the tip of an acute edge lies well beyond its chamfer.
  double extendedEdgeLengthFactor = 2.0;
  /// A new vertex stays at rest when the planes meet farther from it than
  /// this many sample spacings: a remesher's chamfer cuts a sample or two off
  /// a sharp edge, while a CAD mesh's long slivers throw vertices far away.
  /// A corner placed whole asks each of its vertices to rest this near each
  /// of its planes instead (the cut measured across its faces). 0 disables.
  double maxDisplacementSpacings = 2.5;
  /// ...or more than this factor above its chamfer than their angle allows
  /// (geometry.h: chamferApexHeightRatio). 0 disables.
  double apexHeightFactor = 1.5;
  /// ...or when the region next to it turns, over the fitted neighbourhood,
  /// by more than this fraction of the angle between the two planes: a
  /// finely sampled blend, not a sharp edge. 0 disables.
  double maxSupportSpreadRatio = 0.35;
  /// ...or when it would pass through the plane of a third region nearby
  /// whose normal lies between the two flanks' (within
  /// `intermediateSlackRad`) by more than this fraction of its displacement:
  /// the surface turns through facets or a blend. Negative disables.
  double intermediatePlaneTolerance = 0.3;
  /// How far a third region's normal may lie off the arc between the flanks'
  /// normals and still count as between them.
  double intermediateSlackRad = 10.0 * M_PI / 180.0;
  /// ...or when a flank's region, bending across the feature as measured
  /// where its plane was fitted, would leave that plane by more than this
  /// fraction of the vertex's displacement before reaching the sharp edge
  /// (geometry.h: extrapolationBend); at a corner, for each pair of its
  /// planes toward their own line. Negative disables...
  double maxBendFraction = 0.45;
  /// ...tested where the fitted faces spread by at least this angle: below
  /// it, marching cubes' staircase dominates the estimate...
  double minBendSpreadRad = 5.0 * M_PI / 180.0;
  /// ...or where the fitted faces' normals follow their position this well
  /// (geometry.h: curveFitQuality, in [0, 1]): a finely sampled curve.
  double minBendFitQuality = 0.9;

  // --- Fixed: where a region's own plane replaces the fitted one
  // (placement.h: detail::onRegionPlanes)
  /// A fitted plane moved less than this (sample spacings) is kept.
  static constexpr double kMinShiftSpacings = 0.1;
  /// A fitted plane turned farther than this from its region's own plane lies
  /// on another surface the region took in.
  static constexpr double kOwnPlaneMaxTurnRad = 30.0 * M_PI / 180.0;
  /// ...or farther than this beyond the typical turn of its edge's fits.
  static constexpr double kOwnPlaneMaxExtraTurnRad = 20.0 * M_PI / 180.0;
};

/// When a region counts as a plane (planar_regions.h: planarRegionPlanes).
struct PlanarRegionSettings {
  /// The core: the region's faces whose vertices all lie at least this many
  /// hops from the feature zone (beyond the rounding of a reconstruction).
  int coreHops = 3;
  /// A core of fewer faces tells nothing.
  int minCoreFaces = 20;
  /// The core's faces' centroids lie within this RMS distance of its plane
  /// (noise; in sample spacings)...
  double maxRmsSpacings = 0.25;
  /// ...and the mean normals of its two halves, split across either
  /// principal axis of its extent, turn by at most this angle (a curved
  /// region bends; noise averages out).
  double maxBendRad = 3.0 * M_PI / 180.0;
};

// ===== The auto method: what it keeps of the extended method's moves =====
// A feature is one chamfer strip between two regions, or a cluster of corner
// vertices (feature_evidence.h). Distances in sample spacings (the input's
// median edge length).

/// The whole mesh: is the input a chamfered sampling of sharp edges at all?
struct WholeMeshRules {
  /// Nothing is sharpened when the tests refused more than this fraction of
  /// the new vertices of the features placement moved at all...
  double maxRefusedFraction = 0.4;
  /// ...or this fraction on a smooth part made of planes: noise at most
  /// `maxSmoothNoiseSpacings` and a planar share at least
  /// `minPlanarAreaFraction` (surface_measures.h): there the refusals come
  /// from the shape, which the per-feature rules sort out.
  double maxRefusedFractionSmooth = 0.6;
  /// 0: no input counts as smooth.
  double maxSmoothNoiseSpacings = 0.018;
  double minPlanarAreaFraction = 0.3;
  /// A face lies on its region's plane within this angle of the region's
  /// mean normal (the planar share above).
  static constexpr double kPlanarAngleRad = 3.0 * M_PI / 180.0;
  /// Nothing is sharpened either when the moves mostly slide along the
  /// input: the median distance of their targets from the input faces
  /// around them is below this fraction of their length (already sharp). On
  /// a mesh sampled exactly, only the features whose own moves slide.
  double minMedianLift = 0.07;
  /// A mesh counts as sampled exactly on its surface when its median edge
  /// feature (weighted by its new vertices) has nine in ten of its sources
  /// within this distance of their planes (a remesher that casts its
  /// vertices onto the input). 0: off.
  double exactSamplingSpacings = 0.001;
};

/// One feature: restored whole, or left as it came.
struct FeatureRules {
  /// Fewer new vertices than this: too short to be a feature.
  int minFeatureVertices = 3;
  /// An edge whose flanks' planes meet at less than this angle (a shallow
  /// crease or a knife edge): the line they meet on is poorly determined.
  double minFeatureAngleRad = 20.0 * M_PI / 180.0;
  /// An edge whose flanks' planes meet on a line turned out of its chamfer
  /// by a median angle above this: planes meeting across it, not along it.
  /// 0 disables.
  double maxFeatureLineChamferAngleRad = 45.0 * M_PI / 180.0;
  /// Left when more than this fraction of its new vertices were refused by
  /// placement's tests or would move nearer another sheet of the input.
  double maxFeatureFallbackFraction = 0.5;
  /// Left when one of its source vertices lies farther than this from its
  /// plane (a blend, a curved face or a thin wall meets it)...
  double maxFeatureOffPlaneSpacings = 0.6;
  /// ...unless nine in ten of them lie within this distance (sampled on its
  /// planes; the far ones' new vertices stay at rest). 0: every far one counts.
  double onPlaneSpacings = 0.05;
  /// ...or half of them lie within this distance and none farther than
  /// `maxMedianOnPlaneOffSpacings`, both times the sine of the flanks' angle
  /// for an edge (a sampler rounding a few samples near the edge). 0: off.
  double medianOnPlaneSpacings = 0.1;
  double maxMedianOnPlaneOffSpacings = 1.0;
  /// The quantiles of the sources' off-plane distances read above: "nine in
  /// ten" and "half".
  static constexpr double kOnPlaneQuantile = 0.9;
  static constexpr double kMedianQuantile = 0.5;
  /// A target lies on another sheet of the input (a thin wall's other side)
  /// when that sheet is nearer and faces away: normals more than 120 degrees
  /// apart (cosine below this).
  static constexpr double kOtherSheetMaxCos = -0.5;
  /// A feature is a designed fillet (`on_the_surface`) when a fillet fits its
  /// samples across the edge and is wider by more than this than the fillet
  /// the sampler leaves at the edges it meets alike: the ambiguous width,
  /// within which the user decides (bench/quality/families.py). 0: off.
  double designedFilletMarginSpacings = 1.5;
  /// A fillet fits a feature's samples when their RMS distance to it is at
  /// most this (and the designed one's lie farther from the sharp wedge).
  static constexpr double kFilletFitRmsSpacings = 0.1;
  /// The sampler's fillet: this quantile, weighted by samples, of the widths
  /// of the edges a grid meets alike (a designed fillet only widens some)...
  static constexpr double kPeerRoundingQuantile = 0.25;
  /// ...whose flank normals some symmetry of the grid maps within this angle.
  static constexpr double kGridAlikeAngleRad = 10.0 * M_PI / 180.0;
  /// The fillets tried: radii up to this, on steps of this (refined tenfold
  /// around the best).
  static constexpr double kMaxFilletRadiusSpacings = 8.0;
  static constexpr double kFilletRadiusStepSpacings = 0.05;
};

/// One new vertex of a feature kept.
struct VertexRules {
  /// An edge vertex moved farther than this stays at rest when one of its
  /// sources lies more than `maxLongMoveOffPlaneSpacings` off its plane: a
  /// long extrapolation magnifies a curved flank's misfit. 0: off.
  double longMoveSpacings = 2.0;
  double maxLongMoveOffPlaneSpacings = 0.3;
  /// A vertex the bend test would keep at rest moves when its move is at most
  /// this long and nothing else refuses it, counted as refused in its
  /// feature's evidence (a sampler rounds a sharp edge most near its
  /// corners). 0: the bend keeps it at rest, as in the extended method.
  double maxBentMoveSpacings = 1.0;
  /// After the cleanup, a vertex within this distance of a flat patch's
  /// plane lies on it (guards/planar_folds.h)...
  static constexpr double kFoldPlaneSpacings = 0.1;
  /// ...and a patch around a fold grows to this many faces at most.
  static constexpr std::size_t kMaxFoldPatchFaces = 6;
  /// Two faces are folded over each other when their normals are more than
  /// 120 degrees apart (cosine below this).
  static constexpr double kFoldMaxCos = -0.5;
};

/// A rough input (a fused scan: noise above WholeMeshRules::
/// maxSmoothNoiseSpacings) left whole: its planes flattened.
struct RoughInputRules {
  /// Flatten the planes of a rough input left whole (planar_regions.h:
  /// flattenPlanarRegions; needs ExtendedSettings::regionPlanes).
  bool flattenRoughPlanes = true;
  /// A vertex moves onto its plane by at most this (a scan's bulge beside an
  /// edge; farther off is the region's own shape)...
  static constexpr double kFlattenMaxSpacings = 2.0;
  /// ...and by at least this (nearer, it lies on it: the fit's rounding).
  static constexpr double kFlattenMinSpacings = 1e-3;
  /// Rings of vertices read around a vertex for its region's samples and the
  /// other regions' planes...
  static constexpr int kFlattenRings = 3;
  /// ...and for the planes of the convex edge or corner a bulge rises beyond.
  static constexpr int kFlattenCornerRings = 6;
  /// Planes nearer parallel than this meet on no edge.
  static constexpr double kFlattenParallelAngleRad = 5.0 * M_PI / 180.0;
  /// The share of the vertices flattening must move before planes grown face
  /// by face are flattened too (the planes bulge as a fused scan's do); they
  /// take the vertices of no planar region (a region's core fits its face
  /// better than a plane grown over the rounding along its edges).
  static constexpr double kGrownPlanesEvidence = 0.01;
};

/// How plane_patches.h grows a rough input's planes face by face.
struct PlanePatchSettings {
  /// A face joins when its normal turns from the patch's plane by less than
  /// a feature's angle (FeatureRules::minFeatureAngleRad)...
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
  int pairRings = RoughInputRules::kFlattenCornerRings;
};

/// The auto method's rules, by the decision they make.
struct AutoRules {
  WholeMeshRules mesh;
  FeatureRules feature;
  VertexRules vertex;
  RoughInputRules rough;
};

/// A fixed number of the rulebook (not an option), for docs/auto-rules.md's
/// test: its name there and its value, in the unit the page gives.
struct FixedRule {
  std::string_view name;
  double value;
};

/// Every fixed number above, in declaration order (angles in degrees).
inline const std::vector<FixedRule> &fixedRules() {
  constexpr double kDeg = 180.0 / M_PI;
  static const std::vector<FixedRule> rules{
      {"ExtendedSettings::kMinShiftSpacings", ExtendedSettings::kMinShiftSpacings},
      {"ExtendedSettings::kOwnPlaneMaxTurnRad", ExtendedSettings::kOwnPlaneMaxTurnRad * kDeg},
      {"ExtendedSettings::kOwnPlaneMaxExtraTurnRad",
       ExtendedSettings::kOwnPlaneMaxExtraTurnRad * kDeg},
      {"PlanarRegionSettings::coreHops", double(PlanarRegionSettings{}.coreHops)},
      {"PlanarRegionSettings::minCoreFaces", double(PlanarRegionSettings{}.minCoreFaces)},
      {"PlanarRegionSettings::maxRmsSpacings", PlanarRegionSettings{}.maxRmsSpacings},
      {"PlanarRegionSettings::maxBendRad", PlanarRegionSettings{}.maxBendRad * kDeg},
      {"WholeMeshRules::kPlanarAngleRad", WholeMeshRules::kPlanarAngleRad * kDeg},
      {"FeatureRules::kOnPlaneQuantile", FeatureRules::kOnPlaneQuantile},
      {"FeatureRules::kMedianQuantile", FeatureRules::kMedianQuantile},
      {"FeatureRules::kOtherSheetMaxCos", FeatureRules::kOtherSheetMaxCos},
      {"FeatureRules::kFilletFitRmsSpacings", FeatureRules::kFilletFitRmsSpacings},
      {"FeatureRules::kPeerRoundingQuantile", FeatureRules::kPeerRoundingQuantile},
      {"FeatureRules::kGridAlikeAngleRad", FeatureRules::kGridAlikeAngleRad * kDeg},
      {"FeatureRules::kMaxFilletRadiusSpacings", FeatureRules::kMaxFilletRadiusSpacings},
      {"FeatureRules::kFilletRadiusStepSpacings", FeatureRules::kFilletRadiusStepSpacings},
      {"VertexRules::kFoldPlaneSpacings", VertexRules::kFoldPlaneSpacings},
      {"VertexRules::kMaxFoldPatchFaces", double(VertexRules::kMaxFoldPatchFaces)},
      {"VertexRules::kFoldMaxCos", VertexRules::kFoldMaxCos},
      {"RoughInputRules::kFlattenMaxSpacings", RoughInputRules::kFlattenMaxSpacings},
      {"RoughInputRules::kFlattenMinSpacings", RoughInputRules::kFlattenMinSpacings},
      {"RoughInputRules::kFlattenRings", double(RoughInputRules::kFlattenRings)},
      {"RoughInputRules::kFlattenCornerRings", double(RoughInputRules::kFlattenCornerRings)},
      {"RoughInputRules::kFlattenParallelAngleRad",
       RoughInputRules::kFlattenParallelAngleRad * kDeg},
      {"RoughInputRules::kGrownPlanesEvidence", RoughInputRules::kGrownPlanesEvidence},
      {"PlanePatchSettings::maxTurnRad", PlanePatchSettings{}.maxTurnRad * kDeg},
      {"PlanePatchSettings::maxDistanceSpacings", PlanePatchSettings{}.maxDistanceSpacings},
      {"PlanePatchSettings::minAreaSpacings2", PlanePatchSettings{}.minAreaSpacings2},
      {"PlanePatchSettings::trimRmsFactor", PlanePatchSettings{}.trimRmsFactor},
      {"PlanePatchSettings::pairAngleRad", PlanePatchSettings{}.pairAngleRad * kDeg},
  };
  return rules;
}

}  // namespace edge_sharpener
