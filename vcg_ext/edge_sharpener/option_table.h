// One declaration per option of SharpenOptions: the table below drives the
// command line, the MeshLab adapters, the Python binding, validation and the
// JSON report. Adding an option is one field in options.h and one row here.
#pragma once

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "options.h"

namespace edge_sharpener {

/// How an option's value reads and is entered (values travel as doubles:
/// flags 0/1, choices their index, angles in degrees).
enum class OptionType { Flag, Integer, Real, Choice };

/// Who sets the option. `Ordinary` options are what users see first (CLI
/// help, MeshLab dialog, Blender panel); the others are tuning, one group per
/// settings struct of the rulebook (rulebook.h), the auto method's by the
/// decision they make.
enum class OptionGroup {
  Ordinary,
  Paper,           ///< SharpenOptions::paper
  Extended,        ///< SharpenOptions::extended
  AutoWholeMesh,   ///< SharpenOptions::rules.mesh
  AutoFeature,     ///< SharpenOptions::rules.feature
  AutoVertex,      ///< SharpenOptions::rules.vertex
  AutoRoughInput,  ///< SharpenOptions::rules.rough
};

inline const char *toString(OptionGroup g) {
  switch (g) {
    case OptionGroup::Ordinary: return "Options";
    case OptionGroup::Paper: return "Tuning: the paper's degenerate cases";
    case OptionGroup::Extended: return "Tuning: extended and auto methods, detection and placement";
    case OptionGroup::AutoWholeMesh: return "Tuning: auto method, the whole mesh";
    case OptionGroup::AutoFeature: return "Tuning: auto method, each feature";
    case OptionGroup::AutoVertex: return "Tuning: auto method, each new vertex";
    case OptionGroup::AutoRoughInput: return "Tuning: auto method, a rough input";
  }
  return "";
}

/// Which MeshLab filters show an option (bit mask).
enum MeshLabFilterMask : unsigned { kNotInMeshLab = 0, kInSharpen = 1, kInDetect = 2 };

/// One option, declared once.
struct OptionSpec {
  std::string_view key;          ///< snake_case: Python keyword and JSON key
  std::string_view cliFlag;      ///< with dashes; a flag whose default is on turns it off
  std::string_view meshlabName;  ///< parameter name in .mlx scripts (empty: not in MeshLab)
  std::string_view label;        ///< short title (MeshLab dialog, Blender panel)
  std::string_view help;         ///< one plain-text paragraph
  OptionType type;
  OptionGroup group;
  std::string_view unit;      ///< of the value as entered ("deg", "median edge lengths", ...)
  double minValue, maxValue;  ///< allowed range, in the unit above
  bool minExclusive;          ///< the value must be above minValue, not equal to it
  unsigned meshlabFilters;    ///< MeshLabFilterMask bits
  std::vector<std::string_view> choices;       ///< Choice: the names (CLI, Python, JSON)
  std::vector<std::string_view> choiceLabels;  ///< Choice: the titles (MeshLab)
  double (*get)(const SharpenOptions &);       ///< the value, in the unit above
  void (*set)(SharpenOptions &, double);       ///< sets it (assumes a valid value)

