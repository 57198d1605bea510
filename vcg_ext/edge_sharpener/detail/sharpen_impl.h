// Implementation of the entry points declared in edge_sharpener.h: the
// stages run in order, each returning the counts that go into the report.
#pragma once

#include <vcg/complex/complex.h>

#include <optional>
#include <type_traits>
#include <vector>
// (vcglib's algorithm headers need complex.h first)
#include <vcg/complex/algorithms/update/normal.h>

#include "../auto_method.h"
#include "../cleanup.h"
#include "../colorize.h"
#include "../extended_method.h"
#include "../filters.h"
#include "../guards/intersection_guard.h"
#include "../guards/vertex_moves.h"
#include "../held_faces.h"
#include "../option_table.h"
#include "../placement.h"
#include "../restored_edges.h"
#include "../smooth_edges.h"
#include "../subdivision.h"
#include "../util/fast_topology.h"
#include "../util/input_check.h"
#include "../util/mesh_types.h"
#include "../util/non_manifold.h"
#include "../util/part_scales.h"

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

/// The paper's detection: the smooth-edge test, then the six filters; the
/// support plane of every original vertex that places an inserted one.
template <class MeshType>
SupportPlanes detectByFilters(MeshType &m, MeshLabels<MeshType> &labels, const SharpenOptions &opt,
                              SharpenReport &report) {
  reportProgress(opt, 5, "Edge-Sharpener: smooth edges");
  computeFaceNormals(m, labels);
  report.smooth = labelSmoothEdges(m, labels, opt.smoothMultiplier);
  reportProgress(opt, 20, "Edge-Sharpener: six filters");
  report.filters = runSixFilters(m, labels);
  return paperSupportPlanes(m, labels);
}

/// The extended method's detection: the smooth-edge test, then the feature
/// zones between segmented smooth regions (support planes included).
template <class MeshType>
FeatureZones detectByZones(MeshType &m, MeshLabels<MeshType> &labels, const SharpenOptions &opt,
                           SharpenReport &report) {
  reportProgress(opt, 5, "Edge-Sharpener: smooth edges");
  computeFaceNormals(m, labels);
  report.smooth = labelSmoothEdges(m, labels, opt.smoothMultiplier);
  reportProgress(opt, 20, "Edge-Sharpener: feature zones");
  FeatureZones zones;
  detectFeatureZones(m, labels, opt, report, zones);
  return zones;
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

/// Colours (inspection only: by `faceVerdicts` where the auto method gives
/// them and the verdict scheme is asked for, else the paper's labels), the
/// restored vertices (if asked for), compact vectors, normals, output counts.
template <class MeshType>
void finish(MeshType &m, MeshLabels<MeshType> &labels, const SharpenOptions &opt,
            SharpenReport &report, const FaceVerdicts *faceVerdicts = nullptr) {
  if (opt.colorize && faceVerdicts && opt.colors == ColorScheme::Verdict)
    paintVerdicts(m, *faceVerdicts);
  else if (opt.colorize)
    colorize(m, labels);
  recordRestoredVertices(m, labels);
  vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
  updateOutputNormals(m);
  report.outputVertices = m.vert.size();
  report.outputFaces = m.face.size();
  reportProgress(opt, 100, "Edge-Sharpener: done");
}

/// Checks the mesh and the options (InputError otherwise, the mesh
/// untouched); the report's input counts. `nonManifold` tells whether the
/// mesh has non-manifold spots (held as they came: asPeopleHaveIt).
template <class MeshType>
SharpenReport validate(MeshType &m, const SharpenOptions &opt, bool *nonManifold = nullptr) {
  vcg::tri::RequireFFAdjacency(m);
  vcg::tri::RequireCompactness(m);
  if (std::string problem = findOptionProblem(opt); !problem.empty()) throw InputError(problem);
  const std::string problem = findInputProblem(m, nonManifold);
  if (!problem.empty()) throw InputError(problem);
  SharpenReport report;
  report.inputVertices = m.vert.size();
  report.inputFaces = m.face.size();
  report.longestInputEdge = longestEdgeLength(m);
  for (const auto &f : m.face)  // FF topology as findInputProblem() built it
    for (int i = 0; i < 3; ++i) report.inputBorderEdges += f.cFFp(i) == &f;
  return report;
}

/// SharpenOptions::selectedFacesOnly: per face, whether it lies outside the
/// selection (vcglib's face selection flag), and the count selected into
/// `report` (empty without the option).
template <class MeshType>
std::vector<char> unselectedFaces(const MeshType &m, const SharpenOptions &opt,
                                  SharpenReport &report) {
  if (!opt.selectedFacesOnly) return {};
  report.selectedFacesOnly = true;
  std::vector<char> unselected(m.face.size(), 0);
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    unselected[f] = !m.face[f].IsS();
    report.selectedFaces += !unselected[f];
  }
  return unselected;
}

