// edge-sharpener: command-line front end of the Edge-Sharpener core.
//
//   edge-sharpener IN OUT [options of the option table] [--detect-only]
//                         [--reference EXACT] [--sharp-edges EDGES.obj]
//                         [--only-faces FACES.txt | --skip-faces FACES.txt]
//                         [-v | -q | --json]
//
// --help lists the option table's ordinary options, --help-all every option by
// group. By default it prints four lines: the input, what was restored and left
// (formatVerdictSummary), the time, the output; -v adds the stage report, -q
// prints nothing, --json the report as JSON.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <vector>

#include "capacity_hint.h"
#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/option_table.h"
#include "edge_sharpener/restored_edges.h"
#include "edge_sharpener/util/mesh_types.h"
#include "mesh_distance.h"
#include "mesh_io.h"
#include "report_json.h"

namespace es = edge_sharpener;

namespace {

struct CliOptions {
  std::string input, output, reference, sharpEdges, onlyFaces, skipFaces;
  bool detectOnly = false, json = false, quiet = false, verbose = false;
  /// One slot per row of the option table: the value given on the command
  /// line (numbers and flags as doubles, choices by name), and whether it was.
  std::vector<double> number = std::vector<double>(es::optionTable().size(), 0.0);
  std::vector<std::string> choice = std::vector<std::string>(es::optionTable().size());
  std::vector<CLI::Option *> given = std::vector<CLI::Option *>(es::optionTable().size());

