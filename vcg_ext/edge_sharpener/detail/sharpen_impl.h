// Implementation of the entry points declared in edge_sharpener.h: the
// stages run in order, each returning the counts that go into the report.
#pragma once

#include <vcg/complex/complex.h>
// (vcglib's algorithm headers need complex.h first)
#include <vcg/complex/algorithms/update/normal.h>

#include "../cleanup.h"
#include "../colorize.h"
#include "../feature_zones.h"
#include "../filters.h"
#include "../input_check.h"
#include "../intersection_guard.h"
#include "../option_table.h"
#include "../placement.h"
#include "../sampling_grid.h"
#include "../smooth_edges.h"
#include "../subdivision.h"
#include "../vertex_moves.h"

namespace edge_sharpener {

namespace detail {

inline void reportProgress(const SharpenOptions &opt, int percent, const char *stage) {
  if (opt.progress) opt.progress(percent, stage);
}

template <class MeshType>
double longestEdgeLength(MeshType &m) {
  double longest2 = 0;
  const std::int64_t nf = std::int64_t(m.face.size());
#pragma omp parallel for schedule(static, 8192) reduction(max : longest2) if (nf > kParallelMin)
  for (std::int64_t fi = 0; fi < nf; ++fi) {
    const auto &f = m.face[fi];
    if (f.IsD()) continue;
    for (int i = 0; i < 3; ++i)
      longest2 =
          std::max(longest2, (positionOf(f.cV(i)) - positionOf(f.cV((i + 1) % 3))).SquaredNorm());
  }
  return std::sqrt(longest2);
}

/// Smooth-edge test, then detection by the chosen method: the paper's six
/// filters, or the extended method's regions and zone labels.
/// Fills zones.support with the support plane of every original vertex (and,
/// for the extended method, the rest of `zones`).
template <class MeshType>
void detect(MeshType &m, MeshLabels<MeshType> &labels, const SharpenOptions &opt,
            SharpenReport &report, FeatureZones &zones) {
  reportProgress(opt, 5, "Edge-Sharpener: smooth edges");
  computeFaceNormals(m, labels);
  report.smooth = labelSmoothEdges(m, labels, opt.smoothMultiplier);
  if (opt.method == Method::Paper) {
    reportProgress(opt, 20, "Edge-Sharpener: six filters");
    report.filters = runSixFilters(m, labels);
    zones.support = paperSupportPlanes(m, labels);
    return;
  }
  reportProgress(opt, 20, "Edge-Sharpener: feature zones");
  report.extendedMethod = true;
  zones.inputFaces = VertexFaceTable(m);
  const VertexFaceTable &vf = zones.inputFaces;
  segmentRegions(m, labels, vf, opt.minRegionDepth, zones, report.extended,
                 report.smooth.boundaryEdges > 0);
  if (opt.openRegionContacts) {
    report.extended.openedContacts = openRegionContacts(m, vf, zones);
    report.extended.zoneFaces += report.extended.openedContacts;
  }
  if (opt.openInternalCreases) {
    // A coarse sampling of a curved surface has large angles everywhere.
    const double creaseAngle = std::max(
        opt.internalCreaseAngleRad, opt.internalCreaseThresholdFactor * report.smooth.thresholdRad);
    report.extended.openedCreases = openInternalCreases(m, labels, vf, creaseAngle, zones);
    report.extended.zoneFaces += report.extended.openedCreases;
  }
  if (opt.borderTurnThresholdFactor > 0) {
    report.extended.returnedBorderFaces = returnTurnedBorderFaces(
        m, labels, vf, opt, opt.borderTurnThresholdFactor * report.smooth.thresholdRad, zones);
    report.extended.zoneFaces += report.extended.returnedBorderFaces;
  }
  labelZoneVertices(m, vf, opt, zones, report.extended);
  if (opt.samplingGridGuard) zones.samplingGrid = detectSamplingGrid(m);
  zones.support.sampleSpacing = medianEdgeLength(m);
  if (opt.maxSourceOffPlaneSpacings > 0) measureOffPlane(m, zones);
  report.filters = markZoneChamfers(m, labels, zones, opt.sameRegionFeatureAngleRad);
}

template <class MeshType>
SharpenReport validate(MeshType &m, const SharpenOptions &opt) {
  vcg::tri::RequireFFAdjacency(m);
  vcg::tri::RequireCompactness(m);
  if (std::string problem = findOptionProblem(opt); !problem.empty()) throw InputError(problem);
  const std::string problem = findInputProblem(m);
  if (!problem.empty()) throw InputError(problem);
  SharpenReport report;
  report.inputVertices = m.vert.size();
  report.inputFaces = m.face.size();
  report.longestInputEdge = longestEdgeLength(m);
  return report;
}

}  // namespace detail

template <class MeshType>
SharpenReport detectChamfers(MeshType &m, const SharpenOptions &opt) {
  SharpenReport report = detail::validate(m, opt);
  MeshLabels<MeshType> labels(m);
  FeatureZones zones;
  detail::detect(m, labels, opt, report, zones);
  colorize(m, labels);
  selectChamferFaces(m, labels);
  report.outputVertices = m.vert.size();
  report.outputFaces = m.face.size();
  detail::reportProgress(opt, 100, "Edge-Sharpener: done");
  return report;
}

template <class MeshType>
SharpenReport sharpen(MeshType &m, const SharpenOptions &opt) {
  using Alloc = vcg::tri::Allocator<MeshType>;
  if (opt.colorize) {
    vcg::tri::RequirePerFaceColor(m);
    vcg::tri::RequirePerVertexColor(m);
  }
  SharpenReport report = detail::validate(m, opt);
  report.geometryChanged = true;
  MeshLabels<MeshType> labels(m);
  FeatureZones zones;
  detail::detect(m, labels, opt, report, zones);

  detail::reportProgress(opt, 40, "Edge-Sharpener: subdivision");
  const SplitPlan plan = planSplits(m, labels);
  report.subdivision = subdivide(m, plan, labels);
  VertexMoves<MeshType> moves(m, plan, labels, opt.method == Method::Extended);
  const auto &restBeforeProjection = moves.originalRest();

  detail::reportProgress(opt, 60, "Edge-Sharpener: vertex placement");
  report.placement =
      placeInsertedVertices(m, plan, labels, report.longestInputEdge, opt, zones.support);
  if (opt.method == Method::Extended) {
    std::vector<char> nearSharpEdge(plan.originalVertexCount, 0);
    for (std::size_t k = 0; k < plan.inserted.size(); ++k)
      if (labels.placement[plan.originalVertexCount + k] == Placement::Moved)
        for (int i = 0; i < plan.inserted[k].originalCount; ++i)
          nearSharpEdge[plan.inserted[k].original[i]] = 1;
    projectZoneVertices(m, zones, plan.originalVertexCount, nearSharpEdge, opt, report.extended);
    if (opt.samplingGridGuard) {
      report.grid =
          revertGridContradictions(m, moves, zones.samplingGrid, opt.gridSweepToleranceCells);
      revertBlendedFeatures(moves, zones.support.region, opt.gridBlendedFeatureFraction,
                            report.grid);
      report.extended.projectedVertices -= report.grid.zoneReverted;
    }
  }

  detail::reportProgress(opt, 80, "Edge-Sharpener: degenerate cleanup");
  report.cleanup = removeDegenerateTriangles(m, plan, labels, opt.degenerateAngleRad);
  report.intersections = revertSelfIntersections(m, plan, labels, restBeforeProjection,
                                                 opt.degenerateAngleRad, report.longestInputEdge);
  report.extended.projectedVertices -= report.intersections.zoneReverted;
  // Outcomes as they stand after cleanup (collapsed vertices are gone).
  report.placement.byOutcome.fill(0);
  report.placement.maxDisplacement = 0;
  for (std::size_t k = 0; k < plan.inserted.size(); ++k) {
    const auto &v = m.vert[plan.originalVertexCount + k];
    if (v.IsD()) continue;
    ++report.placement.byOutcome[int(labels.placement[&v])];
    report.placement.maxDisplacement =
        std::max(report.placement.maxDisplacement, (positionOf(&v) - plan.inserted[k].rest).Norm());
  }

  if (opt.colorize) colorize(m, labels);
  Alloc::CompactEveryVector(m);
  if (vcg::tri::HasPerFaceNormal(m)) vcg::tri::UpdateNormal<MeshType>::PerFaceNormalized(m);
  if (vcg::tri::HasPerVertexNormal(m)) vcg::tri::UpdateNormal<MeshType>::PerVertexNormalized(m);
  report.outputVertices = m.vert.size();
  report.outputFaces = m.face.size();
  detail::reportProgress(opt, 100, "Edge-Sharpener: done");
  return report;
}

}  // namespace edge_sharpener