/// The faces the pipeline holds and those outside the selection. The auto
/// method judges the selection per feature (featureVerdicts); the paper and
/// extended methods, which judge none, hold every face outside it.
template <class MeshType>
HeldFaces heldWithSelection(const MeshType &m, HeldFaces held, std::vector<char> unselected,
                            Method method) {
  if (unselected.empty()) return held;
  if (method != Method::Auto) {
    held.face.resize(m.face.size(), 0);
    held.vertex.resize(m.vert.size(), 0);
    for (std::size_t f = 0; f < m.face.size(); ++f) {
      if (!unselected[f]) continue;
      held.face[f] = 1;
      for (int i = 0; i < 3; ++i) held.vertex[vcg::tri::Index(m, m.face[f].cV(i))] = 1;
    }
  }
  held.unselected = std::move(unselected);
  return held;
}

/// Runs `pipeline(held, report)` on `m`: the mesh as people have it made one
/// the pipelines take, and put back after. A mesh with non-manifold spots is
/// cut loose there first (NonManifoldCut): the pipeline sees a 2-manifold
/// mesh whose faces at the spots are held; afterwards they are welded back,
/// so the output has the input's non-manifold vertices and edges. Parts
/// sampled at different spacings are each brought to one (PartScales). With
/// SharpenOptions::selectedFacesOnly, the faces outside the selection go to
/// the pipeline too (heldWithSelection); none selected: nothing runs.
template <class MeshType, class Pipeline>
SharpenReport asPeopleHaveIt(MeshType &m, const SharpenOptions &opt, Pipeline &&pipeline) {
  bool nonManifold = false;
  SharpenReport report = validate(m, opt, &nonManifold);
  std::vector<char> unselected = unselectedFaces(m, opt, report);
  if (report.selectedFacesOnly && report.selectedFaces == 0) {
    report.outputVertices = m.vert.size();
    report.outputFaces = m.face.size();
    return report;
  }
  std::optional<NonManifoldCut<MeshType>> cut;
  if (nonManifold) {
    cut.emplace(m);
    if (!cut->manifold()) {
      cut->weld();
      throw InputError(
          "mesh has non-manifold spots too tangled to hold apart; repair them first (MeshLab: "
          "Repair non Manifold Edges, then Vertices)");
    }
  }
  PartScales<MeshType> parts(m);
  if (!cut && parts.rescaled() == 0)
    return pipeline(heldWithSelection(m, HeldFaces{}, std::move(unselected), opt.method), report);
  const std::size_t borderEdges = report.inputBorderEdges;
  const double longestEdge = report.longestInputEdge;
  if (parts.rescaled() > 0) report.longestInputEdge = longestEdgeLength(m);  // as the run sees it
  report = pipeline(
      heldWithSelection(m, cut ? cut->held() : HeldFaces{}, std::move(unselected), opt.method),
      report);
  report.longestInputEdge = longestEdge;
  parts.restore();
  if (cut) {
    cut->weld();
    report.nonManifold = cut->stats();
  }
  report.inputBorderEdges = borderEdges;
  report.parts = parts.parts();
  report.partsRescaled = parts.rescaled();
  if (report.geometryChanged) updateOutputNormals(m);
  report.outputVertices = m.vert.size();
  report.outputFaces = m.face.size();
  return report;
}

/// The paper's and the extended method's guards (the degenerate cleanup, the
/// intersection guard), then the outcomes counted and the output finished.
template <class MeshType>
void guardAndFinish(MeshType &m, VertexMoves<MeshType> &moves, MeshLabels<MeshType> &labels,
                    const SharpenOptions &opt, SharpenReport &report) {
  reportProgress(opt, 80, "Edge-Sharpener: degenerate cleanup");
  report.cleanup = removeDegenerateTriangles(m, moves, opt.degenerateAngleRad);
  report.intersections =
      revertSelfIntersections(m, moves, opt.degenerateAngleRad, report.longestInputEdge);
  countOutcomes(moves, report);
  finish(m, labels, opt, report);
}

