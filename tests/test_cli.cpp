// What the edge-sharpener CLI says to a user: --help (the ordinary options,
// pointing to --help-all) and --help-all (every option of the table, by group),
// the default output (four lines: input, what was restored and left, time,
// output), -q (nothing, the output still written), -v (the stage report too),
// --json (the verdict counts), and the tuning flags reaching the core. The
// program is run as a user runs it; its words are checked against the option
// table, the report's formatting functions and an in-process run.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/option_table.h"
#include "edge_sharpener/report.h"
#include "edge_sharpener/util/mesh_types.h"
#include "mesh_io.h"

namespace es = edge_sharpener;
namespace fs = std::filesystem;

namespace {

struct CliRun {
  int exitCode = -1;
  std::string out, err;
  std::vector<std::string> lines() const {
    std::vector<std::string> v;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);) v.push_back(line);
    return v;
  }
};

std::string readFile(const fs::path &p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// This process's scratch directory, removed when it exits.
const fs::path &scratchRoot() {
  static const struct Root {
    fs::path path = fs::temp_directory_path() / ("es-cli-tests-" + std::to_string(::getpid()));
    ~Root() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  } root;
  return root.path;
}

fs::path scratch(const std::string &name) {
  const fs::path dir = scratchRoot() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// Runs the CLI with `arguments` (already quoted), stdout and stderr apart.
CliRun cli(const std::string &arguments) {
  const fs::path err = scratch("stderr") / "stderr.txt";
  const std::string command =
      std::string("'") + EDGE_SHARPENER_CLI + "' " + arguments + " 2>'" + err.string() + "'";
  CliRun r;
  FILE *pipe = ::popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    r.out.append(buffer, n);
  const int status = ::pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = readFile(err);
  return r;
}

std::string quoted(const fs::path &p) {
  return "'" + p.string() + "'";
}

fs::path sample(const std::string &name) {
  return fs::path(EDGE_SHARPENER_SOURCE_DIR) / "test_meshes" / "generated" / (name + ".ply");
}

/// Whether `text` names the flag `flag` (not as the start of a longer one:
/// --on-plane is not --on-plane-median).
bool namesFlag(const std::string &text, const std::string &flag) {
  const std::regex re("(^|[\\s,])" + flag + "([\\s=,]|$)");
  return std::regex_search(text, re);
}

/// The line formatVerdictSummary() writes for the auto method, built here from
/// the JSON report's verdict counts and labels.h's words.
std::string expectedAutoSummary(const nlohmann::json &verdicts) {
  std::size_t features = 0;
  for (const auto &[name, count] : verdicts.items()) features += count.get<std::size_t>();
  const std::size_t restored = verdicts.at("restored");
  std::string line = "features: " + std::to_string(restored) + " restored, ";
  if (restored == features) return line + "none left";
  line += std::to_string(features - restored) + " left as they were:";
  const char *separator = " ";
  for (int i = 0; i < es::kVerdictCount; ++i) {
    const auto v = static_cast<es::Verdict>(i);
    const std::size_t n = verdicts.at(es::toString(v));
    if (!es::isLeft(v) || n == 0) continue;
    line += separator + std::to_string(n) + " " + es::describe(v);
    separator = ", ";
  }
  return line;
}

}  // namespace

TEST(Cli, HelpListsTheOrdinaryOptionsAndPointsToHelpAll) {
  const CliRun r = cli("--help");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const es::OptionSpec &spec : es::optionTable()) {
    const std::string flag(spec.cliFlag);
    if (spec.ordinary()) {
      EXPECT_TRUE(namesFlag(r.out, flag)) << flag << " missing from --help";
    } else {
      EXPECT_FALSE(namesFlag(r.out, flag)) << "tuning flag " << flag << " in --help";
      EXPECT_EQ(r.out.find(es::toString(spec.group)), std::string::npos)
          << es::toString(spec.group);
    }
  }
  for (const char *own : {"--detect-only", "--json", "--reference", "--sharp-edges", "--quiet",
                          "--verbose", "--help-all"})
    EXPECT_TRUE(namesFlag(r.out, own)) << own;
  const auto lines = r.lines();
  ASSERT_FALSE(lines.empty());
  EXPECT_NE(lines.back().find("--help-all"), std::string::npos) << lines.back();
  for (const std::string &line : lines) EXPECT_LE(line.size(), 100u) << line;
}