  /// The core's options: its defaults, then every option given, in table order.
  es::SharpenOptions sharpenOptions() const {
    es::SharpenOptions opt;
    const auto &table = es::optionTable();
    for (std::size_t i = 0; i < table.size(); ++i) {
      if (given[i]->count() == 0) continue;
      const es::OptionSpec &spec = table[i];
      switch (spec.type) {
        case es::OptionType::Flag: spec.set(opt, spec.defaultValue() != 0 ? 0.0 : 1.0); break;
        case es::OptionType::Choice: spec.set(opt, spec.choiceIndex(choice[i])); break;
        default: spec.set(opt, number[i]);
      }
    }
    return opt;
  }
};

std::string numberText(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

/// `text` broken into lines of at most `width` characters (CLI11 indents the
/// lines after the first under the option's column).
std::string wrapped(const std::string &text, std::size_t width) {
  std::istringstream words(text);
  std::string word, out, line;
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

/// CLI11's help with each description wrapped to fit 100 columns.
class WrappingFormatter : public CLI::Formatter {
 public:
  static constexpr std::size_t kColumn = 30, kWidth = 100;
  WrappingFormatter() { column_width(kColumn); }
  std::string make_option_desc(const CLI::Option *o) const override {
    return wrapped(CLI::Formatter::make_option_desc(o), kWidth - kColumn);
  }
  std::string make_description(const CLI::App *app) const override {
    return wrapped(app->get_description(), kWidth) + "\n";
  }
  /// The description, usage, positionals, then each group, one blank line
  /// apart (CLI11's own puts two): --help (mode Normal) the ordinary options
  /// and the program's own, --help-all (mode All) each method's tuning too.
  std::string make_help(const CLI::App *app, std::string name,
                        CLI::AppFormatMode mode) const override {
    const bool all = mode == CLI::AppFormatMode::All;
    std::string out = make_description(app) + make_usage(app, name) + make_positionals(app);
    for (const std::string &group : app->get_groups()) {
      if (!all && isTuningGroup(group)) continue;
      const auto options = app->get_options(
          [&group](const CLI::Option *o) { return o->get_group() == group && o->nonpositional(); });
      if (!group.empty() && !options.empty()) out += make_group(group, false, options);
    }
    return out + "\n" +
           wrapped(all ? "The tuning options change the rules each method decides by; what each "
                         "rule does and why: docs/auto-method-decisions.md."
                       : "Each method's tuning options: --help-all.",
                   kWidth) +
           "\n";
  }

 private:
  static bool isTuningGroup(const std::string &title) {
    for (const es::OptionSpec &spec : es::optionTable())
      if (!spec.ordinary() && title == es::toString(spec.group)) return true;
    return false;
  }
};

/// Every row of the option table as a command-line option, in its group: the
/// ordinary ones in --help, each method's tuning in --help-all only.
void addTableOptions(CLI::App &app, CliOptions &cli) {
  const auto &table = es::optionTable();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const es::OptionSpec &spec = table[i];
    std::string help(spec.help);
    if (!spec.unit.empty()) help += " [" + std::string(spec.unit) + "]";
    const std::string flag(spec.cliFlag);
    CLI::Option *o = nullptr;
    if (spec.type == es::OptionType::Flag) {
      // A flag turns its option from the default to the other value.
      if (spec.defaultValue() != 0) help += " On by default: the flag turns it off.";
      o = app.add_flag(flag)->description(help);
    } else if (spec.type == es::OptionType::Choice) {
      std::vector<std::string> names(spec.choices.begin(), spec.choices.end());
      o = app.add_option(flag, cli.choice[i], help)
              ->check(CLI::IsMember(names))
              ->default_str(std::string(spec.choiceName(spec.defaultValue())));
    } else {
      o = app.add_option(flag, cli.number[i], help)
              ->check(CLI::Validator(
                  [&spec](std::string &text) {
                    double value = 0;
                    if (!CLI::detail::lexical_cast(text, value)) return text + " is not a number";
                    return spec.problemWith(value);
                  },
                  "", "option range"))
              ->default_str(numberText(spec.defaultValue()))
              ->type_name(spec.type == es::OptionType::Integer ? "INT" : "FLOAT");
    }
    o->group(es::toString(spec.group));
    cli.given[i] = o;
  }
}

/// Progress of a long run on stderr: a line per stage (--verbose)...
bool stderrProgress(const int percent, const char *stage) {
  std::fprintf(stderr, "[%3d%%] %s\n", percent, stage);
  return true;
}

/// ...or, on a terminal, one line rewritten in place and erased at the end.
bool terminalProgress(const int percent, const char *stage) {
  std::fprintf(stderr, "\r\033[K[%3d%%] %s", percent, stage);
  std::fflush(stderr);
  return true;
}
void eraseTerminalProgress() {
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
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

/// Writes the restored sharp edges (restoredEdges: the output edges joining
/// two vertices placed on a sharp edge or corner) as OBJ polylines: their
/// vertices, in the output's order, and one line element per edge. Other
/// tools read them as feature lines (a remesher's protected edges, Blender's
/// OBJ import). \return the number of edges written.
std::size_t writeSharpEdges(const es::Mesh &m, const std::vector<std::uint8_t> &restored,
                            const std::string &path) {
  const auto edges = es::restoredEdges(m, restored);
  std::vector<std::uint32_t> objIndex(m.vert.size(), 0);  // 1-based; 0: on no edge
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "# Edge-Sharpener: the " << edges.size() << " restored sharp edges\n";
  out.precision(9);
  for (const auto &edge : edges)
    for (const std::uint32_t v : edge) objIndex[v] = 1;
  // The edges' vertices in the order of their output index: the file follows the mesh.
  std::uint32_t next = 0;
  for (std::size_t v = 0; v < objIndex.size(); ++v) {
    if (objIndex[v] == 0) continue;
    objIndex[v] = ++next;
    const auto &p = m.vert[v].cP();
    out << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
  }
  for (const auto &[a, b] : edges) out << "l " << objIndex[a] << " " << objIndex[b] << "\n";
  if (!out.flush()) throw std::runtime_error("cannot write " + path);
  return edges.size();
}

/// --only-faces (`listed` true) selects the faces whose indices the text file
/// at `path` lists (whitespace-separated, 0-based, `#` starts a comment),
/// every other face unselected; --skip-faces (`listed` false) selects every
/// face but those. A list of indices, not a mesh property: any script writes
/// one (numpy.savetxt), where few tools write a PLY face property.
void selectFaces(const std::string &path, bool listed, es::Mesh &m) {
  const std::string option = listed ? "--only-faces" : "--skip-faces";
  std::ifstream in(path);
  if (!in) throw std::runtime_error(option + ": cannot read " + path);
  for (auto &f : m.face) listed ? f.ClearS() : f.SetS();
  std::size_t lineNumber = 0;
  for (std::string line; std::getline(in, line);) {
    ++lineNumber;
    std::istringstream words(line.substr(0, line.find('#')));
    for (std::string word; words >> word;) {
      const std::string where = option + ": " + path + " line " + std::to_string(lineNumber);
      unsigned long long index = 0;
      try {
        if (word.find_first_not_of("0123456789") != std::string::npos) throw std::exception();
        index = std::stoull(word);
      } catch (...) {
        throw std::runtime_error(where + ": '" + word + "' is not a face index (0, 1, 2, ...)");
      }
      if (index >= m.face.size())
        throw std::runtime_error(where + ": face " + word + " does not exist (the mesh has " +
                                 std::to_string(m.face.size()) + " faces)");
      listed ? m.face[index].SetS() : m.face[index].ClearS();
    }
  }
}

int run(const CliOptions &cli) {
  if (sameFile(cli.input, cli.output))
    throw std::runtime_error("output would overwrite the input file " + cli.input);
  if (!cli.sharpEdges.empty()) {
    if (cli.detectOnly)
      throw std::runtime_error("--sharp-edges needs sharpening: --detect-only restores none");
    if (sameFile(cli.input, cli.sharpEdges))
      throw std::runtime_error("--sharp-edges would overwrite the input file " + cli.input);
    if (std::filesystem::path(cli.sharpEdges).lexically_normal() ==
        std::filesystem::path(cli.output).lexically_normal())
      throw std::runtime_error("--sharp-edges and the output are the same file");
  }
  const bool selection = !cli.onlyFaces.empty() || !cli.skipFaces.empty();
  if (selection && cli.detectOnly)
    throw std::runtime_error(std::string(cli.onlyFaces.empty() ? "--skip-faces" : "--only-faces") +
                             " needs sharpening: --detect-only looks at every face");
  es::io::returnLargeBlocksToTheSystem();  // see capacity_hint.h
  es::Mesh m;
  if (!cli.detectOnly) es::io::reserveForSharpening(cli.input, m);  // see capacity_hint.h
  const int inputAttributes = es::io::loadMesh(cli.input, m);
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

  es::SharpenOptions opt = cli.sharpenOptions();
  if (selection) {
    selectFaces(cli.onlyFaces.empty() ? cli.skipFaces : cli.onlyFaces, cli.skipFaces.empty(), m);
    opt.selectedFacesOnly = true;
  }
  opt.colorize = opt.colorize || cli.detectOnly;
  constexpr int kProgressFaces = 200000;  // report stages on long runs only
  const bool progressLine = !cli.quiet && !cli.verbose && !cli.json && m.FN() >= kProgressFaces &&
                            ::isatty(STDERR_FILENO);
  if (cli.verbose && m.FN() >= kProgressFaces) opt.progress = stderrProgress;
  if (progressLine) opt.progress = terminalProgress;

  // --sharp-edges: the attribute sharpen() fills when it is there (restored_edges.h).
  using Allocator = vcg::tri::Allocator<es::Mesh>;
  if (!cli.sharpEdges.empty())
    Allocator::AddPerVertexAttribute<std::uint8_t>(m, es::kRestoredVertexAttribute);

  const auto start = std::chrono::steady_clock::now();
  es::SharpenReport report;
  try {
    report = cli.detectOnly ? es::detectChamfers(m, opt) : es::sharpen(m, opt);
  } catch (...) {
    if (progressLine) eraseTerminalProgress();
    throw;
  }
  if (progressLine) eraseTerminalProgress();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::optional<std::size_t> sharpEdgeCount;
  if (!cli.sharpEdges.empty()) {
    auto handle = Allocator::FindPerVertexAttribute<std::uint8_t>(m, es::kRestoredVertexAttribute);
    std::vector<std::uint8_t> restored(m.vert.size());
    for (std::size_t v = 0; v < m.vert.size(); ++v) restored[v] = handle[v];
    Allocator::DeletePerVertexAttribute(m, handle);
    sharpEdgeCount = writeSharpEdges(m, restored, cli.sharpEdges);
  }

  namespace mask = vcg::tri::io;
  int saveMask = inputAttributes & mask::Mask::IOM_VERTCOLOR;  // the input's vertex colours
  if (opt.colorize) saveMask |= mask::Mask::IOM_VERTCOLOR | mask::Mask::IOM_FACECOLOR;
  if (cli.detectOnly) saveMask |= mask::Mask::IOM_FACEFLAGS;
  es::io::saveMesh(m, cli.output, saveMask);

  if (!cli.reference.empty()) after = es::measureDistance(m, reference);
  if (cli.json) {
    nlohmann::json j = es::reportToJson(report);
    j["options"] = es::optionsToJson(opt);
    j["seconds"] = seconds;
    j["input_file"] = cli.input;
    j["output_file"] = cli.output;
    if (before)
      j["distance"] = {{"before", distanceJson(*before)}, {"after", distanceJson(*after)}};
    if (sharpEdgeCount) j["sharp_edges"] = {{"file", cli.sharpEdges}, {"edges", *sharpEdgeCount}};
    std::cout << j.dump(2) << "\n";
  } else if (!cli.quiet) {
    // At most four lines (five with --reference); --verbose adds the stages.
    std::cout << "input: " << cli.input << ", " << report.inputVertices << " vertices, "
              << report.inputFaces << " faces";
    if (cli.verbose) std::cout << ", longest edge " << report.longestInputEdge;
    std::cout << "\n";
    if (cli.verbose) std::cout << es::formatStages(report);
    std::cout << es::formatVerdictSummary(report) << "\n";
    if (const std::string notes = es::formatInputNotes(report); !notes.empty())
      std::cout << notes << "\n";
    std::printf("time: %.*f s\n", seconds < 10 ? 3 : seconds < 100 ? 1 : 0, seconds);
    std::cout << "output: " << cli.output << ", " << m.VN() << " vertices, " << m.FN() << " faces";
    if (sharpEdgeCount)
      std::cout << "; " << *sharpEdgeCount << " sharp edges in " << cli.sharpEdges;
    std::cout << "\n";
    if (before)
      std::printf(
          "distance to the reference, %% of its diagonal: max %.4f%% -> %.4f%% (x%.2f), RMS "
          "%.5f%% -> %.5f%% (x%.2f)\n",
          before->maxPercent(), after->maxPercent(), before->max() / after->max(),
          before->rmsPercent(), after->rmsPercent(), before->rms() / after->rms());
  }
  return 0;
}

}  // namespace

int main(int argc, char **argv) {
  CliOptions cli;
  CLI::App app{
      "Edge-Sharpener: restores sharp edges and corners that uniform remeshing, marching cubes "
      "or scanning cut into chamfers (Attene et al. 2003). Reads and writes PLY, OFF, OBJ, STL; "
      "vertex colours are kept, each new vertex with the mean colour of those it was made "
      "between."};
  app.formatter(std::make_shared<WrappingFormatter>());
  app.set_help_flag("-h,--help", "print the ordinary options and exit");
  app.set_help_all_flag("--help-all", "print every option, each method's tuning too, and exit");
  app.add_option("input", cli.input, "mesh to sharpen")->required()->check(CLI::ExistingFile);
  app.add_option("output", cli.output, "where to write the result")->required();
  addTableOptions(app, cli);
  app.add_flag("--detect-only", cli.detectOnly,
               "only detect: colour the labels and select the faces sharpening may change, no "
               "geometry change");
  app.add_option("--reference", cli.reference,
                 "exact shape: print the two-sided (Metro) distance to it before and after")
      ->check(CLI::ExistingFile);
  app.add_option("--sharp-edges", cli.sharpEdges,
                 "also write the restored sharp edges to this OBJ file, as line elements "
                 "(feature lines for a remesher or a modeller)");
  auto *only = app.add_option("--only-faces", cli.onlyFaces,
                              "sharpen only within these faces: a text file of face indices "
                              "(0-based, whitespace-separated, # comments). A feature outside "
                              "them is left as it came, one they cut is sharpened up to them")
                   ->check(CLI::ExistingFile);
  app.add_option("--skip-faces", cli.skipFaces,
                 "leave these faces as they came (a designed bevel, say): the same file format, "
                 "every other face selected as with --only-faces")
      ->check(CLI::ExistingFile)
      ->excludes(only);
  app.add_flag("-v,--verbose", cli.verbose, "also print what each stage did");
  app.add_flag("-q,--quiet", cli.quiet, "print nothing on success");
  app.add_flag("--json", cli.json, "print the report as JSON instead");
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success &help) {  // --help, --help-all
    return app.exit(help);
  } catch (const CLI::ParseError &e) {  // one line, as every other error
    const bool usage =
        dynamic_cast<const CLI::RequiredError *>(&e) || dynamic_cast<const CLI::ExtrasError *>(&e);
    std::cerr << "edge-sharpener: error: " << e.what() << (usage ? " (see --help)" : "") << "\n";
    return e.get_exit_code();
  }
  try {
    if (cli.verbose && cli.quiet)
      throw std::runtime_error("--verbose and --quiet exclude each other");
    return run(cli);
  } catch (const std::exception &e) {
    std::cerr << "edge-sharpener: error: " << e.what() << "\n";
    return 1;
  }
}
