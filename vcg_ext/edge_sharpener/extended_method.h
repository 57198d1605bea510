// The extended method's two stages as sharpen() calls them: detection
// (smooth regions, the feature zone between them, zone labels, chamfer
// edges) in place of the paper's six filters, and the refinement after the
// paper's placement (zone projection).
#pragma once

#include "extended/feature_zones.h"
#include "guards/vertex_moves.h"
#include "options.h"
#include "report.h"

namespace edge_sharpener {

/// Detection by feature zones: smooth regions segmented; faces returned to
/// the zone where regions touch or crease;
/// zone vertices labelled with the surface they sample; chamfer edges
/// marked between differently labelled vertices. Fills `zones` (support
/// planes included) and report.extended / report.filters.
/// \pre face normals and smooth-edge labels computed.
template <class MeshType>
void detectFeatureZones(MeshType &m, MeshLabels<MeshType> &labels, const SharpenOptions &opt,
                        SharpenReport &report, FeatureZones &zones) {
  report.extendedMethod = true;
  ExtendedStats &stats = report.extended;
  zones.inputFaces = VertexFaceTable(m);
  const VertexFaceTable &vf = zones.inputFaces;
  const bool meshHasBorder = report.smooth.boundaryEdges > 0;
  segmentRegions(m, labels, vf, opt.extended.minRegionDepth, zones, stats, meshHasBorder);
  zones.support.sampleSpacing = medianEdgeLength(m);
  stats.sampleSpacing = zones.support.sampleSpacing;
  if (opt.extended.openRegionContacts) {
    stats.openedContacts = openRegionContacts(
        m, vf, zones, opt.extended.minFacetLengthSpacings * zones.support.sampleSpacing,
        stats.keptFacets, meshHasBorder);
    stats.zoneFaces += stats.openedContacts;
  }
  if (opt.extended.openInternalCreases) {
    // A coarse sampling of a curved surface has large angles everywhere.
    const double creaseAngle =
        std::max(opt.extended.internalCreaseAngleRad,
                 opt.extended.internalCreaseThresholdFactor * report.smooth.thresholdRad);
    stats.openedCreases = openInternalCreases(m, labels, vf, creaseAngle, zones);
    stats.zoneFaces += stats.openedCreases;
  }
  labelZoneVertices(m, vf, opt, zones, stats);
  report.filters = markZoneChamfers(m, labels, zones, opt.extended.sameRegionFeatureAngleRad);
}

/// Per original vertex: 1 when it is a source of an inserted vertex that
/// placement moved (it lies next to a sharp edge being restored).
template <class MeshType>
std::vector<char> sourcesOfMovedVertices(const VertexMoves<MeshType> &moves) {
  const SplitPlan &plan = moves.plan();
  std::vector<char> source(plan.originalVertexCount, 0);
  for (std::size_t k = 0; k < plan.inserted.size(); ++k)
    if (moves.isMoved(plan.originalVertexCount + k))
      for (int i = 0; i < plan.inserted[k].originalCount; ++i)
        source[plan.inserted[k].original[i]] = 1;
  return source;
}

/// After the paper's placement: the zone vertices next to a restored sharp
/// edge move onto their region's plane.
template <class MeshType>
void refineExtendedPlacement(MeshType &m, VertexMoves<MeshType> &moves, const FeatureZones &zones,
                             const SharpenOptions &opt, SharpenReport &report) {
  projectZoneVertices(m, zones, moves.firstInserted(), sourcesOfMovedVertices(moves), opt,
                      report.extended);
}

}  // namespace edge_sharpener