/// The paper's method (section 3): six filters, split, place, clean up.
template <class MeshType>
SharpenReport sharpenPaper(MeshType &m, const SharpenOptions &opt, const HeldFaces &held,
                           SharpenReport report) {
  report.geometryChanged = true;
  MeshLabels<MeshType> labels(m);
  const SupportPlanes support = detectByFilters(m, labels, opt, report);
  holdFaces(m, labels, held, report.filters);
  reportProgress(opt, 40, "Edge-Sharpener: subdivision");
  const SplitPlan plan = planSplits(m, labels);
  report.subdivision = subdivide(m, plan, labels);
  VertexMoves<MeshType> moves(m, plan, labels, /*originalsMayMove=*/false);
  reportProgress(opt, 60, "Edge-Sharpener: vertex placement");
  placeInsertedVertices(m, plan, labels, report.longestInputEdge, opt,
                        PlacementPolicy::paperMethod(opt), support);
  guardAndFinish(m, moves, labels, opt, report);
  return report;
}

/// The extended method: feature zones of any width, their vertices projected
/// onto their regions' planes beside the restored edges.
template <class MeshType>
SharpenReport sharpenExtended(MeshType &m, const SharpenOptions &opt, const HeldFaces &held,
                              SharpenReport report) {
  report.geometryChanged = true;
  MeshLabels<MeshType> labels(m);
  const FeatureZones zones = detectByZones(m, labels, opt, report);
  holdFaces(m, labels, held, report.filters);
  reportProgress(opt, 40, "Edge-Sharpener: subdivision");
  const SplitPlan plan = planSplits(m, labels);
  report.subdivision = subdivide(m, plan, labels);
  VertexMoves<MeshType> moves(m, plan, labels, /*originalsMayMove=*/true);
  reportProgress(opt, 60, "Edge-Sharpener: vertex placement");
  placeInsertedVertices(m, plan, labels, report.longestInputEdge, opt,
                        PlacementPolicy::extendedMethod(opt), zones.support);
  refineExtendedPlacement(m, moves, zones, opt, report);
  sendBackHeldVertices(moves, held);
  guardAndFinish(m, moves, labels, opt, report);
  return report;
}

/// The auto method: the extended method, each feature restored only on
/// strong evidence (auto_method.h; its rules: rulebook.h).
template <class MeshType>
SharpenReport sharpenAuto(MeshType &m, const SharpenOptions &opt, const HeldFaces &held,
                          SharpenReport report) {
  report.geometryChanged = true;
  MeshLabels<MeshType> labels(m);
  const FeatureZones zones = detectByZones(m, labels, opt, report);
  holdFaces(m, labels, held, report.filters);
  reportProgress(opt, 40, "Edge-Sharpener: subdivision");
  AutoMethod<MeshType> autoMethod(m, zones, opt, held);
  const SplitPlan plan = planSplits(m, labels);
  report.subdivision = subdivide(m, plan, labels);
  VertexMoves<MeshType> moves(m, plan, labels, /*originalsMayMove=*/true);
  reportProgress(opt, 60, "Edge-Sharpener: vertex placement");
  placeInsertedVertices(m, plan, labels, report.longestInputEdge, opt,
                        PlacementPolicy::autoMethod(opt), zones.support);
  refineExtendedPlacement(m, moves, zones, opt, report);
  sendBackHeldVertices(moves, held);
  autoMethod.judgeFeatures(moves, report.longestInputEdge);
  reportProgress(opt, 80, "Edge-Sharpener: degenerate cleanup");
  const GuardStats guards = autoMethod.runGuards(moves, labels, report.longestInputEdge);
  report.cleanup = guards.cleanup;
  report.planarFolds = guards.planarFolds;
  report.intersections = guards.intersections;
  countOutcomes(moves, report);
  autoMethod.giveBackResting(moves);
  report.evidenceGuard = true;
  report.evidence = autoMethod.stats();
  report.features = autoMethod.featureRecords();
  const FaceVerdicts faceVerdicts =
      opt.colorize ? autoMethod.outputFaceVerdicts(report.features, report.inputFaces)
                   : FaceVerdicts{};
  finish(m, labels, opt, report, &faceVerdicts);
  return report;
}

}  // namespace detail