TEST(Cli, HelpAllListsEveryOptionUnderItsGroup) {
  const CliRun r = cli("--help-all");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto lines = r.lines();
  // Each flag on a line below its group's title and above the next title.
  for (const es::OptionSpec &spec : es::optionTable()) {
    const std::string flag(spec.cliFlag), title = std::string(es::toString(spec.group)) + ":";
    std::size_t titleLine = lines.size(), flagLine = lines.size();
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (lines[i] == title && titleLine == lines.size()) titleLine = i;
      if (lines[i].rfind("  " + flag, 0) == 0 && namesFlag(lines[i], flag)) flagLine = i;
    }
    ASSERT_LT(titleLine, lines.size()) << "no group " << title;
    ASSERT_LT(flagLine, lines.size()) << flag << " missing from --help-all";
    EXPECT_GT(flagLine, titleLine) << flag;
    for (std::size_t i = titleLine + 1; i < flagLine; ++i)
      EXPECT_FALSE(!lines[i].empty() && lines[i][0] != ' ' && lines[i].back() == ':')
          << flag << " is under " << lines[i] << ", not " << title;
  }
  for (const std::string &line : lines) EXPECT_LE(line.size(), 100u) << line;
}

// Four lines: the input, what was restored and what was left (each verdict with
// its count), the time, the output; the counts are the JSON report's.
TEST(Cli, DefaultOutputIsFourLinesNamingTheVerdicts) {
  const fs::path dir = scratch("default");
  bool someLeft = false;
  // Every feature of the samples is restored; a tuning flag that leaves
  // them all (too short) gives the verdict words something to say.
  const std::vector<std::pair<std::string, std::string>> runs{
      {"pyramid_mc2", ""},
      {"lblock_mc2", ""},
      {"cube_mc2", ""},
      {"cube_mc2", " --min-feature-vertices 1000"}};
  for (const auto &[name, flags] : runs) {
    const fs::path out = dir / (name + ".ply"), jsonOut = dir / (name + ".json.ply");
    const CliRun r = cli(quoted(sample(name)) + " " + quoted(out) + flags);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const CliRun j = cli(quoted(sample(name)) + " " + quoted(jsonOut) + " --json" + flags);
    ASSERT_EQ(j.exitCode, 0) << j.err;
    const nlohmann::json report = nlohmann::json::parse(j.out);
    EXPECT_EQ(readFile(out), readFile(jsonOut)) << name << ": --json changed the output";

    const auto lines = r.lines();
    ASSERT_EQ(lines.size(), 4u) << r.out;
    EXPECT_EQ(lines[0], "input: " + sample(name).string() + ", " +
                            std::to_string(report["input"]["vertices"].get<int>()) + " vertices, " +
                            std::to_string(report["input"]["faces"].get<int>()) + " faces");
    const nlohmann::json &verdicts = report["evidence"]["verdicts"];
    EXPECT_EQ(lines[1], expectedAutoSummary(verdicts));
    EXPECT_EQ(lines[1], report["summary"]);
    someLeft = someLeft || verdicts["restored"] != report["evidence"]["features"];
    EXPECT_TRUE(std::regex_match(lines[2], std::regex("time: [0-9.e-]+ s"))) << lines[2];
    EXPECT_EQ(lines[3], "output: " + out.string() + ", " +
                            std::to_string(report["output"]["vertices"].get<int>()) +
                            " vertices, " + std::to_string(report["output"]["faces"].get<int>()) +
                            " faces");
  }
  EXPECT_TRUE(someLeft) << "no sample has a feature left: the verdict words went untested";
}