  bool ordinary() const { return group == OptionGroup::Ordinary; }
  double defaultValue() const { return get(SharpenOptions{}); }
  /// Why `value` is not allowed, or empty.
  std::string problemWith(double value) const;
  /// The name of choice `index`, for Choice options.
  std::string_view choiceName(double index) const { return choices.at(std::size_t(index)); }
  /// The index of choice `name`, or -1.
  int choiceIndex(std::string_view name) const {
    for (std::size_t i = 0; i < choices.size(); ++i)
      if (choices[i] == name) return int(i);
    return -1;
  }
};

namespace detail {
constexpr double kDegPerRad = 180.0 / M_PI;
/// Rounded to 1e-9 degree: 15 degrees reads 15, not 14.999999999999998.
inline double degrees(double rad) {
  return std::round(rad * kDegPerRad * 1e9) / 1e9;
}
inline double radians(double deg) {
  return deg * M_PI / 180.0;
}
}  // namespace detail

// Each row names its field once in `get` and once in `set`.
#define ES_REAL(field)                                     \
  [](const SharpenOptions &o) { return double(o.field); }, \
      [](SharpenOptions &o, double v) { o.field = v; }
#define ES_INT(field)                                      \
  [](const SharpenOptions &o) { return double(o.field); }, \
      [](SharpenOptions &o, double v) { o.field = int(v); }
#define ES_FLAG(field)                                         \
  [](const SharpenOptions &o) { return o.field ? 1.0 : 0.0; }, \
      [](SharpenOptions &o, double v) { o.field = v != 0; }
#define ES_ANGLE(field)                                             \
  [](const SharpenOptions &o) { return detail::degrees(o.field); }, \
      [](SharpenOptions &o, double v) { o.field = detail::radians(v); }

/// Every option, ordinary ones first, then each method's tuning; options are
/// applied in this order.
// One row per option (clang-format would put each field on a line of its own).
// clang-format off
inline const std::vector<OptionSpec> &optionTable() {
  using T = OptionType;
  using G = OptionGroup;
  constexpr unsigned kBoth = kInSharpen | kInDetect;
  static const std::vector<OptionSpec> table{
      // ----- what users set
      {"method", "--method", "method", "Method",
       "auto (the default): the extended method, sharpening only the features with strong "
       "evidence, the mesh left as it is when most are weak (a scan, a model already sharp); "
       "extended: chamfer zones of any width, every feature sharpened; paper: the 2003 method "
       "as published (chamfers one triangle wide).",
       T::Choice, G::Ordinary, "", 0, 2, false, kBoth,
       {"paper", "extended", "auto"},
       {"Paper (2003)", "Extended (feature zones)", "Auto (extended, on strong evidence only)"},
       [](const SharpenOptions &o) { return double(int(o.method)); },
       [](SharpenOptions &o, double v) { o.method = Method(int(v)); }},
      {"multiplier", "--multiplier", "smoothMultiplier", "Smooth-edge multiplier",
       "An edge is smooth when the angle between the normals of its two faces is below this "
       "multiple of the mean of that angle over the whole mesh (paper: 2). Smaller values find "
       "fewer smooth regions; larger values may take curved chamfers for smooth surface.",
       T::Real, G::Ordinary, "x mean normal angle", 0, 100, true, kBoth, {}, {},
       ES_REAL(smoothMultiplier)},
      {"edge_length_check", "--no-length-check", "edgeLengthCheck", "Edge-length check",
       "Leave an inserted vertex in the middle of its chamfer edge or corner triangle when "
       "moving it would create an edge longer than the longest edge of the input (paper, "
       "Figure 7). Keep it on: without it, nearly parallel planes can send vertices far away.",
       T::Flag, G::Ordinary, "", 0, 1, false, kInSharpen, {}, {}, ES_FLAG(edgeLengthCheck)},
      {"colorize", "--colorize", "colorize", "Colorize",
       "Paint per-face and per-vertex colour for inspection, in the scheme --colors names.",
       T::Flag, G::Ordinary, "", 0, 1, false, kInSharpen, {}, {}, ES_FLAG(colorize)},
      {"colors", "--colors", "colors", "Colours",
       "What --colorize and Detect paint. verdict (the default): the faces of each feature the "
       "auto method judged by its verdict (restored green, already sharp blue, outside the "
       "selection white, each reason for leaving it its own colour: docs/plugin.md has the "
       "legend), other faces grey. paper: the paper's labels (smooth regions red, chamfer "
       "triangles blue, corner triangles green, others grey; inserted vertices moved yellow, "
       "kept at rest by a fallback in another colour). The paper and extended methods judge no "
       "feature: they always paint the paper's labels.",
       T::Choice, G::Ordinary, "", 0, 1, false, kBoth,
       {"verdict", "paper"}, {"By verdict", "Paper's labels"},
       [](const SharpenOptions &o) { return double(int(o.colors)); },
       [](SharpenOptions &o, double v) { o.colors = ColorScheme(int(v)); }},
      {"degenerate_angle_deg", "--degenerate-angle", "degenerateAngleDeg", "Degenerate angle (deg)",
       "After sharpening, new triangles with an angle below this many degrees are removed "
       "(paper: 1 degree).",
       T::Real, G::Ordinary, "deg", 0, 59, false, kInSharpen, {}, {}, ES_ANGLE(degenerateAngleRad)},
      // ----- the paper's degenerate cases
      {"convexity_check", "--no-convexity-check", "", "Convexity check",
       "Keep a new vertex unmoved when its chamfer is bordered by a concave edge on one side "
       "and a convex edge on the other (paper, section 3). Paper and extended methods: auto "
       "judges these moves by its own tests (a saddle corner's are sound).",
       T::Flag, G::Paper, "", 0, 1, false, kNotInMeshLab, {}, {}, ES_FLAG(paper.convexityCheck)},
      {"parallel_angle_deg", "--parallel-angle", "", "Parallel-plane tolerance",
       "Two planes whose normals are closer than this angle count as parallel; three normals "
       "whose triple product is below its sine count as coplanar.",
       T::Real, G::Paper, "deg", 0, 89, false, kNotInMeshLab, {}, {},
       ES_ANGLE(paper.parallelAngleRad)},
      // ----- extended method: detection and placement (extended and auto)
      {"min_region_depth", "--min-region-depth", "", "Minimum region depth",
       "A smooth region whose vertices all lie fewer than this many hops from its border is a "
       "corridor (a regular chamfer band) and joins the feature zone.",
       T::Integer, G::Extended, "hops", 0, 100, false, kNotInMeshLab, {}, {},
       ES_INT(extended.minRegionDepth)},
      {"open_region_contacts", "--keep-contacts", "", "Open region contacts",
       "Return to the feature zone the region faces around vertices where two smooth regions "
       "touch.",
       T::Flag, G::Extended, "", 0, 1, false, kNotInMeshLab, {}, {},
       ES_FLAG(extended.openRegionContacts)},
      {"min_facet_length_spacings", "--min-facet-length", "", "Narrow facet length",
       "...except the faces of a region that opening would leave without an interior vertex "
       "and that spans at least this many sample spacings: a narrow facet (of a coarse "
       "cylinder), not a smooth piece of a chamfer (0: such regions open too).",
       T::Real, G::Extended, "sample spacings", 0, 1e6, false, kNotInMeshLab, {}, {},
       ES_REAL(extended.minFacetLengthSpacings)},
      {"region_planes", "--local-planes-only", "", "Planar regions' own planes",
       "Place a feature's new vertices on its flanks' own planes where their regions are planes "
       "away from their features (fitted over their cores), up to a corner whose third face is "
       "a plane too: a reconstruction rounds the planes fitted next to the feature.",
       T::Flag, G::Extended, "", 0, 1, false, kNotInMeshLab, {}, {},
       ES_FLAG(extended.regionPlanes)},
      {"open_internal_creases", "--keep-internal-creases", "", "Open internal creases",
       "Return to the feature zone the region faces around internal creases (a non-smooth edge "
       "inside one region).",
       T::Flag, G::Extended, "", 0, 1, false, kNotInMeshLab, {}, {},
       ES_FLAG(extended.openInternalCreases)},
      {"internal_crease_angle_deg", "--internal-crease-angle", "", "Internal crease angle",
       "An internal crease turns its face normals by more than this angle; below it, a "
       "non-smooth edge inside a region is marching-cubes noise.",
       T::Real, G::Extended, "deg", 0, 180, false, kNotInMeshLab, {}, {},
       ES_ANGLE(extended.internalCreaseAngleRad)},
      {"internal_crease_threshold_factor", "--internal-crease-factor", "", "Internal crease factor",
       "...and by more than this multiple of the smooth-edge threshold (a coarse sampling of a "
       "curved surface has large angles everywhere).",
       T::Real, G::Extended, "x smooth threshold", 0, 100, false, kNotInMeshLab, {}, {},
       ES_REAL(extended.internalCreaseThresholdFactor)},
      {"same_region_feature_angle_deg", "--same-region-angle", "", "Same-region feature angle",
       "Two vertices of one region whose planes turn by more than this angle lie on different "
       "surfaces: a chamfer edge may join them (0: one region is one surface).",
       T::Real, G::Extended, "deg", 0, 180, false, kNotInMeshLab, {}, {},
       ES_ANGLE(extended.sameRegionFeatureAngleRad)},
      {"support_rings", "--support-rings", "", "Support rings",
       "Face rings around a region's border vertex used to fit its plane.",
       T::Integer, G::Extended, "rings", 1, 20, false, kNotInMeshLab, {}, {},
       ES_INT(extended.supportRings)},
      {"label_slack_hops", "--label-slack", "", "Label slack",
       "A zone vertex considers the regions reaching it within this many hops of the closest "
       "one.",
       T::Integer, G::Extended, "hops", 0, 100, false, kNotInMeshLab, {}, {},
       ES_INT(extended.labelSlackHops)},
      {"max_label_hops", "--max-label-hops", "", "Maximum label distance",
       "A zone vertex takes region labels from at most this many hops away: a region's plane "
       "extrapolated farther misses a curved surface.",
       T::Integer, G::Extended, "hops", 0, 100, false, kNotInMeshLab, {}, {},
       ES_INT(extended.maxLabelHops)},
      {"max_projection_factor", "--max-projection", "", "Maximum projection",
       "Longest move of a zone vertex onto its region's plane, in mean edge lengths (0: "
       "never).",
       T::Real, G::Extended, "mean edge lengths", 0, 10, false, kNotInMeshLab, {}, {},
       ES_REAL(extended.maxProjectionFactor)},
      {"extended_edge_length_factor", "--length-factor", "", "Edge-length factor",
       "The edge-length check allows this multiple of the longest input edge (the tip of an "
       "acute edge lies well beyond its chamfer).",
       T::Real, G::Extended, "x longest edge", 1, 100, false, kNotInMeshLab, {}, {},
       ES_REAL(extended.extendedEdgeLengthFactor)},
      {"max_displacement_spacings", "--max-displacement", "", "Maximum displacement",
       "Keep a vertex at rest when the planes meet farther than this many median edge lengths "
       "from it (0: off).",
       T::Real, G::Extended, "median edge lengths", 0, 1000, false, kNotInMeshLab, {}, {},
       ES_REAL(extended.maxDisplacementSpacings)},
      {"apex_height_factor", "--apex-factor", "", "Apex factor",
       "Keep a vertex at rest when the planes meet this many times higher above its chamfer "
       "than their angle allows (0: off).",
       T::Real, G::Extended, "", 0, 100, false, kNotInMeshLab, {}, {},
       ES_REAL(extended.apexHeightFactor)},
      {"max_support_spread_ratio", "--spread-ratio", "", "Spread ratio",
       "Keep a vertex at rest when its regions turn, over the fitted neighbourhood, by more "
       "than this fraction of the angle between their planes (a blend; 0: off).",
       T::Real, G::Extended, "", 0, 10, false, kNotInMeshLab, {}, {},
       ES_REAL(extended.maxSupportSpreadRatio)},
      {"intermediate_plane_tolerance", "--intermediate-tolerance", "",
       "Intermediate-plane tolerance",
       "Keep a vertex at rest when it would pass through the plane of a third region whose "
       "normal lies between the flanks' by more than this fraction of its displacement "
       "(negative: off).",
       T::Real, G::Extended, "", -1, 10, false, kNotInMeshLab, {}, {},
       ES_REAL(extended.intermediatePlaneTolerance)},
      {"max_bend_fraction", "--bend-fraction", "", "Bend fraction",
       "Keep a vertex at rest when a flank's region, bending across the feature, would leave "
       "its plane by more than this fraction of the vertex's displacement (negative: off).",
       T::Real, G::Extended, "", -1, 10, false, kNotInMeshLab, {}, {},
       ES_REAL(extended.maxBendFraction)},
      {"min_bend_spread_deg", "--bend-spread", "", "Bend spread",
       "...tested where the fitted faces spread by at least this angle.",
       T::Real, G::Extended, "deg", 0, 180, false, kNotInMeshLab, {}, {},
       ES_ANGLE(extended.minBendSpreadRad)},
      {"min_bend_fit_quality", "--bend-fit-quality", "", "Bend fit quality",
       "...or where the fitted faces' normals follow their position this well (0 to 1).",
       T::Real, G::Extended, "", 0, 1, false, kNotInMeshLab, {}, {},
       ES_REAL(extended.minBendFitQuality)},
      {"intermediate_slack_deg", "--intermediate-slack", "", "Intermediate slack",
       "How far a third region's normal may lie off the arc between the flanks' normals and "
       "still count as between them.",
       T::Real, G::Extended, "deg", 0, 180, false, kNotInMeshLab, {}, {},
       ES_ANGLE(extended.intermediateSlackRad)},
      {"fit_trim_angle_deg", "--fit-trim-angle", "", "Fit trim angle",
       "A region's plane is refitted without its faces turned more than this from the first "
       "fit (0: no refit).",
       T::Real, G::Extended, "deg", 0, 180, false, kNotInMeshLab, {}, {},
       ES_ANGLE(extended.fitTrimAngleRad)},
      // ----- auto method: the whole mesh
      {"max_refused_fraction", "--max-refused", "", "Refused fraction",
       "Auto method: nothing is sharpened when the other tests kept at rest more than this "
       "fraction of the new vertices of the features that moved at all (the input is not a "
       "chamfered sampling of sharp edges: a scan, a model already sharp, a smooth shape).",
       T::Real, G::AutoWholeMesh, "", 0, 1, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.mesh.maxRefusedFraction)},
      {"max_refused_fraction_smooth", "--max-refused-smooth", "", "Refused fraction, smooth",
       "Auto method: the refused fraction's bound on a smooth part made of planes (see "
       "--smooth-noise and --min-planar-area), where refusals come from the shape and the "
       "per-feature evidence judges each feature.",
       T::Real, G::AutoWholeMesh, "", 0, 1, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.mesh.maxRefusedFractionSmooth)},
      {"max_smooth_noise_spacings", "--smooth-noise", "", "Smooth surface noise",
       "Auto method: a surface counts as smooth when the median change of its vertices' "
       "umbrella curvature from their neighbours' is at most this (a remeshed or reconstructed "
       "solid; a fused scan is rougher; 0: no surface counts as smooth).",
       T::Real, G::AutoWholeMesh, "median edge lengths", 0, 10, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.mesh.maxSmoothNoiseSpacings)},
      {"min_planar_area_fraction", "--min-planar-area", "", "Minimum planar area",
       "Auto method: the share of the surface that must lie on planes (faces within 3 degrees "
       "of their smooth region's mean normal) for the smooth bound to apply.",
       T::Real, G::AutoWholeMesh, "", 0, 1, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.mesh.minPlanarAreaFraction)},
      {"min_median_lift", "--min-lift", "", "Minimum median lift",
       "Auto method: nothing is sharpened when the moves mostly slide along the input: their "
       "targets' median distance from the input faces around them is below this fraction of "
       "their length (a model already sharp; 0: off). On a mesh sampled exactly, only the "
       "features whose own moves slide are left.",
       T::Real, G::AutoWholeMesh, "", 0, 1, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.mesh.minMedianLift)},
      {"exact_sampling_spacings", "--exact-sampling", "", "Exact sampling tolerance",
       "Auto method: a mesh whose median feature has nine in ten of its vertices within this "
       "distance of their planes is sampled exactly (Blender's voxel remesh with Preserve "
       "Volume): there a feature with half of its vertices beyond --on-plane (a designed "
       "bevel) stays as it was, as do the new vertices of such far ones (0: off).",
       T::Real, G::AutoWholeMesh, "median edge lengths", 0, 100, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.mesh.exactSamplingSpacings)},
      // ----- auto method: each feature
      {"max_feature_fallback_fraction", "--feature-fallback", "", "Feature fallback fraction",
       "Auto method: a feature (a chamfer strip with its corners) stays as it was when more "
       "than this fraction of its new vertices were kept at rest by the other tests or would "
       "move nearer another sheet of the surface (a thin wall's other side) than their own "
       "(the default: most of them).",
       T::Real, G::AutoFeature, "", 0, 1, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.feature.maxFeatureFallbackFraction)},
      {"max_feature_off_plane_spacings", "--feature-off-plane", "", "Feature off-plane distance",
       "Auto method: a feature stays as it was when one of its vertices lies farther than this "
       "from the plane fitted to its flank: a blend, a curved face or a thin wall meets it.",
       T::Real, G::AutoFeature, "median edge lengths", 0, 100, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.feature.maxFeatureOffPlaneSpacings)},
      {"on_plane_spacings", "--on-plane", "", "On-plane tolerance",
       "Auto method: ...unless nine in ten of the feature's vertices lie within this distance of "
       "their planes (an exactly sampled feature whose far vertices lie where it meets another "
       "part: the new vertices they source stay at rest; 0: every far vertex counts).",
       T::Real, G::AutoFeature, "median edge lengths", 0, 100, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.feature.onPlaneSpacings)},
      {"median_on_plane_spacings", "--on-plane-median", "", "Median on-plane tolerance",
       "Auto method: ...or unless half of the feature's vertices lie within this distance of "
       "their planes and none farther than --on-plane-median-max (a sampler rounding a few "
       "samples near the edge): the far ones' new vertices stay at rest. For an edge, both "
       "distances times the sine of its flanks' angle (0: off).",
       T::Real, G::AutoFeature, "median edge lengths", 0, 100, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.feature.medianOnPlaneSpacings)},
      {"max_median_on_plane_off_spacings", "--on-plane-median-max", "",
       "Median on-plane: farthest vertex",
       "Auto method: the farthest a vertex may lie from its plane for --on-plane-median to "
       "apply.",
       T::Real, G::AutoFeature, "median edge lengths", 0, 100, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.feature.maxMedianOnPlaneOffSpacings)},
      {"min_feature_vertices", "--min-feature-vertices", "", "Minimum feature size",
       "Auto method: a feature with fewer new vertices than this stays as it was.",
       T::Integer, G::AutoFeature, "vertices", 0, 1000, false, kNotInMeshLab, {}, {},
       ES_INT(rules.feature.minFeatureVertices)},
      {"min_feature_angle_deg", "--min-feature-angle", "", "Minimum feature angle (deg)",
       "Auto method: an edge stays as it was when its flanks' planes meet at less than this "
       "angle, at a shallow crease or at a knife edge: the line they meet on is poorly "
       "determined there (0: off).",
       T::Real, G::AutoFeature, "deg", 0, 90, false, kNotInMeshLab, {}, {},
       ES_ANGLE(rules.feature.minFeatureAngleRad)},
      {"max_feature_line_chamfer_angle_deg", "--line-chamfer-angle", "",
       "Line-chamfer angle (deg)",
       "Auto method: an edge stays as it was when the line its flanks' planes meet on turns "
       "out of its chamfer by a median angle above this: a sharp edge runs along its chamfer "
       "(0: off).",
       T::Real, G::AutoFeature, "deg", 0, 90, false, kNotInMeshLab, {}, {},
       ES_ANGLE(rules.feature.maxFeatureLineChamferAngleRad)},
      {"designed_fillet_margin_spacings", "--fillet-margin", "", "Designed fillet margin",
       "Auto method: an edge stays as it was when its samples lie on one arc (a fillet fits "
       "them) wider by more than this than the arcs the sampler leaves at the edges it meets "
       "alike: a designed fillet, not the sampler's rounding (0: off).",
       T::Real, G::AutoFeature, "median edge lengths", 0, 100, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.feature.designedFilletMarginSpacings)},
      // ----- auto method: each new vertex
      {"max_bent_move_spacings", "--bent-move", "", "Move across a bend",
       "Auto method: a new vertex the bend test (--bend-fraction) would keep at rest moves with "
       "its feature when its move is at most this long and nothing else refuses it, counted as "
       "refused in the feature's evidence (a sampler rounds a sharp edge most near its "
       "corners; 0: the bend keeps it at rest).",
       T::Real, G::AutoVertex, "median edge lengths", 0, 100, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.vertex.maxBentMoveSpacings)},
      {"long_move_spacings", "--long-move", "", "Long move",
       "Auto method: a new vertex on an edge (not a corner) moved farther than this from its "
       "chamfer stays at rest when one of its vertices lies farther than --long-move-off-plane "
       "from its plane: a long extrapolation magnifies a curved flank's misfit (0: off).",
       T::Real, G::AutoVertex, "median edge lengths", 0, 100, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.vertex.longMoveSpacings)},
      {"max_long_move_off_plane_spacings", "--long-move-off-plane", "",
       "Long move off-plane distance",
       "Auto method: the off-plane distance a long move's vertices may have (see --long-move).",
       T::Real, G::AutoVertex, "median edge lengths", 0, 100, false, kNotInMeshLab, {}, {},
       ES_REAL(rules.vertex.maxLongMoveOffPlaneSpacings)},
      // ----- auto method: a rough input
      {"flatten_rough_planes", "--keep-rough-planes", "", "Flatten a rough input's planes",
       "Auto method: on a rough input left whole (a fused scan, see --smooth-noise), vertices "
       "up to two sample spacings out of a planar region move onto its plane (beside a convex "
       "edge, behind the planes around them); where that moved 1% of the vertices, again on "
       "planes grown face by face. Off with --local-planes-only.",
       T::Flag, G::AutoRoughInput, "", 0, 1, false, kNotInMeshLab, {}, {},
       ES_FLAG(rules.rough.flattenRoughPlanes)},
  };
  return table;
}
// clang-format on

