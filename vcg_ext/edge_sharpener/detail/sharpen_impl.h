// Implementation of the entry points declared in edge_sharpener.h: the
// stages run in order, each returning the counts that go into the report.
#pragma once

#include <vcg/complex/complex.h>

#include <optional>
#include <tuple>
#include <type_traits>
#include <vector>
// (vcglib's algorithm headers need complex.h first)
#include <vcg/complex/algorithms/update/normal.h>

#include "../cleanup.h"
#include "../colorize.h"
#include "../extended/plane_patches.h"
#include "../extended_method.h"
#include "../filters.h"
#include "../guards/feature_evidence.h"
#include "../guards/intersection_guard.h"
#include "../guards/planar_folds.h"
#include "../guards/vertex_moves.h"
#include "../option_table.h"
#include "../placement.h"
#include "../restored_edges.h"
#include "../smooth_edges.h"
#include "../subdivision.h"
#include "../util/fast_topology.h"
#include "../util/input_check.h"

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
/// filters, or the extended method's feature zones. Fills zones.support with
/// the support plane of every original vertex that places an inserted one
/// (and, for the extended method, the rest of `zones`).
template <class MeshType>
void detect(MeshType &m, MeshLabels<MeshType> &labels, const SharpenOptions &opt,
            SharpenReport &report, FeatureZones &zones) {
  reportProgress(opt, 5, "Edge-Sharpener: smooth edges");
  computeFaceNormals(m, labels);
  report.smooth = labelSmoothEdges(m, labels, opt.smoothMultiplier);
  if (usesFeatureZones(opt.method)) {
    reportProgress(opt, 20, "Edge-Sharpener: feature zones");
    detectFeatureZones(m, labels, opt, report, zones);
    return;
  }
  reportProgress(opt, 20, "Edge-Sharpener: six filters");
  report.filters = runSixFilters(m, labels);
  zones.support = paperSupportPlanes(m, labels);
}

template <class MeshType>
void requireColours(MeshType &m, const SharpenOptions &opt) {
  if (!opt.colorize) return;
  vcg::tri::RequirePerFaceColor(m);
  vcg::tri::RequirePerVertexColor(m);
}

/// The outcome of every inserted vertex, and the zone vertices still
/// projected, once every guard has run.
template <class MeshType>
void countOutcomes(const VertexMoves<MeshType> &moves, SharpenReport &report) {
  report.placement = moves.countOutcomes();
  if (report.extendedMethod) {
    const auto projected = moves.originalMoves();
    report.extended.projectedVertices = projected.count;
    report.extended.maxProjection = projected.longest;
  }
}

/// The output's normals, those of vcglib's UpdateNormal::PerFaceNormalized
/// and PerVertexNormalized (each vertex's faces' area-weighted normals summed
/// in face order, normalized), with each face's area normal computed once and
/// without vcglib's use of the vertices' visited flags. The faces' normals
/// and the normalization run on every core, the vertices' sums on one.
template <class MeshType>
void updateOutputNormals(MeshType &m) {
  const bool faceNormals = vcg::tri::HasPerFaceNormal(m);
  const bool vertexNormals = vcg::tri::HasPerVertexNormal(m);
  if (!faceNormals && !vertexNormals) return;
  using AreaNormal = std::decay_t<decltype(vcg::TriangleNormal(m.face[0]))>;
  using VertexNormal = typename MeshType::VertexType::NormalType;
  const std::int64_t nf = std::int64_t(m.face.size()), nv = std::int64_t(m.vert.size());
  std::vector<AreaNormal> areaNormal(vertexNormals ? m.face.size() : 0);
#pragma omp parallel for schedule(static, 8192) if (nf > kParallelMin)
  for (std::int64_t fi = 0; fi < nf; ++fi) {
    auto &f = m.face[fi];
    if (f.IsD()) continue;
    const AreaNormal n = vcg::TriangleNormal(f);
    if (vertexNormals) areaNormal[fi] = n;
    if (faceNormals) {
      f.N() = n;
      f.N().Normalize();
    }
  }
  if (!vertexNormals) return;
  const auto writable = [](const auto &v) { return !v.IsD() && v.IsRW(); };
  std::vector<char> reached(m.vert.size(), 0);
  for (std::int64_t fi = 0; fi < nf; ++fi) {
    auto &f = m.face[fi];
    if (f.IsD()) continue;
    const VertexNormal n = areaNormal[fi];
    for (int k = 0; k < 3; ++k) {
      auto &v = *f.V(k);
      char &first = reached[vcg::tri::Index(m, &v)];
      if (!first) {
        first = 1;
        if (writable(v)) v.N() = VertexNormal(0, 0, 0);
      }
      if (f.IsR() && writable(v)) v.N() += n;
    }
  }
#pragma omp parallel for schedule(static, 8192) if (nv > kParallelMin)
  for (std::int64_t vi = 0; vi < nv; ++vi)
    if (writable(m.vert[vi])) m.vert[vi].N().Normalize();
}

/// Colours (inspection only), the restored vertices (if asked for),
/// compact vectors, normals, output counts.
template <class MeshType>
void finish(MeshType &m, MeshLabels<MeshType> &labels, const SharpenOptions &opt,
            SharpenReport &report) {
  if (opt.colorize) colorize(m, labels);
  recordRestoredVertices(m, labels);
  vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
  updateOutputNormals(m);
  report.outputVertices = m.vert.size();
  report.outputFaces = m.face.size();
  reportProgress(opt, 100, "Edge-Sharpener: done");
}

