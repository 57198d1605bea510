// edge-sharpener: command-line front end of the Edge-Sharpener core.
//
//   edge-sharpener IN OUT [--multiplier X] [--no-length-check] [--colorize]
//                         [--detect-only] [--json] [--reference EXACT]
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "capacity_hint.h"
#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/mesh_distance.h"
#include "edge_sharpener/mesh_types.h"
#include "mesh_io.h"
#include "report_json.h"

namespace es = edge_sharpener;

namespace {

struct CliOptions {
  std::string input, output, reference;
  double multiplier = 2.0;
  std::string method = "paper";
  es::SharpenOptions extended;  // tuning of the extended method
  double degenerateAngleDeg = 1.0;
  bool keepContacts = false;
  bool gridGuard = false;
  bool strict = false;                             // the strict plane guard's preset
  double borderTurnFactor = -1, maxOffPlane = -1;  // its settings one by one (-1: unset)
  bool noLengthCheck = false, noConvexityCheck = false;
  bool colorize = false, detectOnly = false, json = false, quiet = false;
};

bool stderrProgress(const int percent, const char *stage) {
  std::fprintf(stderr, "[%3d%%] %s\n", percent, stage);
  return true;
}

bool sameFile(const std::string &a, const std::string &b) {
  std::error_code ec;
  return std::filesystem::exists(b, ec) && std::filesystem::equivalent(a, b, ec);
}

nlohmann::json distanceJson(const es::DistanceReport &d) {
  return {{"max", d.max()},
          {"mean", d.mean()},
          {"rms", d.rms()},
          {"max_percent", d.maxPercent()},
          {"mean_percent", d.meanPercent()},
          {"rms_percent", d.rmsPercent()},
          {"reference_diagonal", d.referenceDiagonal}};
}

int run(const CliOptions &cli) {
  if (sameFile(cli.input, cli.output))
    throw std::runtime_error("output would overwrite the input file " + cli.input);
  es::io::returnLargeBlocksToTheSystem();  // see capacity_hint.h
  es::Mesh m;
  if (!cli.detectOnly) es::io::reserveForSharpening(cli.input, m);  // see capacity_hint.h
  es::io::loadMesh(cli.input, m);
  // With --reference, the input's distance is measured before sharpening (no
  // copy kept: measuring changes no position), so a mesh it cannot be
  // measured on is refused before any output is written.
  es::Mesh reference;
  std::optional<es::DistanceReport> before, after;
  if (!cli.reference.empty()) {
    es::io::loadMesh(cli.reference, reference);
    if (reference.FN() == 0) throw std::runtime_error(cli.reference + ": reference has no faces");
    before = es::measureDistance(m, reference);
  }

  es::SharpenOptions opt = cli.extended;  // carries the extended method's tuning flags
  opt.smoothMultiplier = cli.multiplier;
  opt.method = cli.method == "extended" ? es::Method::Extended : es::Method::Paper;
  opt.openRegionContacts = !cli.keepContacts;
  opt.samplingGridGuard = cli.gridGuard;
  opt.setStrictPlaneGuard(cli.strict);
  if (cli.borderTurnFactor >= 0) opt.borderTurnThresholdFactor = cli.borderTurnFactor;
  if (cli.maxOffPlane >= 0) opt.maxSourceOffPlaneSpacings = cli.maxOffPlane;
  opt.edgeLengthCheck = !cli.noLengthCheck;
  opt.convexityCheck = !cli.noConvexityCheck;
  opt.degenerateAngleRad = cli.degenerateAngleDeg * M_PI / 180.0;
  opt.colorize = cli.colorize || cli.detectOnly;
  constexpr int kProgressFaces = 200000;  // report stages on long runs only
  if (!cli.quiet && m.FN() >= kProgressFaces) opt.progress = stderrProgress;

  const auto start = std::chrono::steady_clock::now();
  const es::SharpenReport report =
      cli.detectOnly ? es::detectChamfers(m, opt) : es::sharpen(m, opt);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  namespace mask = vcg::tri::io;
  int saveMask = 0;
  if (opt.colorize) saveMask |= mask::Mask::IOM_VERTCOLOR | mask::Mask::IOM_FACECOLOR;
  if (cli.detectOnly) saveMask |= mask::Mask::IOM_FACEFLAGS;
  es::io::saveMesh(m, cli.output, saveMask);

  if (!cli.reference.empty()) after = es::measureDistance(m, reference);
  if (cli.json) {
    nlohmann::json j = es::reportToJson(report);
    j["seconds"] = seconds;
    j["input_file"] = cli.input;
    j["output_file"] = cli.output;
    if (before)
      j["distance"] = {{"before", distanceJson(*before)}, {"after", distanceJson(*after)}};
    std::cout << j.dump(2) << "\n";
  } else if (!cli.quiet) {
    std::cout << es::formatReport(report) << "time: " << seconds << " s\n";
    if (before) {
      std::printf("distance to %s (%% of its bbox diagonal %.4g):\n", cli.reference.c_str(),
                  before->referenceDiagonal);
      std::printf("  before: max %.4f%%  mean %.5f%%  RMS %.5f%%\n", before->maxPercent(),
                  before->meanPercent(), before->rmsPercent());
      std::printf("  after:  max %.4f%%  mean %.5f%%  RMS %.5f%%\n", after->maxPercent(),
                  after->meanPercent(), after->rmsPercent());
      std::printf("  reduction: max x%.2f, RMS x%.2f\n", before->max() / after->max(),
                  before->rms() / after->rms());
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char **argv) {
  CliOptions cli;
  CLI::App app{
      "Edge-Sharpener: restores sharp edges and corners that uniform remeshing, marching cubes "
      "or scanning cut into chamfers (Attene et al. 2003). Reads and writes PLY, OFF, OBJ, STL."};
  app.add_option("input", cli.input, "mesh to sharpen")->required()->check(CLI::ExistingFile);
  app.add_option("output", cli.output, "where to write the result")->required();
  app.add_option("--multiplier", cli.multiplier,
                 "smooth-edge threshold as a multiple of the mean normal angle")
      ->default_val(2.0)
      ->check(CLI::PositiveNumber);
  app.add_option("--method", cli.method,
                 "paper: the 2003 method as published; extended: feature zones of any width")
      ->default_val("paper")
      ->check(CLI::IsMember({"paper", "extended"}));
  app.add_option("--min-region-depth", cli.extended.minRegionDepth,
                 "extended: thinner smooth regions (in hops) are corridors of the feature zone")
      ->default_val(cli.extended.minRegionDepth)
      ->check(CLI::Range(0, 100));
  app.add_option("--support-rings", cli.extended.supportRings,
                 "extended: face rings used to fit a region's plane")
      ->default_val(cli.extended.supportRings)
      ->check(CLI::Range(1, 20));
  app.add_option("--max-projection", cli.extended.maxProjectionFactor,
                 "extended: longest move of a zone vertex onto its region's plane, in mean edge "
                 "lengths (0: never)")
      ->default_val(cli.extended.maxProjectionFactor)
      ->check(CLI::Range(0.0, 10.0));
  app.add_option("--apex-factor", cli.extended.apexHeightFactor,
                 "extended: keep a vertex at rest when the planes meet this many times higher "
                 "above its chamfer than their angle allows (0: off)")
      ->default_val(cli.extended.apexHeightFactor)
      ->check(CLI::Range(0.0, 100.0));
  app.add_option("--length-factor", cli.extended.extendedEdgeLengthFactor,
                 "extended: the edge-length check allows this multiple of the longest input edge")
      ->default_val(cli.extended.extendedEdgeLengthFactor)
      ->check(CLI::Range(1.0, 100.0));
  app.add_option("--max-displacement", cli.extended.maxDisplacementSpacings,
                 "extended: keep a vertex at rest when the planes meet farther than this many "
                 "median edge lengths from it (0: off)")
      ->default_val(cli.extended.maxDisplacementSpacings)
      ->check(CLI::Range(0.0, 1000.0));
  app.add_option("--spread-ratio", cli.extended.maxSupportSpreadRatio,
                 "extended: keep a vertex at rest when its regions turn by more than this "
                 "fraction of the angle between their planes (a blend; 0: off)")
      ->default_val(cli.extended.maxSupportSpreadRatio)
      ->check(CLI::Range(0.0, 10.0));
  app.add_flag("--strict", cli.strict,
               "extended: strict plane guard (--border-turn 1 --max-off-plane 0.3, planes fitted "
               "around the flat faces away from the zone): keeps blends and finely facetted "
               "curves at rest; also keeps wide bevels of coarse remeshings");
  app.add_option("--border-turn", cli.borderTurnFactor,
                 "extended: return to the zone the region faces next to it that turn from their "
                 "region's plane by more than this multiple of the smooth threshold (0: off)")
      ->check(CLI::Range(0.0, 100.0));
  app.add_option("--max-off-plane", cli.maxOffPlane,
                 "extended: keep a vertex at rest when a source vertex lies farther than this "
                 "many median edge lengths from its plane (0: off)")
      ->check(CLI::Range(0.0, 100.0));
  app.add_flag("--grid-guard", cli.gridGuard,
               "extended: on a marching-cubes resampling (its vertices on an axis-aligned grid), "
               "send back a vertex whose move sweeps over a grid node the sampler saw on the "
               "other side (blends and bevels hardly larger than a cell); not for "
               "reconstructions such as Screened Poisson");
  app.add_option("--grid-tolerance", cli.extended.gridSweepToleranceCells,
                 "extended: a node counts as swept when it lies this many cells past the moved "
                 "face")
      ->default_val(cli.extended.gridSweepToleranceCells)
      ->check(CLI::Range(0.0, 10.0));
  app.add_option("--grid-blended-fraction", cli.extended.gridBlendedFeatureFraction,
                 "extended: with --grid-guard, when this fraction of the moves between two "
                 "regions went back, the rest of them go back too (a blend, not a sharp edge; "
                 "0: off)")
      ->default_val(cli.extended.gridBlendedFeatureFraction)
      ->check(CLI::Range(0.0, 1.0));
  app.add_flag("--keep-contacts", cli.keepContacts,
               "extended: leave faces where two smooth regions touch in their regions");
  app.add_flag("--no-length-check", cli.noLengthCheck,
               "allow placements that create edges longer than the input's longest");
  app.add_flag("--no-convexity-check", cli.noConvexityCheck,
               "also move vertices of chamfers bordered by a concave and a convex edge");
  app.add_option("--degenerate-angle", cli.degenerateAngleDeg,
                 "triangles with an angle below this (degrees) are removed after sharpening")
      ->default_val(1.0)
      ->check(CLI::Range(0.0, 59.0));
  app.add_flag("--colorize", cli.colorize, "paint the paper's colours into the output");
  app.add_flag("--detect-only", cli.detectOnly,
               "only detect: colour and select chamfer/corner faces, no geometry change");
  app.add_flag("--json", cli.json, "print the report as JSON");
  app.add_option("--reference", cli.reference,
                 "exact shape: print the two-sided (Metro) distance to it before and after")
      ->check(CLI::ExistingFile);
  app.add_flag("-q,--quiet", cli.quiet, "print nothing on success");
  CLI11_PARSE(app, argc, argv);
  try {
    return run(cli);
  } catch (const std::exception &e) {
    std::cerr << "edge-sharpener: error: " << e.what() << "\n";
    return 1;
  }
}
