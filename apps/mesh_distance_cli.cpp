// mesh-distance: the project's Metro. Two-sided surface distance between mesh A and the
// reference mesh B, absolute and as a percentage of B's bounding-box diagonal.
//
//   mesh-distance A B [--samples N] [--seed S] [--json]
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "edge_sharpener/mesh_distance.h"
#include "edge_sharpener/mesh_types.h"
#include "mesh_io.h"

namespace es = edge_sharpener;

namespace {

/// Loads a mesh the distance can be measured on: at least one face, finite coordinates.
void loadMeasurableMesh(const std::string& path, es::Mesh& mesh) {
  es::io::loadMesh(path, mesh);
  if (mesh.fn == 0) throw std::runtime_error(path + ": mesh has no faces");
  for (const auto& v : mesh.vert)
    if (!v.IsD() &&
        !(std::isfinite(v.cP().X()) && std::isfinite(v.cP().Y()) && std::isfinite(v.cP().Z())))
      throw std::runtime_error(path + ": mesh has NaN or infinite vertex coordinates");
}

nlohmann::json oneSidedJson(const es::OneSidedDistance& d, const es::DistanceReport& report) {
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

nlohmann::json meshJson(const std::string& path, const es::Mesh& mesh) {
  return {{"path", path}, {"vertices", mesh.vn}, {"faces", mesh.fn}};
}

void printRow(const char* label, double min, double max, double mean, double rms,
              const std::string& samples, const es::DistanceReport& report) {
  std::printf("%-16s %12.6g %12.6g %12.6g %12.6g %10s\n", label, min, max, mean, rms,
              samples.c_str());
  std::printf("%-16s %11.4f%% %11.4f%% %11.4f%% %11.4f%%\n", "  (% diagonal)",
              report.percentOfDiagonal(min), report.percentOfDiagonal(max),
              report.percentOfDiagonal(mean), report.percentOfDiagonal(rms));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Two-sided distance between mesh A and reference mesh B (Metro-style: vertices, edges "
      "and faces sampled), absolute and in % of B's bounding-box diagonal."};
  std::string pathA, pathB;
  es::DistanceOptions options;
  bool json = false;
  app.add_option("A", pathA, "Measured mesh (PLY, OFF, OBJ, STL)")->required();
  app.add_option("B", pathB, "Reference mesh (PLY, OFF, OBJ, STL)")->required();
  app.add_option("--samples", options.faceSamples,
                 "Face samples per side, spread by area (edges get a quarter as many)")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{1}, std::size_t{1000000000}));
  app.add_option("--seed", options.seed, "Seed of the sampling generator")->capture_default_str();
  app.add_flag("--json", json, "Print the result as JSON");
  CLI11_PARSE(app, argc, argv);

  try {
    es::Mesh a, b;
    loadMeasurableMesh(pathA, a);
    loadMeasurableMesh(pathB, b);
    const es::DistanceReport report = es::measureDistance(a, b, options);
    const es::OneSidedDistance& f = report.forward;
    const es::OneSidedDistance& r = report.backward;

    if (json) {
      const nlohmann::json out = {{"a", meshJson(pathA, a)},
                                  {"b", meshJson(pathB, b)},
                                  {"reference_diagonal", report.referenceDiagonal},
                                  {"face_samples", options.faceSamples},
                                  {"seed", options.seed},
                                  {"forward", oneSidedJson(f, report)},
                                  {"backward", oneSidedJson(r, report)},
                                  {"symmetric",
                                   {{"max", report.max()},
                                    {"mean", report.mean()},
                                    {"rms", report.rms()},
                                    {"max_percent", report.maxPercent()},
                                    {"mean_percent", report.meanPercent()},
                                    {"rms_percent", report.rmsPercent()}}}};
      std::printf("%s\n", out.dump(2).c_str());
      return 0;
    }
    std::printf("A: %s (%d vertices, %d faces)\n", pathA.c_str(), a.vn, a.fn);
    std::printf("B: %s (%d vertices, %d faces), reference diagonal %.6g\n", pathB.c_str(), b.vn,
                b.fn, report.referenceDiagonal);
    std::printf("%-16s %12s %12s %12s %12s %10s\n", "", "min", "max", "mean", "RMS", "samples");
    printRow("forward  A->B", f.min, f.max, f.mean, f.rms, std::to_string(f.samples), report);
    printRow("backward B->A", r.min, r.max, r.mean, r.rms, std::to_string(r.samples), report);
    printRow("symmetric", std::min(f.min, r.min), report.max(), report.mean(), report.rms(),
             std::to_string(f.samples + r.samples), report);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "mesh-distance: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