// Without verdicts (paper, extended) the second line counts the new vertices
// placed and left at rest; --detect-only says what it found; --sharp-edges
// joins the output line.
TEST(Cli, DefaultOutputOfTheOtherMethodsAndModes) {
  const fs::path dir = scratch("methods");
  const fs::path in = sample("lblock_mc2"), out = dir / "out.ply";
  for (const std::string method : {"paper", "extended"}) {
    const CliRun r = cli(quoted(in) + " " + quoted(out) + " --method " + method);
    const CliRun j = cli(quoted(in) + " " + quoted(out) + " --json --method " + method);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json report = nlohmann::json::parse(j.out);
    const auto lines = r.lines();
    ASSERT_EQ(lines.size(), 4u) << r.out;
    EXPECT_EQ(lines[1].rfind(
                  "new vertices: " + std::to_string(report["placement"]["moved"].get<int>()) +
                      " placed on sharp edges, " +
                      std::to_string(report["placement"]["fallbacks"].get<int>()) + " left at rest",
                  0),
              0u)
        << lines[1];
    EXPECT_GT(report["placement"]["moved"].get<int>(), 100);
    EXPECT_FALSE(report.contains("evidence"));
  }
  // The default's Detect says what Sharpen would do; the others what they found.
  const CliRun detect = cli(quoted(in) + " " + quoted(out) + " --detect-only");
  ASSERT_EQ(detect.exitCode, 0) << detect.err;
  const auto lines = detect.lines();
  ASSERT_EQ(lines.size(), 4u) << detect.out;
  EXPECT_TRUE(std::regex_match(lines[1], std::regex("detected, as Sharpen judges them: features: "
                                                    "[1-9][0-9]* restored, .*; [1-9][0-9]* faces "
                                                    "selected, those Sharpen changes \\(geometry "
                                                    "unchanged\\)")))
      << lines[1];
  const CliRun detectExtended =
      cli(quoted(in) + " " + quoted(out) + " --detect-only --method extended");
  ASSERT_EQ(detectExtended.exitCode, 0) << detectExtended.err;
  ASSERT_EQ(detectExtended.lines().size(), 4u) << detectExtended.out;
  EXPECT_TRUE(std::regex_match(detectExtended.lines()[1],
                               std::regex("detected: [1-9][0-9]* chamfer faces, [0-9]+ "
                                          "corner faces, [0-9]+ smooth-region faces; "
                                          "[1-9][0-9]* faces selected, those Sharpen may "
                                          "change \\(geometry unchanged\\)")))
      << detectExtended.lines()[1];
  const fs::path edges = dir / "edges.obj";
  const CliRun withEdges = cli(quoted(in) + " " + quoted(out) + " --sharp-edges " + quoted(edges));
  ASSERT_EQ(withEdges.exitCode, 0) << withEdges.err;
  ASSERT_EQ(withEdges.lines().size(), 4u) << withEdges.out;
  std::size_t written = 0;  // one "l A B" line per edge
  std::istringstream obj(readFile(edges));
  for (std::string line; std::getline(obj, line);) written += line.rfind("l ", 0) == 0;
  EXPECT_GT(written, 0u);
  const std::string outputLine = withEdges.lines()[3];
  const std::string suffix = "; " + std::to_string(written) + " sharp edges in " + edges.string();
  EXPECT_TRUE(outputLine.size() > suffix.size() &&
              outputLine.compare(outputLine.size() - suffix.size(), suffix.size(), suffix) == 0)
      << outputLine;
}

