// mesh-distance: the project's Metro. Two-sided surface distance between mesh A and the
// reference mesh B, absolute and as a percentage of B's bounding-box diagonal.
//
//   mesh-distance A B [--samples N] [--seed S] [--sampling uniform|meshlab] [--json]
//   [--no-vertex-samples] [--no-edge-samples]
//                     [--color-out FILE.ply [--color-max D | --color-max-percent P]]
//                     [--fidelity [--fidelity-samples N] [--fidelity-seed S]]
// --fidelity adds Neural Dual Contouring's feature-fidelity measures (NC, ECD, EF1; see
// featureFidelity() in mesh_distance.h) after the table, and as "fidelity" in the JSON.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "edge_sharpener/util/mesh_types.h"
#include "mesh_distance.h"
#include "mesh_io.h"
// (vcglib's algorithm headers need complex.h, included above, first)
#include <vcg/complex/algorithms/closest.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/space/index/grid_static_ptr.h>

namespace es = edge_sharpener;

namespace {

/// Loads a mesh the distance can be measured on: at least one face, finite coordinates.
void loadMeasurableMesh(const std::string &path, es::Mesh &mesh) {
  es::io::loadMesh(path, mesh);
  if (mesh.fn == 0) throw std::runtime_error(path + ": mesh has no faces");
  for (const auto &v : mesh.vert)
    if (!v.IsD() &&
        !(std::isfinite(v.cP().X()) && std::isfinite(v.cP().Y()) && std::isfinite(v.cP().Z())))
      throw std::runtime_error(path + ": mesh has NaN or infinite vertex coordinates");
}

nlohmann::json oneSidedJson(const es::OneSidedDistance &d, const es::DistanceReport &report) {
  return {{"min", d.min},
          {"max", d.max},
          {"mean", d.mean},
          {"rms", d.rms},
          {"samples", d.samples},
          {"min_percent", report.percentOfDiagonal(d.min)},
          {"max_percent", report.percentOfDiagonal(d.max)},
          {"mean_percent", report.percentOfDiagonal(d.mean)},
          {"rms_percent", report.percentOfDiagonal(d.rms)}};
}

nlohmann::json meshJson(const std::string &path, const es::Mesh &mesh) {
  return {{"path", path}, {"vertices", mesh.vn}, {"faces", mesh.fn}};
}

/// Metro's error colouring: every vertex of `a` gets its distance to `b`'s surface as
/// quality and a blue (0) -> red (`colorMax` or more) colour, every face the largest
/// distance found at its corners, edge midpoints and barycentre; written to `path` (PLY).
/// Returns the largest vertex distance.
double writeErrorColoring(es::Mesh &a, es::Mesh &b, double colorMax, const std::string &path) {
  using Grid = vcg::GridStaticPtr<es::Mesh::FaceType, es::Mesh::ScalarType>;
  vcg::tri::UpdateNormal<es::Mesh>::PerFaceNormalized(b);
  Grid grid;
  grid.Set(b.face.begin(), b.face.end(), es::closestFaceGridBox(b, a));
  vcg::Box3<es::Mesh::ScalarType> both = a.bbox;
  both.Add(b.bbox);
  const es::Mesh::ScalarType searchRadius = 2 * both.Diag() + 1e-30f;
  double largest = 0;
  for (auto &v : a.vert) {
    if (v.IsD()) continue;
    es::Mesh::ScalarType dist = searchRadius;
    es::Mesh::CoordType closest;
    const auto *f = vcg::tri::GetClosestFaceBase(b, grid, v.cP(), searchRadius, dist, closest);
    const double d = f ? dist : searchRadius;
    largest = std::max(largest, d);
    v.Q() = static_cast<float>(d);
    v.C() = vcg::Color4b::ColorRamp(static_cast<float>(colorMax), 0.0f, static_cast<float>(d));
  }
  // Faces: the largest distance at the barycentre and the edge midpoints, where a
  // chamfer is farthest from the true surface (its vertices lie on it).
  for (auto &f : a.face) {
    if (f.IsD()) continue;
    const es::Mesh::CoordType points[4] = {(f.cP(0) + f.cP(1) + f.cP(2)) / 3,
                                           (f.cP(0) + f.cP(1)) / 2, (f.cP(1) + f.cP(2)) / 2,
                                           (f.cP(2) + f.cP(0)) / 2};
    double worst = 0;
    for (const auto &p : points) {
      es::Mesh::ScalarType dist = searchRadius;
      es::Mesh::CoordType closest;
      const auto *g = vcg::tri::GetClosestFaceBase(b, grid, p, searchRadius, dist, closest);
      worst = std::max(worst, g ? static_cast<double>(dist) : static_cast<double>(searchRadius));
    }
    for (int i = 0; i < 3; ++i) worst = std::max(worst, static_cast<double>(f.cV(i)->cQ()));
    f.Q() = static_cast<float>(worst);
    f.C() = vcg::Color4b::ColorRamp(static_cast<float>(colorMax), 0.0f, static_cast<float>(worst));
  }
  namespace mask = vcg::tri::io;
  es::io::saveMesh(a, path,
                   mask::Mask::IOM_VERTCOLOR | mask::Mask::IOM_VERTQUALITY |
                       mask::Mask::IOM_FACECOLOR | mask::Mask::IOM_FACEQUALITY);
  return largest;
}

nlohmann::json finiteOrNull(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json fidelityJson(const es::FeatureFidelity &f, const es::FidelityOptions &options) {
  return {{"unit", "reference_diagonal"},
          {"reference_diagonal", f.referenceDiagonal},
          {"samples", f.samples},
          {"seed", f.seed},
          {"edge_radius", options.edgeRadius},
          {"edge_max_abs_dot", options.edgeMaxAbsDot},
          {"edge_f1_threshold", options.edgeF1Threshold},
          {"nc", f.nc},
          {"nc_forward", f.ncForward},
          {"nc_backward", f.ncBackward},
          {"edge_points_a", f.edgePointsA},
          {"edge_points_b", f.edgePointsReference},
          {"ecd", finiteOrNull(f.ecd)},
          {"ecd_forward", finiteOrNull(f.ecdForward)},
          {"ecd_backward", finiteOrNull(f.ecdBackward)},
          {"ecd_mean_distance", finiteOrNull(f.ecdMeanDistance)},
          {"edge_precision", f.edgePrecision},
          {"edge_recall", f.edgeRecall},
          {"ef1", f.ef1}};
}

void printFidelity(const es::FeatureFidelity &f, const es::FidelityOptions &options) {
  std::printf(
      "feature fidelity (Neural Dual Contouring's measures; both meshes scaled by 1/B's "
      "diagonal, %zu samples per mesh, seed %u):\n",
      f.samples, f.seed);
  std::printf("  NC  normal consistency      %10.6f  (A->B %.6f, B->A %.6f)\n", f.nc, f.ncForward,
              f.ncBackward);
  std::printf("  edge points                 A %zu, B %zu  (|n.n'| < %g within %g)\n",
              f.edgePointsA, f.edgePointsReference, options.edgeMaxAbsDot, options.edgeRadius);
  std::printf(
      "  ECD edge chamfer distance   %10.4g  (sum of both directions' mean squared distances; "
      "mean distance %.4g)\n",
      f.ecd, f.ecdMeanDistance);
  std::printf("  EF1 edge F1 at %-12g %10.6f  (precision %.6f, recall %.6f)\n",
              options.edgeF1Threshold, f.ef1, f.edgePrecision, f.edgeRecall);
}

void printRow(const char *label, double min, double max, double mean, double rms,
              const std::string &samples, const es::DistanceReport &report) {
  std::printf("%-16s %12.6g %12.6g %12.6g %12.6g %10s\n", label, min, max, mean, rms,
              samples.c_str());
  std::printf("%-16s %11.4f%% %11.4f%% %11.4f%% %11.4f%%\n", "  (% diagonal)",
              report.percentOfDiagonal(min), report.percentOfDiagonal(max),
              report.percentOfDiagonal(mean), report.percentOfDiagonal(rms));
}

}  // namespace

int main(int argc, char **argv) {
  CLI::App app{
      "Two-sided distance between mesh A and reference mesh B (Metro-style: vertices, edges "
      "and faces sampled), absolute and in % of B's bounding-box diagonal."};
  std::string pathA, pathB;
  es::DistanceOptions options;
  bool json = false;
  std::string colorOut;
  double colorMax = -1, colorMaxPercent = -1;
  app.add_option("A", pathA, "Measured mesh (PLY, OFF, OBJ, STL)")->required();
  app.add_option("B", pathB, "Reference mesh (PLY, OFF, OBJ, STL)")->required();
  app.add_option("--samples", options.faceSamples,
                 "Face samples per side, spread by area (edges get a quarter as many)")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{1}, std::size_t{1000000000}));
  auto *seedOption = app.add_option(
      "--seed", options.seed,
      "Seed of the sampling generator (default 1; with --sampling meshlab, 5489: where a fresh "
      "MeshLab's generator starts, so that the figures are MeshLab's own)");
  std::string sampling = "uniform";
  app.add_option("--sampling", sampling,
                 "How samples are spread on each side. uniform: every vertex, N/4 points along "
                 "the edges, N face points by stratified subdivision. meshlab: as MeshLab's "
                 "\"Hausdorff Distance\" filter (vertices, edges and faces sampled): N vertices "
                 "(all when N >= their count), N points along the edges, N Montecarlo face points")
      ->capture_default_str()
      ->check(CLI::IsMember({"uniform", "meshlab"}));
  app.add_flag("--json", json, "Print the result as JSON");
  bool noVertices = false, noEdges = false;
  app.add_flag("--no-vertex-samples", noVertices, "Do not sample the meshes' vertices");
  app.add_flag("--no-edge-samples", noEdges, "Do not sample points along the meshes' edges");
  auto *colorOpt = app.add_option(
      "--color-out", colorOut,
      "Write A as a PLY whose vertices carry their distance to B (quality) and Metro's error "
      "colour: blue = 0, red = the colour scale's maximum or more");
  app.add_option("--color-max", colorMax,
                 "Colour scale maximum, absolute (default: the symmetric Hausdorff distance)")
      ->needs(colorOpt)
      ->check(CLI::PositiveNumber);
  app.add_option("--color-max-percent", colorMaxPercent,
                 "Colour scale maximum in % of B's bounding-box diagonal")
      ->needs(colorOpt)
      ->excludes("--color-max")
      ->check(CLI::PositiveNumber);
  bool fidelity = false;
  es::FidelityOptions fidelityOptions;
  auto *fidelityFlag = app.add_flag(
      "--fidelity", fidelity,
      "Also measure Neural Dual Contouring's feature fidelity: both meshes scaled by 1/B's "
      "bounding-box diagonal (after moving B's box minimum to the origin), N area-uniform "
      "samples on each; NC = normal consistency (mean |n.n'| with the nearest sample of the "
      "other mesh, both directions averaged); edge points = samples with a sample of the same "
      "mesh within 0.004 whose |n.n'| < 0.2; ECD = edge chamfer distance, NDC's: the sum of both "
      "directions' mean squared nearest-edge-point distances; EF1 = edge F1 at 0.005 "
      "(precision: A's edge points matched; recall: B's). No edge point on either mesh: ECD 0, "
      "EF1 1; on one only: ECD infinite (JSON null), EF1 0");
  app.add_option("--fidelity-samples", fidelityOptions.samples,
                 "Samples per mesh for --fidelity (NDC: 100000)")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{1}, std::size_t{10000000}))
      ->needs(fidelityFlag);
  app.add_option("--fidelity-seed", fidelityOptions.seed,
                 "Seed of the --fidelity sampling: B is sampled with it, A with seed + 1")
      ->capture_default_str()
      ->needs(fidelityFlag);
  CLI11_PARSE(app, argc, argv);
  options.sampleVertices = !noVertices;
  options.sampleEdges = !noEdges;
  options.sampling =
      sampling == "meshlab" ? es::DistanceSampling::meshlab : es::DistanceSampling::uniform;
  if (options.sampling == es::DistanceSampling::meshlab && seedOption->count() == 0)
    options.seed = es::kMeshLabSeed;

  try {
    es::Mesh a, b;
    loadMeasurableMesh(pathA, a);
    loadMeasurableMesh(pathB, b);
    const es::DistanceReport report = es::measureDistance(a, b, options);
    const es::OneSidedDistance &f = report.forward;
    const es::OneSidedDistance &r = report.backward;
    double colorScale = 0, largestVertexDistance = 0;
    if (!colorOut.empty()) {
      if (es::io::lowerExtension(colorOut) != "ply")
        throw std::runtime_error(colorOut + ": --color-out writes PLY (colour and quality)");
      colorScale = colorMax > 0          ? colorMax
                   : colorMaxPercent > 0 ? colorMaxPercent * report.referenceDiagonal / 100.0
                                         : report.max();
      if (!(colorScale > 0)) colorScale = 1e-30;
      largestVertexDistance = writeErrorColoring(a, b, colorScale, colorOut);
    }
    es::FeatureFidelity fidelityReport;
    if (fidelity) fidelityReport = es::featureFidelity(a, b, fidelityOptions);

    if (json) {
      nlohmann::json out = {{"a", meshJson(pathA, a)},
                            {"b", meshJson(pathB, b)},
                            {"reference_diagonal", report.referenceDiagonal},
                            {"sampling", es::distanceSamplingName(options.sampling)},
                            {"face_samples", options.faceSamples},
                            {"seed", options.seed},
                            {"sampled",
                             {{"vertices", options.sampleVertices},
                              {"edges", options.sampleEdges},
                              {"faces", options.sampleFaces}}},
                            {"forward", oneSidedJson(f, report)},
                            {"backward", oneSidedJson(r, report)},
                            {"symmetric",
                             {{"max", report.max()},
                              {"mean", report.mean()},
                              {"rms", report.rms()},
                              {"max_percent", report.maxPercent()},
                              {"mean_percent", report.meanPercent()},
                              {"rms_percent", report.rmsPercent()}}}};
      if (!colorOut.empty())
        out["color_out"] = {{"path", colorOut},
                            {"color_max", colorScale},
                            {"max_vertex_distance", largestVertexDistance}};
      if (fidelity) out["fidelity"] = fidelityJson(fidelityReport, fidelityOptions);
      std::printf("%s\n", out.dump(2).c_str());
      return 0;
    }
    std::printf("A: %s (%d vertices, %d faces)\n", pathA.c_str(), a.vn, a.fn);
    std::printf("B: %s (%d vertices, %d faces), reference diagonal %.6g\n", pathB.c_str(), b.vn,
                b.fn, report.referenceDiagonal);
    std::printf("sampling: %s, %zu samples per kind\n", es::distanceSamplingName(options.sampling),
                options.faceSamples);
    std::printf("%-16s %12s %12s %12s %12s %10s\n", "", "min", "max", "mean", "RMS", "samples");
    printRow("forward  A->B", f.min, f.max, f.mean, f.rms, std::to_string(f.samples), report);
    printRow("backward B->A", r.min, r.max, r.mean, r.rms, std::to_string(r.samples), report);
    printRow("symmetric", std::min(f.min, r.min), report.max(), report.mean(), report.rms(),
             std::to_string(f.samples + r.samples), report);
    if (!colorOut.empty())
      std::printf("error colouring of A (blue 0 -> red %.6g) written to %s\n", colorScale,
                  colorOut.c_str());
    if (fidelity) printFidelity(fidelityReport, fidelityOptions);
  } catch (const std::exception &error) {
    std::fprintf(stderr, "mesh-distance: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