namespace detail {

/// The paper's and the extended method's Detect: their labels painted with
/// the paper's palette; selected, the faces they may change (the paper's
/// chamfer and corner triangles, the extended method's feature zones).
template <class MeshType>
SharpenReport detectByLabels(MeshType &m, const SharpenOptions &opt) {
  return asPeopleHaveIt(m, opt, [&](const HeldFaces &held, SharpenReport report) {
    MeshLabels<MeshType> labels(m);
    std::vector<int> faceRegion;  // the zone methods': kZone on the faces they may change
    if (opt.method == Method::Paper)
      detectByFilters(m, labels, opt, report);
    else
      faceRegion = detectByZones(m, labels, opt, report).faceRegion;
    holdFaces(m, labels, held, report.filters);
    colorize(m, labels);
    report.detectedFaces =
        faceRegion.empty() ? selectChamferFaces(m, labels) : selectZoneFaces(m, faceRegion, held);
    report.outputVertices = m.vert.size();
    report.outputFaces = m.face.size();
    reportProgress(opt, 100, "Edge-Sharpener: done");
    return report;
  });
}

/// The mesh layout the command-line tools use, in MeshType's scalar: the
/// copy Detect runs the auto method on.
template <class MeshType>
using WorkMeshOf =
    std::conditional_t<std::is_same_v<typename MeshType::ScalarType, double>, MeshD, Mesh>;

/// A copy of m's positions and faces, in m's order. \pre m compact.
template <class MeshType, class WorkMesh>
void copyPositionsAndFaces(const MeshType &m, WorkMesh &work) {
  using Coord = typename WorkMesh::CoordType;
  vcg::tri::Allocator<WorkMesh>::AddVertices(work, m.vert.size());
  for (std::size_t v = 0; v < m.vert.size(); ++v)
    work.vert[v].P() = Coord::Construct(m.vert[v].cP());
  vcg::tri::Allocator<WorkMesh>::AddFaces(work, m.face.size());
  for (std::size_t f = 0; f < m.face.size(); ++f)
    for (int j = 0; j < 3; ++j) work.face[f].V(j) = &work.vert[vcg::tri::Index(m, m.face[f].cV(j))];
}

/// The default's Detect: the auto method runs on a copy, and `m` shows what
/// it did. Its faces are painted by verdict (or the paper's labels, as the
/// extended method's Detect paints them), and selected where Sharpen
/// changes them: the faces of the features it restores or finds already
/// sharp (whose moves off the input it keeps), and every face of an input
/// vertex it moves. So Sharpen with that selection does what Sharpen does
/// without one, and deselecting a feature's faces leaves it as it came.
template <class MeshType>
SharpenReport detectByDefault(MeshType &m, const SharpenOptions &opt) {
  using WorkCoord = typename WorkMeshOf<MeshType>::CoordType;
  validate(m, opt);  // an InputError before anything is copied
  WorkMeshOf<MeshType> work;
  copyPositionsAndFaces(m, work);
  SharpenOptions workOpt = opt;
  workOpt.colorize = false;
  SharpenReport report = sharpen(work, workOpt);
  const FaceVerdicts verdicts = featureFaceVerdicts(report.features, m.face.size());
  std::vector<char> moved(m.vert.size(), 0);
  for (std::size_t v = 0; v < m.vert.size(); ++v)  // input vertices keep their index
    moved[v] = work.vert[v].cP() != WorkCoord::Construct(m.vert[v].cP());
  if (opt.colors == ColorScheme::Verdict)
    paintVerdicts(m, verdicts);
  else
    detectByLabels(m, opt);  // paints the paper's labels; its selection is replaced below
  report.detectedFaces = 0;
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    auto &face = m.face[f];
    bool changed = verdicts[f] == std::int8_t(Verdict::Restored) ||
                   verdicts[f] == std::int8_t(Verdict::AlreadySharp);
    for (int j = 0; j < 3; ++j) changed = changed || moved[vcg::tri::Index(m, face.cV(j))];
    changed ? face.SetS() : face.ClearS();
    report.detectedFaces += changed;
  }
  report.geometryChanged = false;
  report.outputVertices = m.vert.size();
  report.outputFaces = m.face.size();
  return report;
}

}  // namespace detail

template <class MeshType>
SharpenReport detectChamfers(MeshType &m, const SharpenOptions &options) {
  SharpenOptions opt = options;
  opt.selectedFacesOnly = false;  // detection looks at the whole mesh, and selects
  if (opt.method == Method::Auto) return detail::detectByDefault(m, opt);
  return detail::detectByLabels(m, opt);
}

template <class MeshType>
SharpenReport sharpen(MeshType &m, const SharpenOptions &opt) {
  detail::requireColours(m, opt);
  const auto pipeline = opt.method == Method::Paper      ? detail::sharpenPaper<MeshType>
                        : opt.method == Method::Extended ? detail::sharpenExtended<MeshType>
                                                         : detail::sharpenAuto<MeshType>;
  return detail::asPeopleHaveIt(m, opt, [&](const HeldFaces &held, SharpenReport report) {
    return pipeline(m, opt, held, std::move(report));
  });
}

}  // namespace edge_sharpener
