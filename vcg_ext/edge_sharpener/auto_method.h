// The auto method's steps beyond the extended method, as its pipeline calls
// them (sharpen_impl.h: sharpenAuto): the input it may give back, its
// measures, the judgement of every feature, the guards it may undo whole,
// and what it gives back or flattens at the end. Its state lives here, in
// one object; its counts in one EvidenceStats, read once by the report.
#pragma once

#include <algorithm>
#include <optional>
#include <tuple>
#include <vector>

#include "cleanup.h"
#include "extended/plane_patches.h"
#include "extended/zones.h"
#include "guards/element_snapshot.h"
#include "guards/feature_evidence.h"
#include "guards/intersection_guard.h"
#include "guards/planar_folds.h"
#include "guards/refused_moves.h"
#include "guards/surface_measures.h"
#include "guards/vertex_moves.h"
#include "options.h"
#include "report.h"
#include "util/non_manifold.h"

namespace edge_sharpener {

/// What the cleanup and the guards after it did (zero where undone whole).
struct GuardStats {
  CleanupStats cleanup;
  PlanarFoldStats planarFolds;
  IntersectionStats intersections;
};

namespace detail {

/// Auto method, on a rough input (a fused scan: its noise above the smooth
/// bound) left whole: the vertices labelled with its planar regions onto
/// their planes, on the regions' faces, and the vertices bulged beyond a
/// convex edge or corner behind its planes (flattenPlanarRegions, within
/// RoughInputRules::kFlattenMaxSpacings). Where that moved a share of the
/// vertices (kGrownPlanesEvidence: the planes bulge as a fused scan's do; an
/// exact mesh's planes move none), the same again on planes grown face by
/// face (growPlanePatches), which the segmentation may have merged across a
/// rounded edge. A vertex labelled with a region that is a plane keeps it: its
/// core's fit is the better estimate of the face, while a plane grown over
/// the whole face takes in the rounding a reconstruction leaves along its
/// edges; it may still go behind the grown planes of a convex edge or corner
/// it bulges beyond. \return the number of vertices moved and of planes grown.
template <class MeshType>
std::pair<std::size_t, std::size_t> flattenRoughPlanes(MeshType &m, const FeatureZones &zones,
                                                       const SurfaceMeasures &surface,
                                                       const SharpenOptions &opt) {
  using Rough = RoughInputRules;
  if (!opt.rules.rough.flattenRoughPlanes || zones.support.regionPlanes.empty() ||
      !(surface.noiseSpacings > opt.rules.mesh.maxSmoothNoiseSpacings))
    return {0, 0};
  const double spacing = spacingUnit(zones.support);
  const double minMove = Rough::kFlattenMinSpacings * spacing;
  const double maxMove = Rough::kFlattenMaxSpacings * spacing;
  const int outward = outwardSign(m);
  const VertexFaceTable vf(m);  // the flattening moves vertices only
  using Coord = typename MeshType::CoordType;
  std::vector<Coord> input(m.vert.size());
  for (std::size_t v = 0; v < m.vert.size(); ++v) input[v] = m.vert[v].cP();
  const std::size_t onRegions =
      flattenPlanarRegions(m, vf, zones, zones.support.regionPlanes, minMove, maxMove, outward);
  std::size_t grown = 0;
  if (double(onRegions) >= Rough::kGrownPlanesEvidence * double(m.vn)) {
    PlanePatchSettings settings;
    settings.maxTurnRad = settings.pairAngleRad = opt.rules.feature.minFeatureAngleRad;
    const PlanePatches patches = growPlanePatches(m, vf, spacing, settings);
    grown = patches.count();
    std::vector<char> onRegionPlane(m.vert.size(), 0);
    for (std::size_t v = 0; v < std::min(zones.vertexLabel.size(), m.vert.size()); ++v)
      onRegionPlane[v] = regionPlaneOf(zones.support.regionPlanes, zones.vertexLabel[v]) != nullptr;
    flattenPlanarRegions(m, vf, patches.labels, patches.planes, minMove, maxMove, outward,
                         onRegionPlane);
  }
  std::size_t moved = 0;
  for (std::size_t v = 0; v < m.vert.size(); ++v) moved += !(m.vert[v].cP() == input[v]);
  return {moved, grown};
}

}  // namespace detail

/// The auto method's state: the input's faces and measures, taken before the
/// split; the evidence guard, after placement; the counts of every step.
template <class MeshType>
class AutoMethod {
 public:
  /// Before the split: keeps the input's faces (to give back where nothing
  /// moved) and measures its surface (noise, planar share).
  AutoMethod(MeshType &m, const FeatureZones &zones, const SharpenOptions &opt,
             const HeldFaces &held)
      : m_(m),
        zones_(zones),
        opt_(opt),
        held_(held),
        input_(m),
        surface_(
            measureSurface(m, zones.inputFaces, zones.faceRegion, zones.support.sampleSpacing)) {}

