// What each stage of Edge-Sharpener did: one struct, filled stage by stage,
// printed by the CLI (text or JSON) and logged by the MeshLab filter; its
// formatting for people (formatVerdictSummary, formatStages, formatReport).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "labels.h"

namespace edge_sharpener {

/// Stage 1: smooth-edge test.
struct SmoothEdgeStats {
  std::size_t edges = 0;            ///< undirected edges
  std::size_t boundaryEdges = 0;    ///< edges with one incident face (never smooth)
  std::size_t degenerateEdges = 0;  ///< interior edges next to a zero-area face (never smooth)
  std::size_t smoothEdges = 0;      ///< "brown" edges
  double meanAngleRad = 0;          ///< mean normal angle over interior edges
  double thresholdRad = 0;          ///< multiplier x meanAngleRad
};

/// Stage 2: the six filters of the paper.
struct FilterStats {
  std::size_t interiorRedVertices = 0;  ///< filter 1
  std::size_t coreRedFaces = 0;         ///< filter 2
  std::size_t redFaces = 0;             ///< after filter 3 (recursive growth)
  std::size_t redVertices = 0;          ///< after filter 4
  std::size_t redEdges = 0;             ///< filter 4
  std::size_t chamferEdges = 0;         ///< filter 5 ("blue")
  std::size_t cornerFaces = 0;          ///< filter 6 ("green")
  std::size_t chamferFaces = 0;         ///< faces with one or two chamfer edges
};

/// Stage 3+4: split plan and subdivision.
struct SubdivisionStats {
  std::size_t facesSplitIn2 = 0;  ///< one chamfer edge
  std::size_t facesSplitIn3 = 0;  ///< two chamfer edges
  std::size_t facesSplitIn6 = 0;  ///< corner triangles (fan)
  std::size_t insertedVertices = 0;
  std::size_t addedFaces = 0;
};

/// Stage 5: placement of the inserted vertices; counts by outcome.
struct PlacementStats {
  std::array<std::size_t, kPlacementCount> byOutcome{};  ///< indexed by Placement
  double maxDisplacement = 0;  ///< largest distance an inserted vertex moved
  /// Of the moved, those moved with their feature across a bending flank
  /// (SharpenOptions::maxBentMoveSpacings).
  std::size_t movedAcrossBends = 0;
  std::size_t count(Placement p) const { return byOutcome[static_cast<int>(p)]; }
  std::size_t moved() const { return count(Placement::Moved); }
  std::size_t fallbacks() const {
    std::size_t n = 0;
    for (int i = 0; i < kPlacementCount; ++i)
      if (i != int(Placement::Moved) && i != int(Placement::Original)) n += byOutcome[i];
    return n;
  }
};

/// Stage 6: removal of degenerate triangles (angle below the threshold).
struct CleanupStats {
  std::size_t degenerateFound = 0;  ///< new faces below the angle threshold before cleanup
  std::size_t collapses = 0;        ///< edges collapsed between coinciding new vertices
  std::size_t removedFaces = 0;     ///< faces deleted by those collapses (2 each, 1 on a border)
  std::size_t flips = 0;            ///< edges flipped inside split faces
  std::size_t reverted = 0;         ///< inserted vertices moved back (counted in placement too)
  std::size_t remaining = 0;        ///< faces with a moved vertex still below the threshold
  std::size_t inherited = 0;        ///< degenerate children of input slivers (at rest too)
  std::size_t partWay = 0;  ///< auto method: of those reverted, taken part of the way out again
};

/// Stage 6a, auto method: flat patches folded over themselves, tiled again
/// (guards/planar_folds.h).
struct PlanarFoldStats {
  std::size_t folds = 0;    ///< faces with a moved vertex folded over a neighbour on one plane
  std::size_t patches = 0;  ///< flat patches around them tiled again without the fold
  std::size_t relaxedVertices = 0;  ///< vertices moved on the plane of a fold to unfold it
};

/// Stage 6b: moved vertices sent back to rest because a face of theirs
/// intersected another face (intersection_guard.h).
struct IntersectionStats {
  std::size_t intersectingPairs = 0;  ///< intersecting face pairs with a moved vertex, first round
  std::size_t reverted = 0;           ///< inserted vertices sent back (counted in placement too)
  std::size_t zoneReverted = 0;       ///< extended method: projected zone vertices back at rest
  std::size_t rounds = 0;             ///< rounds of search + revert that found an intersection
  std::size_t remaining = 0;          ///< intersecting pairs left alone: they intersect at rest too
};

/// One feature the auto method judged (SharpenReport::features): a chamfer
/// strip between two smooth regions, or a cluster of corner vertices.
struct FeatureRecord {
  bool corner = false;
  Verdict verdict = Verdict::Restored;
  std::size_t newVertices = 0;
  /// Edges: the median length of the chamfer edges it splits (from one
  /// flank's border to the other's), in sample spacings; corners: 0.
  double widthSpacings = 0;
  /// Edges: the median angle at which its flanks' planes meet, in [0, pi/2]
  /// (small for a shallow crease and for a knife edge); corners: 0.
  double flankAngleRad = 0;
  /// The input faces it splits, by index (a corner triangle is its corner's
  /// and that of each edge whose new vertex lies on it).
  std::vector<std::size_t> faces;
};

/// Per face, the verdict of the feature it belongs to (featureFaceVerdicts,
/// EvidenceGuard::outputFaceVerdicts), or kNoVerdict; what the verdict
/// colours paint (colorize.h).
using FaceVerdicts = std::vector<std::int8_t>;
inline constexpr std::int8_t kNoVerdict = -1;

/// Where a face or vertex belongs to several features: which verdict it
/// takes. A restored feature first (it is what changed), then the reasons to leave
/// one in the enum's order, then no feature.
inline int verdictRank(std::int8_t v) {
  if (v == kNoVerdict) return kVerdictCount + 1;
  return v == std::int8_t(Verdict::Restored) ? 0 : 1 + v;
}

/// `current` or `candidate`, whichever verdictRank puts first.
inline std::int8_t firstVerdict(std::int8_t current, std::int8_t candidate) {
  return verdictRank(candidate) < verdictRank(current) ? candidate : current;
}

/// The input faces' verdicts from the report's features (each feature's
/// faces, by input index); kNoVerdict where none judged the face.
inline FaceVerdicts featureFaceVerdicts(const std::vector<FeatureRecord> &features,
                                        std::size_t faceCount) {
  FaceVerdicts out(faceCount, kNoVerdict);
  for (const FeatureRecord &r : features)
    for (const std::size_t f : r.faces)
      if (f < faceCount) out[f] = firstVerdict(out[f], std::int8_t(r.verdict));
  return out;
}

/// Stage 6c, auto method: features sent back whole for weak evidence
/// (feature_evidence.h).
struct EvidenceStats {
  std::size_t features = 0;      ///< features (inserted vertices joined through their sources)
  std::size_t weakFeatures = 0;  ///< of those, left as they were
  /// ...of which already sharp: their moves slide along a mesh sampled
  /// exactly that is sharp in part (weakFeatures in feature_evidence.h)
  std::size_t alreadySharpFeatures = 0;
  std::size_t reverted = 0;        ///< inserted vertices sent back (counted in placement too)
  std::size_t zoneReverted = 0;    ///< projected zone vertices sent back
  double refusedFraction = 0;      ///< of the moved features' vertices, those refused
  double refusedBound = 0;         ///< above it, the whole mesh is left (refusedBound)
  double medianLift = 1;           ///< how far the moves lift the surface, per unit of length
  double noiseSpacings = 0;        ///< the input surface's noise (surfaceNoiseSpacings)
  double planarFraction = 0;       ///< the input's share of area on planes
  bool exactSampling = false;      ///< sampled exactly on its surface (sampledExactly)
  bool wholeMeshLeft = false;      ///< too many refused, or too little lift: nothing sharpened
  std::size_t facesGivenBack = 0;  ///< split faces at rest back to their input face (fanned)
  std::size_t restingVerticesRemoved = 0;  ///< other inserted vertices at rest, merged away
  std::size_t verticesRemoved = 0;         ///< inserted vertices deleted by the two above
  std::size_t facesRemoved = 0;            ///< faces deleted by the two above
  std::size_t flattenedVertices = 0;       ///< left whole, rough: vertices of planes flattened
  std::size_t grownPlanes = 0;             ///< ...and planes grown face by face for it
  /// Features per verdict (Verdict), each feature counted once.
  std::array<std::size_t, kVerdictCount> verdicts{};
  std::size_t count(Verdict v) const { return verdicts[static_cast<int>(v)]; }
  /// Features with new vertices on both sides of the user's selection's border.
  std::size_t cutBySelection = 0;
};

/// Extended method: segmentation and zone labelling.
struct ExtendedStats {
  std::size_t regions = 0;               ///< smooth regions kept
  std::size_t corridors = 0;             ///< thin smooth regions returned to the zone
  std::size_t openedContacts = 0;        ///< region faces returned to the zone at region contacts
  std::size_t keptFacets = 0;            ///< narrow facets kept whole at region contacts
  std::size_t planarRegions = 0;         ///< regions that are planes (their own plane placed)
  std::size_t openedCreases = 0;         ///< region faces returned to the zone at internal creases
  std::size_t zoneFaces = 0;             ///< faces outside every region
  std::size_t zoneVertices = 0;          ///< vertices outside every region
  std::size_t labelledZoneVertices = 0;  ///< zone vertices given a region label
  std::size_t projectedVertices = 0;     ///< zone vertices moved onto their region's plane
  std::size_t projectionsRejected = 0;   ///< moves refused by the displacement/quality guards
  double maxProjection = 0;              ///< longest such move
  double sampleSpacing = 0;  ///< the input's median edge length: the unit of every `...Spacings`
};

/// What the input had at its non-manifold spots.
struct NonManifoldStats {
  std::size_t edges = 0;          ///< edges shared by three or more faces
  std::size_t vertices = 0;       ///< vertices whose faces are not one fan (edge ends included)
  std::size_t heldFaces = 0;      ///< faces left as they came there
  std::size_t firstHeldFace = 0;  ///< lowest input index of a held face
};

struct SharpenReport {
  std::size_t inputVertices = 0, inputFaces = 0;
  std::size_t inputBorderEdges = 0;  ///< edges of the input with one face (open borders)
  std::size_t outputVertices = 0, outputFaces = 0;
  double longestInputEdge = 0;
  SmoothEdgeStats smooth;
  FilterStats filters;
  SubdivisionStats subdivision;
  PlacementStats placement;
  CleanupStats cleanup;
  PlanarFoldStats planarFolds;  ///< auto method only
  IntersectionStats intersections;
  bool evidenceGuard = false;  ///< the auto method's evidence guard ran
  EvidenceStats evidence;
  std::vector<FeatureRecord> features;  ///< the auto method's, each with its verdict
  bool extendedMethod = false;
  ExtendedStats extended;        ///< filled by the extended method only
  bool geometryChanged = false;  ///< false for detection-only runs
  NonManifoldStats nonManifold;  ///< the spots held as they came (none: zeros)
  /// Connected parts, when some were sampled at spacings so different that
  /// each was sharpened at its own (util/part_scales.h; else both 0).
  std::size_t parts = 0, partsRescaled = 0;
  /// SharpenOptions::selectedFacesOnly: the faces selected (else both 0).
  bool selectedFacesOnly = false;
  std::size_t selectedFaces = 0;
  /// detectChamfers(): the faces it selected (those Sharpen may change).
  std::size_t detectedFaces = 0;
};

namespace detail {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

inline void formatDetection(std::ostream &s, const SharpenReport &r) {
  s << "smooth edges: " << r.smooth.smoothEdges << " of " << r.smooth.edges
    << " (mean normal angle " << r.smooth.meanAngleRad * kDegreesPerRadian << " deg, threshold "
    << r.smooth.thresholdRad * kDegreesPerRadian << " deg; boundary " << r.smooth.boundaryEdges
    << ", next to degenerate faces " << r.smooth.degenerateEdges << ")\n";
  s << "filters: interior red vertices " << r.filters.interiorRedVertices << ", core red faces "
    << r.filters.coreRedFaces << ", red faces " << r.filters.redFaces << ", red vertices "
    << r.filters.redVertices << ", chamfer edges " << r.filters.chamferEdges << ", chamfer faces "
    << r.filters.chamferFaces << ", corner faces " << r.filters.cornerFaces << "\n";
}

inline void formatFeatureZones(std::ostream &s, const SharpenReport &r) {
  const ExtendedStats &e = r.extended;
  s << "feature zones: " << e.regions << " smooth regions (" << e.planarRegions << " planes, "
    << e.corridors << " corridors dissolved), " << e.zoneFaces << " zone faces ("
    << e.openedContacts << " opened at region contacts (" << e.keptFacets
    << " narrow facets kept), " << e.openedCreases << " at internal creases), "
    << e.labelledZoneVertices << " of " << e.zoneVertices
    << " zone vertices labelled, sample spacing " << e.sampleSpacing;
  if (r.geometryChanged)
    s << ", " << e.projectedVertices << " projected onto their region (max " << e.maxProjection
      << ", " << e.projectionsRejected << " refused)";
  s << "\n";
}

inline void formatPlacement(std::ostream &s, const SharpenReport &r) {
  s << "subdivision: " << r.subdivision.facesSplitIn2 << " faces split in 2, "
    << r.subdivision.facesSplitIn3 << " in 3, " << r.subdivision.facesSplitIn6 << " in 6; "
    << r.subdivision.insertedVertices << " vertices and " << r.subdivision.addedFaces
    << " faces added\n";
  s << "placement: " << r.placement.moved() << " moved (max displacement "
    << r.placement.maxDisplacement;
  if (r.placement.movedAcrossBends > 0)
    s << "; " << r.placement.movedAcrossBends << " with their feature across a bending flank";
  s << "), " << r.placement.fallbacks() << " kept by fallback";
  for (int i = 0; i < kPlacementCount; ++i) {
    auto p = static_cast<Placement>(i);
    if (p == Placement::Original || p == Placement::Moved || r.placement.byOutcome[i] == 0)
      continue;
    s << "; " << toString(p) << " " << r.placement.byOutcome[i];
  }
  s << "\n";
}

inline void formatGuards(std::ostream &s, const SharpenReport &r) {
  s << "cleanup: " << r.cleanup.degenerateFound << " degenerate faces found, "
    << r.cleanup.collapses << " collapses, " << r.cleanup.flips << " flips, " << r.cleanup.reverted
    << " vertices reverted";
  if (r.evidenceGuard) s << " (" << r.cleanup.partWay << " taken part of the way out again)";
  s << ", " << r.cleanup.remaining << " remaining, " << r.cleanup.inherited
    << " inherited from input slivers\n";
  if (r.evidenceGuard)
    s << "planar folds: " << r.planarFolds.folds << " folded faces found, " << r.planarFolds.patches
      << " flat patches tiled again, " << r.planarFolds.relaxedVertices
      << " vertices moved on a fold's plane\n";
  s << "self-intersections: " << r.intersections.intersectingPairs
    << " intersecting face pairs found, " << r.intersections.reverted
    << " inserted vertices reverted";
  if (r.extendedMethod) s << ", " << r.intersections.zoneReverted << " zone vertices reverted";
  s << " (" << r.intersections.rounds << " rounds), " << r.intersections.remaining
    << " left as they are (they intersect at rest too)\n";
  if (!r.evidenceGuard) return;
  const char *verdict = !r.evidence.wholeMeshLeft ? ""
                        : r.evidence.flattenedVertices == 0
                            ? ": too little evidence, the mesh is left as it was"
                            : ": too little evidence, no feature sharpened";
  s << "evidence: " << r.evidence.weakFeatures << " of " << r.evidence.features
    << " features left as they were (";
  if (r.evidence.alreadySharpFeatures > 0)
    s << r.evidence.alreadySharpFeatures << " of them already sharp; ";
  s << r.evidence.reverted << " inserted and " << r.evidence.zoneReverted
    << " zone vertices sent back); " << int(std::lround(100 * r.evidence.refusedFraction))
    << "% of the moves refused (bound " << int(std::lround(100 * r.evidence.refusedBound)) << "%), "
    << "median lift " << std::lround(100 * r.evidence.medianLift) / 100.0 << ", noise "
    << std::lround(1000 * r.evidence.noiseSpacings) / 1000.0 << " spacings, "
    << int(std::lround(100 * r.evidence.planarFraction)) << "% of the area on planes"
    << (r.evidence.exactSampling ? ", sampled exactly on its surface" : "") << verdict << "; ";
  if (r.evidence.flattenedVertices > 0)
    s << r.evidence.flattenedVertices
      << " vertices of the rough input's planar regions flattened onto their planes ("
      << r.evidence.grownPlanes << " planes grown face by face); ";
  s << r.evidence.facesGivenBack << " split faces at rest given back their input face, "
    << r.evidence.restingVerticesRemoved << " other inserted vertices at rest removed\n";
}

}  // namespace detail

/// What each stage did, one line per stage (the middle of formatReport; the
/// CLI's --verbose).
inline std::string formatStages(const SharpenReport &r) {
  std::ostringstream s;
  detail::formatDetection(s, r);
  if (r.extendedMethod) detail::formatFeatureZones(s, r);
  if (!r.geometryChanged) return s.str();
  detail::formatPlacement(s, r);
  detail::formatGuards(s, r);
  return s.str();
}

/// The full stage report, one line per stage between the input and the output
/// (the CLI's --verbose, the MeshLab log).
inline std::string formatReport(const SharpenReport &r) {
  std::ostringstream s;
  s << "input: " << r.inputVertices << " vertices, " << r.inputFaces << " faces, longest edge "
    << r.longestInputEdge << "\n";
  s << formatStages(r);
  if (!r.geometryChanged) return s.str();
  s << "output: " << r.outputVertices << " vertices, " << r.outputFaces << " faces\n";
  return s.str();
}

namespace detail {

/// "features: 14 restored, 3 left as they were: 2 too short, 1 shallow angle"
inline void formatVerdictCounts(std::ostream &s, const EvidenceStats &e) {
  std::size_t features = 0;
  for (const std::size_t n : e.verdicts) features += n;
  if (features == 0) {
    s << "features: none found to restore";
    return;
  }
  const std::size_t restored = e.count(Verdict::Restored);
  s << "features: " << restored << " restored, ";
  if (restored == features) {
    s << "none left";
    return;
  }
  s << features - restored << " left as they were:";
  const char *separator = " ";
  for (int i = 0; i < kVerdictCount; ++i) {
    const auto v = static_cast<Verdict>(i);
    if (!isLeft(v) || e.verdicts[i] == 0) continue;
    s << separator << e.verdicts[i] << " " << describe(v);
    separator = ", ";
  }
}

}  // namespace detail

/// What was restored and what was left, in one line without a newline (the
/// CLI's default output, the MeshLab log, the JSON report's "summary"):
///   auto:      "features: 14 restored, 3 left as they were: 2 too short, 1 shallow angle"
///              (each verdict that occurred, in describe()'s words)
///   paper, extended: "new vertices: 120 placed on sharp edges, 8 left at rest"
///   detection only, auto: "detected, as Sharpen judges them: features: 14 restored, ...;
///                          740 faces selected, those Sharpen changes (geometry unchanged)"
///   detection only, others: "detected: 686 chamfer faces, 12 corner faces, 6722
///                     smooth-region faces; 740 faces selected, those Sharpen may change"
inline std::string formatVerdictSummary(const SharpenReport &r) {
  std::ostringstream s;
  if (r.selectedFacesOnly && r.selectedFaces == 0)
    return "nothing selected: the mesh is left as it came";
  if (!r.geometryChanged && r.evidenceGuard) {
    s << "detected, as Sharpen judges them: ";
    detail::formatVerdictCounts(s, r.evidence);
    s << "; " << r.detectedFaces << " faces selected, those Sharpen changes (geometry unchanged)";
    return s.str();
  }
  if (!r.geometryChanged) {
    s << "detected: " << r.filters.chamferFaces << " chamfer faces, " << r.filters.cornerFaces
      << " corner faces, " << r.filters.redFaces << " smooth-region faces; " << r.detectedFaces
      << " faces selected, those Sharpen may change (geometry unchanged)";
    return s.str();
  }
  if (r.evidenceGuard) {
    detail::formatVerdictCounts(s, r.evidence);
    if (r.evidence.flattenedVertices > 0)
      s << "; " << r.evidence.flattenedVertices << " vertices flattened onto their planes";
    return s.str();
  }
  s << "new vertices: " << r.placement.moved() << " placed on sharp edges, "
    << r.placement.fallbacks() << " left at rest";
  if (r.extendedMethod && r.extended.projectedVertices > 0)
    s << "; " << r.extended.projectedVertices << " zone vertices moved onto their planes";
  return s.str();
}

/// What the input had that the run left as it came or handled apart, in one
/// line for people ("" when nothing): its non-manifold spots, its parts at
/// other spacings, its open borders, the user's selection.
inline std::string formatInputNotes(const SharpenReport &r) {
  std::ostringstream s;
  const NonManifoldStats &n = r.nonManifold;
  if (n.vertices > 0)
    s << "non-manifold: " << n.edges << (n.edges == 1 ? " edge, " : " edges, ") << n.vertices
      << (n.vertices == 1 ? " vertex" : " vertices") << "; the " << n.heldFaces
      << " faces there left as they came (the first: face " << n.firstHeldFace << ")";
  if (r.partsRescaled > 0)
    s << (n.vertices > 0 ? "; " : "") << "parts: " << r.parts << ", " << r.partsRescaled
      << " of them sampled at other spacings than the largest, each sharpened at its own";
  if (r.inputBorderEdges > 0)
    s << (n.vertices > 0 || r.partsRescaled > 0 ? "; " : "") << "open: " << r.inputBorderEdges
      << " border edges, their vertices kept where they are";
  if (r.selectedFacesOnly) {
    s << (s.tellp() > 0 ? "; " : "") << "selection: " << r.selectedFaces << " of " << r.inputFaces
      << " faces";
    if (r.selectedFaces == 0)
      ;  // formatVerdictSummary says it
    else if (r.evidenceGuard) {
      s << ", " << r.evidence.count(Verdict::OutsideSelection)
        << " features outside it left as they came";
      if (r.evidence.cutBySelection > 0)
        s << ", " << r.evidence.cutBySelection << " it cuts sharpened up to its border";
    } else
      s << ", the faces outside it neither split nor moved";
  }
  return s.str();
}

}  // namespace edge_sharpener
