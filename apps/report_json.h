// JSON form of SharpenReport, for the CLI's --json output and the benchmarks.
#pragma once

#include <nlohmann/json.hpp>

#include "edge_sharpener/option_table.h"
#include "edge_sharpener/report.h"

namespace edge_sharpener {

/// The options a run used, one key per row of the option table (angles in
/// degrees, as entered).
inline nlohmann::json optionsToJson(const SharpenOptions &opt) {
  nlohmann::json j = nlohmann::json::object();
  for (const OptionSpec &spec : optionTable()) {
    const std::string key(spec.key);
    const double value = spec.get(opt);
    switch (spec.type) {
      case OptionType::Flag: j[key] = value != 0; break;
      case OptionType::Choice: j[key] = std::string(spec.choiceName(value)); break;
      case OptionType::Integer: j[key] = int(value); break;
      case OptionType::Real: j[key] = value; break;
    }
  }
  return j;
}

/// The report as JSON: each stage's counts; "evidence" (the auto method) with
/// "verdicts", {verdict name: features}, every verdict; "summary", the line
/// formatVerdictSummary() writes; "input_notes", formatInputNotes()'s ("" when
/// nothing to say).
inline nlohmann::json reportToJson(const SharpenReport &r) {
  nlohmann::json placement = {{"moved", r.placement.moved()},
                              {"fallbacks", r.placement.fallbacks()},
                              {"max_displacement", r.placement.maxDisplacement},
                              {"moved_across_bends", r.placement.movedAcrossBends}};
  for (int i = 0; i < kPlacementCount; ++i) {
    const auto p = static_cast<Placement>(i);
    if (p != Placement::Original && p != Placement::Moved)
      placement["fallback_" + std::string(toString(p))] = r.placement.byOutcome[i];
  }
  nlohmann::json j = {
      {"input",
       {{"vertices", r.inputVertices},
        {"faces", r.inputFaces},
        {"border_edges", r.inputBorderEdges},
        {"longest_edge", r.longestInputEdge}}},
      {"output", {{"vertices", r.outputVertices}, {"faces", r.outputFaces}}},
      {"geometry_changed", r.geometryChanged},
      {"non_manifold",
       {{"edges", r.nonManifold.edges},
        {"vertices", r.nonManifold.vertices},
        {"held_faces", r.nonManifold.heldFaces},
        {"first_held_face", r.nonManifold.firstHeldFace}}},
      {"parts", {{"parts", r.parts}, {"rescaled", r.partsRescaled}}},
      {"selection",
       {{"selected_faces_only", r.selectedFacesOnly}, {"selected_faces", r.selectedFaces}}},
      {"smooth_edges",
       {{"edges", r.smooth.edges},
        {"boundary", r.smooth.boundaryEdges},
        {"next_to_degenerate", r.smooth.degenerateEdges},
        {"smooth", r.smooth.smoothEdges},
        {"mean_angle_rad", r.smooth.meanAngleRad},
        {"threshold_rad", r.smooth.thresholdRad}}},
      {"filters",
       {{"interior_red_vertices", r.filters.interiorRedVertices},
        {"core_red_faces", r.filters.coreRedFaces},
        {"red_faces", r.filters.redFaces},
        {"red_vertices", r.filters.redVertices},
        {"red_edges", r.filters.redEdges},
        {"chamfer_edges", r.filters.chamferEdges},
        {"chamfer_faces", r.filters.chamferFaces},
        {"corner_faces", r.filters.cornerFaces}}},
      {"subdivision",
       {{"faces_split_in_2", r.subdivision.facesSplitIn2},
        {"faces_split_in_3", r.subdivision.facesSplitIn3},
        {"faces_split_in_6", r.subdivision.facesSplitIn6},
        {"inserted_vertices", r.subdivision.insertedVertices},
        {"added_faces", r.subdivision.addedFaces}}},
      {"placement", placement},
      {"cleanup",
       {{"degenerate_found", r.cleanup.degenerateFound},
        {"collapses", r.cleanup.collapses},
        {"removed_faces", r.cleanup.removedFaces},
        {"flips", r.cleanup.flips},
        {"reverted", r.cleanup.reverted},
        {"remaining", r.cleanup.remaining},
        {"inherited", r.cleanup.inherited},
        {"part_way", r.cleanup.partWay}}},
      {"planar_folds",
       {{"folds", r.planarFolds.folds},
        {"patches", r.planarFolds.patches},
        {"relaxed_vertices", r.planarFolds.relaxedVertices}}},
      {"self_intersections",
       {{"intersecting_pairs", r.intersections.intersectingPairs},
        {"reverted", r.intersections.reverted},
        {"zone_reverted", r.intersections.zoneReverted},
        {"rounds", r.intersections.rounds},
        {"remaining", r.intersections.remaining}}},
  };
  if (r.extendedMethod)
    j["extended"] = {{"regions", r.extended.regions},
                     {"corridors", r.extended.corridors},
                     {"opened_contacts", r.extended.openedContacts},
                     {"kept_facets", r.extended.keptFacets},
                     {"planar_regions", r.extended.planarRegions},
                     {"opened_creases", r.extended.openedCreases},
                     {"zone_faces", r.extended.zoneFaces},
                     {"zone_vertices", r.extended.zoneVertices},
                     {"labelled_zone_vertices", r.extended.labelledZoneVertices},
                     {"projected_vertices", r.extended.projectedVertices},
                     {"projections_rejected", r.extended.projectionsRejected},
                     {"max_projection", r.extended.maxProjection},
                     {"sample_spacing", r.extended.sampleSpacing}};
  if (r.evidenceGuard) {
    nlohmann::json verdicts = nlohmann::json::object();
    for (int i = 0; i < kVerdictCount; ++i)
      verdicts[toString(static_cast<Verdict>(i))] = r.evidence.verdicts[i];
    j["evidence"] = {{"features", r.evidence.features},
                     {"weak_features", r.evidence.weakFeatures},
                     {"already_sharp_features", r.evidence.alreadySharpFeatures},
                     {"reverted", r.evidence.reverted},
                     {"zone_reverted", r.evidence.zoneReverted},
                     {"refused_fraction", r.evidence.refusedFraction},
                     {"refused_bound", r.evidence.refusedBound},
                     {"median_lift", r.evidence.medianLift},
                     {"noise_spacings", r.evidence.noiseSpacings},
                     {"planar_fraction", r.evidence.planarFraction},
                     {"exact_sampling", r.evidence.exactSampling},
                     {"whole_mesh_left", r.evidence.wholeMeshLeft},
                     {"flattened_vertices", r.evidence.flattenedVertices},
                     {"grown_planes", r.evidence.grownPlanes},
                     {"faces_given_back", r.evidence.facesGivenBack},
                     {"resting_vertices_removed", r.evidence.restingVerticesRemoved},
                     {"vertices_removed", r.evidence.verticesRemoved},
                     {"faces_removed", r.evidence.facesRemoved},
                     {"verdicts", verdicts},
                     {"cut_by_selection", r.evidence.cutBySelection}};
  }
  if (r.evidenceGuard) {
    nlohmann::json features = nlohmann::json::array();
    for (std::size_t c = 0; c < r.features.size(); ++c) {
      const FeatureRecord &f = r.features[c];
      features.push_back({{"id", c},
                          {"kind", f.corner ? "corner" : "edge"},
                          {"verdict", toString(f.verdict)},
                          {"new_vertices", f.newVertices},
                          {"width_spacings", f.widthSpacings},
                          {"flank_angle_deg", f.flankAngleRad * 180 / M_PI},
                          {"faces", f.faces}});
    }
    j["features"] = features;
  }
  j["summary"] = formatVerdictSummary(r);
  j["input_notes"] = formatInputNotes(r);
  return j;
}

}  // namespace edge_sharpener