  /// After placement: judges every feature (a verdict each) and sends back
  /// to rest the moves of those left and of the vertices weak on their own,
  /// and every vertex of a face outside the user's selection.
  void judgeFeatures(VertexMoves<MeshType> &moves, double longestInputEdge) {
    guard_.emplace(m_, moves, zones_.support,
                   InputSurface{zones_.inputFaces, input_.faceVertices()}, surface_,
                   longestInputEdge, opt_, held_);
    stats_ = guard_->revertWeakFeatures();
    for (std::size_t f = 0; f < held_.unselected.size(); ++f) {
      if (!held_.unselected[f]) continue;
      for (const std::uint32_t v : input_.faceVertices()[f])
        if (moves.hasRest(v) && moves.isMoved(v)) {
          moves.sendBack(v, Placement::Original);
          ++stats_.zoneReverted;
        }
    }
  }

  /// The degenerate cleanup (where vertices moved), the planar folds and the
  /// intersection guard; when they refused so many moves that the mesh as a
  /// whole shows too little evidence, all of it is undone and every vertex
  /// goes back to rest (its cleanup and intersection counts then zero).
  GuardStats runGuards(VertexMoves<MeshType> &moves, MeshLabels<MeshType> &labels,
                       double longestInputEdge) {
    const ElementSnapshot<MeshType> beforeGuards(m_, labels);
    GuardStats guards = cleanUp(moves, longestInputEdge);
    // A corner placed whole that the guards could not keep whole is given up,
    // and they run again without it.
    if (guard_->cornerPatchRefused()) {
      beforeGuards.restore(m_, labels);
      guard_->leaveRefusedCornerPatches(stats_);
      guards = cleanUp(moves, longestInputEdge);
    }
    if (guard_->leaveMeshIfGuardsRefused(beforeGuards, stats_)) {
      guards.cleanup = {};
      guards.intersections = {};
    }
    return guards;
  }

  /// The degenerate cleanup (where vertices moved), the planar folds and the
  /// intersection guard, once.
  GuardStats cleanUp(VertexMoves<MeshType> &moves, double longestInputEdge) {
    GuardStats guards;
    const std::vector<char> placedWhole = guard_->placedWholeVertices();
    std::vector<RefusedPlacement> refused;
    guards.cleanup = removeDegenerateTriangles(m_, moves, opt_.degenerateAngleRad,
                                               /*onlyWhereMoved=*/true, &placedWhole, &refused);
    const double spacing = spacingUnit(zones_.support);
    FoldSettings folds;
    folds.planeTolerance = VertexRules::kFoldPlaneSpacings * spacing;
    folds.minAngleRad = opt_.degenerateAngleRad;
    folds.exactTolerance = opt_.rules.mesh.exactSamplingSpacings * spacing;
    folds.parallelAngleRad = opt_.paper.parallelAngleRad;
    folds.relaxRings = opt_.extended.maxLabelHops;  // a fold sharpening made lies in its zone
    guards.planarFolds = unfoldPlanarPatches(
        m_, [&](std::size_t v) { return !moves.isAtRest(v); }, folds);
    guards.intersections = revertSelfIntersections(m_, moves, opt_.degenerateAngleRad,
                                                   longestInputEdge, &guard_->retreatFirst());
    guards.cleanup.partWay =
        takeRefusedPartWay(m_, moves, refused, opt_.degenerateAngleRad, longestInputEdge);
    return guards;
  }

  /// Split faces whose vertices all rest back to their input face, the other
  /// inserted vertices at rest merged away; a rough input left whole gets its
  /// planes flattened (detail::flattenRoughPlanes).
  void giveBackResting(const VertexMoves<MeshType> &moves) {
    const int verticesBefore = m_.vn, facesBefore = m_.fn;
    stats_.facesGivenBack = input_.unsplitResting(m_, moves);
    stats_.restingVerticesRemoved = InputFaces<MeshType>::dissolveRestingEdgeVertices(m_, moves);
    stats_.verticesRemoved = std::size_t(verticesBefore - m_.vn);
    stats_.facesRemoved = std::size_t(facesBefore - m_.fn);
    if (stats_.wholeMeshLeft)
      std::tie(stats_.flattenedVertices, stats_.grownPlanes) =
          detail::flattenRoughPlanes(m_, zones_, surface_, opt_);
  }

  /// Every step's counts.
  const EvidenceStats &stats() const { return stats_; }

  /// Per face of the mesh as it is now, the verdict its colour shows
  /// (EvidenceGuard::outputFaceVerdicts, from featureRecords(); all
  /// kNoVerdict before judgeFeatures()).
  FaceVerdicts outputFaceVerdicts(const std::vector<FeatureRecord> &features,
                                  std::size_t inputFaceCount) const {
    return guard_ ? guard_->outputFaceVerdicts(features, inputFaceCount)
                  : FaceVerdicts(m_.face.size(), kNoVerdict);
  }

  /// Every feature with its verdict (after the guards).
  std::vector<FeatureRecord> featureRecords() const {
    return guard_ ? guard_->records() : std::vector<FeatureRecord>{};
  }

 private:
  MeshType &m_;
  const FeatureZones &zones_;
  const SharpenOptions &opt_;
  const HeldFaces &held_;
  InputFaces<MeshType> input_;
  SurfaceMeasures surface_;
  std::optional<EvidenceGuard<MeshType>> guard_;  ///< from judgeFeatures() on
  EvidenceStats stats_;
};

}  // namespace edge_sharpener