TEST(Cli, QuietPrintsNothingAndStillWritesTheOutput) {
  const fs::path dir = scratch("quiet");
  const fs::path in = sample("cube_mc2"), out = dir / "out.ply", loud = dir / "loud.ply";
  const CliRun r = cli("-q " + quoted(in) + " " + quoted(out));
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "");
  ASSERT_TRUE(fs::exists(out));
  ASSERT_EQ(cli(quoted(in) + " " + quoted(loud)).exitCode, 0);
  EXPECT_EQ(readFile(out), readFile(loud)) << "-q changed the result";
  es::Mesh input, sharpened;
  es::io::loadMesh(in.string(), input);
  es::io::loadMesh(out.string(), sharpened);
  EXPECT_GT(sharpened.FN(), input.FN());
  // -q with -v: one line on stderr, status 1, nothing written.
  const fs::path none = dir / "none.ply";
  const CliRun both = cli("-q -v " + quoted(in) + " " + quoted(none));
  EXPECT_EQ(both.exitCode, 1);
  EXPECT_EQ(both.out, "");
  EXPECT_EQ(both.err, "edge-sharpener: error: --verbose and --quiet exclude each other\n");
  EXPECT_FALSE(fs::exists(none));
}

// -v: the four lines with the stage report between the input and the summary,
// exactly formatStages() of the same run in process.
TEST(Cli, VerboseAddsTheStageReport) {
  const fs::path dir = scratch("verbose");
  const fs::path in = sample("pyramid_mc2"), out = dir / "out.ply";
  const CliRun r = cli("-v " + quoted(in) + " " + quoted(out));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  es::Mesh m;
  es::io::loadMesh(in.string(), m);
  const es::SharpenReport report = es::sharpen(m, es::SharpenOptions{});
  const std::string stages = es::formatStages(report);
  for (const char *stage : {"smooth edges: ", "filters: ", "feature zones: ", "subdivision: ",
                            "placement: ", "cleanup: ", "self-intersections: ", "evidence: "})
    EXPECT_NE(stages.find(stage), std::string::npos) << stage;
  const auto lines = r.lines();
  ASSERT_GE(lines.size(), 5u);
  EXPECT_EQ(lines[0].rfind("input: " + in.string() + ", ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(", longest edge "), std::string::npos) << lines[0];
  const std::size_t afterInput = r.out.find('\n') + 1;
  EXPECT_EQ(r.out.substr(afterInput, stages.size()), stages);
  const std::string rest = r.out.substr(afterInput + stages.size());
  EXPECT_EQ(rest.rfind(es::formatVerdictSummary(report) + "\ntime: ", 0), 0u) << rest;
  EXPECT_EQ(lines.back().rfind("output: " + out.string() + ", ", 0), 0u) << lines.back();
}

// The report's verdicts: every verdict by name, summing to the features.
TEST(Cli, JsonVerdictsSumToTheFeatures) {
  const fs::path dir = scratch("json");
  for (const std::string name : {"pyramid_mc2", "lblock_mc2", "cube_mc2"}) {
    for (const std::string extra : {"", " --min-feature-vertices 40"}) {
      const CliRun r =
          cli(quoted(sample(name)) + " " + quoted(dir / "out.ply") + " --json" + extra);
      ASSERT_EQ(r.exitCode, 0) << r.err;
      const nlohmann::json j = nlohmann::json::parse(r.out);
      ASSERT_TRUE(j.contains("evidence")) << name;
      const nlohmann::json &verdicts = j["evidence"]["verdicts"];
      ASSERT_EQ(verdicts.size(), std::size_t(es::kVerdictCount));
      std::size_t sum = 0;
      for (int i = 0; i < es::kVerdictCount; ++i) {
        const char *key = es::toString(static_cast<es::Verdict>(i));
        ASSERT_TRUE(verdicts.contains(key)) << key;
        sum += verdicts[key].get<std::size_t>();
      }
      EXPECT_EQ(sum, j["evidence"]["features"].get<std::size_t>()) << name << extra;
      // Each feature listed, with the verdict the counts count and the faces it splits.
      ASSERT_EQ(j["features"].size(), sum) << name << extra;
      std::map<std::string, std::size_t> listed;
      std::set<std::size_t> faces;
      for (const auto &f : j["features"]) {
        ++listed[f["verdict"].get<std::string>()];
        EXPECT_GT(f["new_vertices"].get<std::size_t>(), 0u);
        EXPECT_FALSE(f["faces"].empty());
        for (const auto &face : f["faces"]) faces.insert(face.get<std::size_t>());
        if (f["kind"] == "edge") {
          EXPECT_GT(f["width_spacings"].get<double>(), 0.0) << name;
          EXPECT_GT(f["flank_angle_deg"].get<double>(), 0.0) << name;
        } else {
          EXPECT_EQ(f["kind"], "corner");
        }
      }
      for (const auto &[verdict, count] : listed) EXPECT_EQ(verdicts[verdict], count) << verdict;
      EXPECT_LT(*faces.rbegin(), j["input"]["faces"].get<std::size_t>());
      EXPECT_GT(sum, 0u) << name;
      EXPECT_EQ(verdicts["restored"].get<std::size_t>() +
                    j["evidence"]["weak_features"].get<std::size_t>(),
                sum)
          << name << extra;
    }
  }
}

// A tuning flag, though --help hides it, reaches the core: with every feature
// shorter than the minimum size, each is left as too short and the mesh comes
// back as it was.
TEST(Cli, TuningFlagsStillWork) {
  const fs::path dir = scratch("tuning");
  const fs::path in = sample("cube_mc2"), out = dir / "out.ply";
  const CliRun r = cli(quoted(in) + " " + quoted(out) + " --json --min-feature-vertices 1000");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["options"]["min_feature_vertices"], 1000);
  const nlohmann::json &verdicts = j["evidence"]["verdicts"];
  EXPECT_EQ(verdicts["restored"], 0);
  EXPECT_GT(verdicts["too_short"].get<int>(), 0);
  EXPECT_EQ(j["output"]["faces"], j["input"]["faces"]);
  const CliRun text = cli(quoted(in) + " " + quoted(out) + " --min-feature-vertices 1000");
  ASSERT_EQ(text.lines().size(), 4u) << text.out;
  EXPECT_EQ(text.lines()[1], expectedAutoSummary(verdicts));
  EXPECT_NE(text.lines()[1].find(std::to_string(verdicts["too_short"].get<int>()) + " too short"),
            std::string::npos)
      << text.lines()[1];
  // Out of range: the one-line error of any bad value.
  const CliRun bad = cli(quoted(in) + " " + quoted(dir / "bad.ply") + " --max-label-hops 1000");
  EXPECT_NE(bad.exitCode, 0);
  EXPECT_EQ(bad.err,
            "edge-sharpener: error: --max-label-hops: option max_label_hops must be in [0, 100] "
            "hops\n");
  EXPECT_FALSE(fs::exists(dir / "bad.ply"));
}

// --skip-faces and --only-faces (issue 61): the designed bevel of
// bevelled_block_mc2 (its faces listed by generate-test-meshes --bevel-faces)
// left as it came, bit for bit, the rest sharpened, the output nearer the
// exact shape than the input; the selection in the report and on the fifth
// line; bad lists refused with the line that is wrong.
TEST(Cli, SkipFacesLeavesADesignedBevelAsItCame) {
  const fs::path dir = scratch("skip_faces");
  const fs::path in = sample("bevelled_block_mc2"), out = dir / "out.ply";
  const fs::path bevel = in.parent_path() / "bevelled_block_mc2_bevel.txt";
  const fs::path reference = sample("bevelled_block_reference");
  const CliRun r = cli(quoted(in) + " " + quoted(out) + " --json --skip-faces " + quoted(bevel) +
                       " --reference " + quoted(reference));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  es::Mesh input, output;
  es::io::loadMesh(in.string(), input);
  es::io::loadMesh(out.string(), output);
  std::vector<std::size_t> bevelFaces;
  {
    std::ifstream list(bevel);
    for (std::string line; std::getline(list, line);)
      if (!line.empty() && line[0] != '#') bevelFaces.push_back(std::stoul(line));
  }
  ASSERT_GT(bevelFaces.size(), 50u);
  EXPECT_TRUE(j["selection"]["selected_faces_only"].get<bool>());
  EXPECT_EQ(j["selection"]["selected_faces"].get<std::size_t>(),
            input.face.size() - bevelFaces.size());
  EXPECT_GE(j["evidence"]["verdicts"]["outside_selection"].get<std::size_t>(), 1u);
  EXPECT_GE(j["evidence"]["verdicts"]["restored"].get<std::size_t>(), 10u);
  for (const std::size_t f : bevelFaces)
    for (int i = 0; i < 3; ++i) {
      const std::size_t v = vcg::tri::Index(input, input.face[f].cV(i));
      ASSERT_EQ(output.vert[v].cP(), input.vert[v].cP()) << "bevel vertex " << v << " moved";
    }
  EXPECT_LT(j["distance"]["after"]["max"].get<double>(),
            j["distance"]["before"]["max"].get<double>());
  EXPECT_LT(j["distance"]["after"]["rms"].get<double>(),
            j["distance"]["before"]["rms"].get<double>());

  const CliRun text = cli(quoted(in) + " " + quoted(out) + " --skip-faces " + quoted(bevel));
  ASSERT_EQ(text.exitCode, 0) << text.err;
  ASSERT_EQ(text.lines().size(), 5u) << text.out;
  EXPECT_EQ(
      text.lines()[2].rfind("selection: " + std::to_string(input.face.size() - bevelFaces.size()) +
                                " of " + std::to_string(input.face.size()) + " faces",
                            0),
      0u)
      << text.out;

  // No face listed: nothing selected, the mesh written as it came.
  const fs::path none = dir / "none.txt";
  std::ofstream(none) << "# no face\n";
  const CliRun empty = cli(quoted(in) + " " + quoted(out) + " --only-faces " + quoted(none));
  ASSERT_EQ(empty.exitCode, 0) << empty.err;
  EXPECT_NE(empty.out.find("nothing selected: the mesh is left as it came"), std::string::npos);
  es::Mesh same;
  es::io::loadMesh(out.string(), same);
  ASSERT_EQ(same.vert.size(), input.vert.size());
  ASSERT_EQ(same.face.size(), input.face.size());
  for (std::size_t v = 0; v < input.vert.size(); ++v)
    ASSERT_EQ(same.vert[v].cP(), input.vert[v].cP());

  const fs::path bad = dir / "bad.txt";
  for (const auto &[content, message] : std::vector<std::pair<std::string, std::string>>{
           {"1 2\n3 x\n", "bad.txt line 2: 'x' is not a face index"},
           {"-4\n", "line 1: '-4' is not a face index"},
           {"7000000\n", "face 7000000 does not exist (the mesh has 6460 faces)"}}) {
    std::ofstream(bad) << content;
    const CliRun e =
        cli(quoted(in) + " " + quoted(dir / "bad.ply") + " --only-faces " + quoted(bad));
    EXPECT_EQ(e.exitCode, 1) << content;
    EXPECT_NE(e.err.find(message), std::string::npos) << e.err;
    EXPECT_FALSE(fs::exists(dir / "bad.ply"));
  }
  const CliRun detect = cli(quoted(in) + " " + quoted(dir / "d.ply") +
                            " --detect-only --skip-faces " + quoted(bevel));
  EXPECT_EQ(detect.exitCode, 1);
  EXPECT_NE(detect.err.find("--skip-faces needs sharpening"), std::string::npos) << detect.err;
}