#undef ES_REAL
#undef ES_INT
#undef ES_FLAG
#undef ES_ANGLE

inline std::string OptionSpec::problemWith(double value) const {
  const std::string name(key);
  if (!std::isfinite(value)) return "option " + name + " must be a finite number";
  if (type == OptionType::Flag && value != 0 && value != 1)
    return "option " + name + " must be true or false";
  if ((type == OptionType::Integer || type == OptionType::Choice) && value != std::floor(value))
    return "option " + name + " must be a whole number";
  const bool belowMin = minExclusive ? !(value > minValue) : !(value >= minValue);
  if (belowMin || !(value <= maxValue)) {
    if (type == OptionType::Choice) return "option " + name + " has no such choice";
    auto text = [](double x) {
      std::string s = std::to_string(x);
      s.erase(s.find_last_not_of('0') + 1);
      if (!s.empty() && s.back() == '.') s.pop_back();
      return s;
    };
    return "option " + name + " must be in " + (minExclusive ? "(" : "[") + text(minValue) + ", " +
           text(maxValue) + "]" + (unit.empty() ? "" : " " + std::string(unit));
  }
  return {};
}

/// The option called `key`, or null.
inline const OptionSpec *findOption(std::string_view key) {
  for (const OptionSpec &spec : optionTable())
    if (spec.key == key) return &spec;
  return nullptr;
}

/// Why these options cannot run, or empty: every option's value against its
/// declared range.
inline std::string findOptionProblem(const SharpenOptions &opt) {
  for (const OptionSpec &spec : optionTable()) {
    std::string problem = spec.problemWith(spec.get(opt));
    if (!problem.empty()) return problem;
  }
  return {};
}

}  // namespace edge_sharpener