/// Auto method, on a rough input (a fused scan: its noise above the smooth
/// bound) left whole: the vertices labelled with its planar regions onto
/// their planes, on the regions' faces, and the vertices bulged beyond a
/// convex edge or corner behind its planes (flattenPlanarRegions, within
/// kFlattenMaxSpacings). Where that moved a share of the vertices
/// (kGrownPlanesEvidence: the planes bulge as a fused scan's do; an exact
/// mesh's planes move none), the same again on planes grown face by face
/// (growPlanePatches), which the segmentation may have merged across a
/// rounded edge. \return the number of vertices moved and of planes grown.
template <class MeshType>
std::pair<std::size_t, std::size_t> flattenRoughPlanes(MeshType &m, const FeatureZones &zones,
                                                       const SurfaceMeasures &surface,
                                                       const SharpenOptions &opt) {
  if (!opt.flattenRoughPlanes || zones.support.regionPlanes.empty() ||
      !(surface.noiseSpacings > opt.maxSmoothNoiseSpacings))
    return {0, 0};
  const double spacing = spacingUnit(zones.support);
  const double minMove = kFlattenMinSpacings * spacing, maxMove = kFlattenMaxSpacings * spacing;
  const int outward = outwardSign(m);
  const VertexFaceTable vf(m);  // the flattening moves vertices only
  using Coord = typename MeshType::CoordType;
  std::vector<Coord> input(m.vert.size());
  for (std::size_t v = 0; v < m.vert.size(); ++v) input[v] = m.vert[v].cP();
  const std::size_t onRegions =
      flattenPlanarRegions(m, vf, zones, zones.support.regionPlanes, minMove, maxMove, outward);
  std::size_t grown = 0;
  if (double(onRegions) >= kGrownPlanesEvidence * double(m.vn)) {
    PlanePatchSettings settings;
    settings.maxTurnRad = settings.pairAngleRad = opt.minFeatureAngleRad;
    const PlanePatches patches = growPlanePatches(m, vf, spacing, settings);
    grown = patches.count();
    flattenPlanarRegions(m, vf, patches.labels, patches.planes, minMove, maxMove, outward);
  }
  std::size_t moved = 0;
  for (std::size_t v = 0; v < m.vert.size(); ++v) moved += !(m.vert[v].cP() == input[v]);
  return {moved, grown};
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
  detail::requireColours(m, opt);
  SharpenReport report = detail::validate(m, opt);
  report.geometryChanged = true;
  MeshLabels<MeshType> labels(m);
  FeatureZones zones;
  detail::detect(m, labels, opt, report, zones);

  detail::reportProgress(opt, 40, "Edge-Sharpener: subdivision");
  std::optional<InputFaces<MeshType>> input;  // the auto method may give it back whole
  SurfaceMeasures surface;
  if (opt.method == Method::Auto) {
    input.emplace(m);
    surface = measureSurface(m, zones.inputFaces, zones.faceRegion, zones.support.sampleSpacing);
  }
  const SplitPlan plan = planSplits(m, labels);
  report.subdivision = subdivide(m, plan, labels);
  VertexMoves<MeshType> moves(m, plan, labels, usesFeatureZones(opt.method));

  detail::reportProgress(opt, 60, "Edge-Sharpener: vertex placement");
  placeInsertedVertices(m, plan, labels, report.longestInputEdge, opt, zones.support);
  if (usesFeatureZones(opt.method)) refineExtendedPlacement(m, moves, zones, opt, report);
  std::optional<EvidenceGuard<MeshType>> evidence;
  if (input) {
    evidence.emplace(m, moves, zones.support, InputSurface{zones.inputFaces, input->faceVertices()},
                     surface, report.longestInputEdge, opt);
    report.evidenceGuard = true;
    report.evidence = evidence->revertWeakFeatures();
  }

  detail::reportProgress(opt, 80, "Edge-Sharpener: degenerate cleanup");
  std::optional<ElementSnapshot<MeshType>> beforeGuards;
  if (input) beforeGuards.emplace(m, labels);
  report.cleanup = removeDegenerateTriangles(m, moves, opt.degenerateAngleRad,
                                             /*onlyWhereMoved=*/input.has_value());
  if (input)
    report.planarFolds = unfoldPlanarPatches(
        m, [&](std::size_t v) { return !moves.isAtRest(v); },
        kFoldPlaneSpacings * spacingUnit(zones.support), opt.degenerateAngleRad);
  report.intersections =
      revertSelfIntersections(m, moves, opt.degenerateAngleRad, report.longestInputEdge,
                              evidence ? &evidence->retreatFirst() : nullptr);
  if (evidence && evidence->leaveMeshIfGuardsRefused(*beforeGuards, report.evidence)) {
    report.cleanup = {};  // undone
    report.intersections = {};
  }
  detail::countOutcomes(moves, report);
  if (input) {
    const int verticesBefore = m.vn, facesBefore = m.fn;
    report.evidence.facesGivenBack = input->unsplitResting(m, moves);
    report.evidence.restingVerticesRemoved =
        InputFaces<MeshType>::dissolveRestingEdgeVertices(m, moves);
    report.evidence.verticesRemoved = std::size_t(verticesBefore - m.vn);
    report.evidence.facesRemoved = std::size_t(facesBefore - m.fn);
    if (report.evidence.wholeMeshLeft)
      std::tie(report.evidence.flattenedVertices, report.evidence.grownPlanes) =
          detail::flattenRoughPlanes(m, zones, surface, opt);
  }
  detail::finish(m, labels, opt, report);
  return report;
}

}  // namespace edge_sharpener
