// Bad and unusual inputs (issue 6): every file of tests/reliability/bad_inputs/
// through the readers + core (in process) and through the two CLIs (as a user
// runs them). Each gets a clear error or a correct result, never a crash, and
// the input file is never modified.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/restored_edges.h"
#include "edge_sharpener/util/mesh_types.h"
#include "mesh_io.h"
#include "reliability/invariants.h"

namespace es = edge_sharpener;
namespace fs = std::filesystem;
using es_reliability::sharpenProblem;

namespace {

enum class Outcome {
  LoadError,  ///< the reader refuses the file (one-line message)
  Refused,    ///< read, but the core refuses it (InputError, mesh untouched)
  Processed,  ///< sharpened; the result keeps every invariant
};

struct BadInput {
  const char *file;
  Outcome outcome;
  const char *message;  ///< substring of the error (LoadError/Refused)
  int faces;            ///< faces after loading (-1: not checked)
};

std::ostream &operator<<(std::ostream &os, const BadInput &b) {
  return os << b.file;
}

// The table docs/reliability.md reproduces, in runs of files with the same outcome: the
// message (a substring of the error, LoadError/Refused) and the faces after loading (-1: not
// checked).
std::vector<BadInput> badInputs() {
  std::vector<BadInput> rows;
  const auto add = [&](Outcome outcome, const char *message, int faces,
                       std::initializer_list<const char *> files) {
    for (const char *file : files) rows.push_back({file, outcome, message, faces});
  };
  add(Outcome::LoadError, "empty file", -1, {"empty.ply", "empty.off", "empty.obj", "empty.stl"});
  add(Outcome::LoadError, "cannot read mesh", -1,
      {"garbage.ply", "garbage.off", "garbage.obj", "garbage.stl", "garbage_header.ply",
       "garbage_counts.off", "garbage_text.obj", "truncated.ply", "truncated_binary.ply",
       "truncated.off", "truncated.obj", "truncated_binary.stl", "overdeclared_binary.stl"});
  add(Outcome::Refused, "NaN or infinite", 4, {"nan.off", "inf.obj", "nan.ply"});
  add(Outcome::Refused, "point cloud", 0, {"pointcloud.ply", "pointcloud.obj"});
  add(Outcome::LoadError, "cannot read mesh", -1,
      {"out_of_range.off", "out_of_range.obj", "negative_index.ply", "out_of_range_binary.ply"});
  add(Outcome::LoadError, "out of range", -1, {"polygon_out_of_range.ply"});
  add(Outcome::LoadError, "fewer than 3 vertices", -1, {"polygon_short.ply"});
  add(Outcome::Processed, "", 12, {"cube_big_endian.ply"});
  add(Outcome::Processed, "", 4, {"tetra_tristrips.ply"});
  add(Outcome::Processed, "", 14, {"zero_area_face.off"});
  add(Outcome::Refused, "repeats a vertex", 5, {"repeated_vertex_face.off"});
  add(Outcome::Processed, "", 5, {"duplicate_face.off", "duplicate_face_flipped.obj"});
  add(Outcome::Processed, "", 12, {"duplicate_vertex.off", "unreferenced_vertices.off"});
  add(Outcome::Processed, "", 3, {"nonmanifold_edge.off"});
  add(Outcome::Processed, "", 8, {"nonmanifold_vertex.off"});
  add(Outcome::Refused, "consistently oriented", 4, {"inconsistent_orientation.off"});
  add(Outcome::Processed, "", 10, {"open_box.off"});
  add(Outcome::Processed, "", 16, {"two_components.obj"});
  add(Outcome::Processed, "", 12, {"quads.off", "quads.obj", "quads.ply"});
  add(Outcome::Processed, "", 16, {"pentagonal_prism.obj"});
  add(Outcome::Processed, "", 1, {"one_triangle.off"});
  add(Outcome::Processed, "", 4, {"tetra_binary.stl"});
  return rows;
}

const std::vector<BadInput> kBadInputs = badInputs();

std::string dataDir() {
  return std::string(EDGE_SHARPENER_SOURCE_DIR) + "/tests/reliability/bad_inputs/";
}

std::string readBytes(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// A fresh scratch directory for one test.
fs::path scratchDir(const std::string &name) {
  const fs::path dir =
      fs::temp_directory_path() / ("es-reliability-" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

struct RunResult {
  int exitCode = -1;  ///< -1 when killed by a signal
  int signal = 0;
  std::string stderrText;
};

/// Runs a shell command; stderr captured through a file.
RunResult run(const std::string &command, const fs::path &errFile) {
  RunResult r;
  const int status = std::system((command + " >/dev/null 2>'" + errFile.string() + "'").c_str());
  if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.stderrText = readBytes(errFile.string());
  return r;
}

class BadInputFile : public ::testing::TestWithParam<BadInput> {};

}  // namespace

// All files in the folder are in the table (and vice versa).
TEST(ReliabilityBadInput, TableCoversEveryFile) {
  std::vector<std::string> listed, present;
  for (const BadInput &b : kBadInputs) listed.push_back(b.file);
  for (const auto &e : fs::directory_iterator(dataDir()))
    if (e.path().extension() != ".py") present.push_back(e.path().filename().string());
  std::sort(listed.begin(), listed.end());
  std::sort(present.begin(), present.end());
  EXPECT_EQ(listed, present);
}

// In process: reader, then core.
TEST_P(BadInputFile, ReaderAndCore) {
  const BadInput b = GetParam();
  const std::string path = dataDir() + b.file;
  const std::string bytes = readBytes(path);
  es::Mesh m;
  std::string loadError;
  try {
    es::io::loadMesh(path, m);
  } catch (const std::runtime_error &e) {
    loadError = e.what();
  }
  EXPECT_EQ(readBytes(path), bytes) << "reading modified the file";
  if (b.outcome == Outcome::LoadError) {
    ASSERT_FALSE(loadError.empty()) << "loaded " << m.fn << " faces";
    EXPECT_NE(loadError.find(b.message), std::string::npos) << loadError;
    EXPECT_EQ(loadError.find('\n'), std::string::npos) << "not one line: " << loadError;
    return;
  }
  ASSERT_TRUE(loadError.empty()) << loadError;
  if (b.faces >= 0) {
    EXPECT_EQ(m.fn, b.faces);
  }

  es::Mesh input, work;
  vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(input, m);
  vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(work, m);
  vcg::tri::UpdateTopology<es::Mesh>::FaceFace(work);
  const es::SharpenOptions opt;
  if (b.outcome == Outcome::Refused) {
    EXPECT_NE(es::findInputProblem(work), "");
    try {
      es::sharpen(work, opt);
      FAIL() << "sharpen accepted " << b.file;
    } catch (const es::InputError &e) {
      EXPECT_NE(std::string(e.what()).find(b.message), std::string::npos) << e.what();
    }
    EXPECT_TRUE(es_reliability::identical(work, input)) << "a refused mesh was modified";
    return;
  }
  const es::SharpenReport r = es::sharpen(work, opt);
  EXPECT_EQ(sharpenProblem(input, work, r, opt.degenerateAngleRad), "");
}

// As a user runs it: the CLI exits 0 with an output, or 1 with a one-line
// "edge-sharpener: error: ..." and no output; never a signal; input unchanged.
TEST_P(BadInputFile, SharpenerCli) {
  const BadInput b = GetParam();
  const fs::path dir = scratchDir(std::string("cli-") + b.file);
  // Work on a copy, read-only, so even a rogue write would be caught.
  const fs::path input = dir / b.file;
  fs::copy_file(dataDir() + b.file, input);
  fs::permissions(input, fs::perms::owner_read | fs::perms::group_read);
  const std::string bytes = readBytes(input.string());
  struct stat before {};
  ASSERT_EQ(::stat(input.c_str(), &before), 0);

  const fs::path output = dir / "out.ply";
  const RunResult r = run(std::string("'") + EDGE_SHARPENER_CLI + "' --quiet '" + input.string() +
                              "' '" + output.string() + "'",
                          dir / "stderr.txt");
  ASSERT_EQ(r.signal, 0) << "killed by signal " << r.signal << ": " << r.stderrText;
  EXPECT_EQ(readBytes(input.string()), bytes);
  struct stat after {};
  ASSERT_EQ(::stat(input.c_str(), &after), 0);
  EXPECT_EQ(before.st_mtim.tv_sec, after.st_mtim.tv_sec);
  EXPECT_EQ(before.st_mtim.tv_nsec, after.st_mtim.tv_nsec);
  for (const auto &e : fs::directory_iterator(dir))
    EXPECT_TRUE(e.path() == input || e.path() == output || e.path().filename() == "stderr.txt")
        << "stray file " << e.path();

  if (b.outcome == Outcome::Processed) {
    EXPECT_EQ(r.exitCode, 0) << r.stderrText;
    EXPECT_TRUE(fs::exists(output));
    es::Mesh out;
    es::io::loadMesh(output.string(), out);
    EXPECT_GE(out.fn, b.faces);
  } else {
    EXPECT_EQ(r.exitCode, 1) << r.stderrText;
    EXPECT_FALSE(fs::exists(output));
    EXPECT_EQ(r.stderrText.rfind("edge-sharpener: error: ", 0), 0u) << r.stderrText;
    EXPECT_NE(r.stderrText.find(b.message), std::string::npos) << r.stderrText;
    EXPECT_EQ(std::count(r.stderrText.begin(), r.stderrText.end(), '\n'), 1) << r.stderrText;
  }
  fs::permissions(input, fs::perms::owner_all);
}

// mesh-distance: the bad file as either side; a clear error or a result, never a crash.
TEST_P(BadInputFile, DistanceCli) {
  const BadInput b = GetParam();
  const fs::path dir = scratchDir(std::string("dist-") + b.file);
  const std::string good = dataDir() + "quads.off";
  const std::string bad = dataDir() + b.file;
  const std::string bytes = readBytes(bad);
  for (int side = 0; side < 2; ++side) {
    const std::string a = side == 0 ? bad : good, ref = side == 0 ? good : bad;
    const RunResult r =
        run(std::string("'") + MESH_DISTANCE_CLI + "' --samples 2000 '" + a + "' '" + ref + "'",
            dir / "stderr.txt");
    ASSERT_EQ(r.signal, 0) << "killed by signal " << r.signal << ": " << r.stderrText;
    // Measurable: at least one face and finite coordinates.
    const bool measurable = b.outcome == Outcome::Processed ||
                            (b.outcome == Outcome::Refused && b.faces > 0 &&
                             std::string(b.message).find("NaN") == std::string::npos);
    if (measurable) {
      EXPECT_EQ(r.exitCode, 0) << r.stderrText;
    } else {
      EXPECT_EQ(r.exitCode, 1) << r.stderrText;
    }
  }
  EXPECT_EQ(readBytes(bad), bytes);
}

INSTANTIATE_TEST_SUITE_P(Files, BadInputFile, ::testing::ValuesIn(kBadInputs),
                         [](const ::testing::TestParamInfo<BadInput> &info) {
                           std::string n = info.param.file;
                           std::replace(n.begin(), n.end(), '.', '_');
                           return n;
                         });

// A scan or a coloured remesh keeps its vertex colours: the PLY's colours are
// read, written back, and the new vertices take their sources' mean colour
// (vcglib would make them white). Blue is 7 on every input vertex, so on every
// output vertex too.
TEST(ReliabilityUnusualInput, CliKeepsAPlysVertexColours) {
  const fs::path dir = scratchDir("colours");
  es::Mesh m;
  es::io::loadMesh(std::string(EDGE_SHARPENER_SOURCE_DIR) + "/test_meshes/generated/lblock_mc2.ply",
                   m);
  vcg::tri::UpdateBounding<es::Mesh>::Box(m);
  for (auto &v : m.vert) {
    const auto t = (v.cP() - m.bbox.min) / m.bbox.Diag();
    v.C() = vcg::Color4b(static_cast<unsigned char>(250 * t[0]),
                         static_cast<unsigned char>(250 * t[1]), 7, 255);
  }
  const fs::path input = dir / "coloured.ply", output = dir / "out.ply";
  es::io::saveMesh(m, input.string(), vcg::tri::io::Mask::IOM_VERTCOLOR);
  const RunResult r = run(std::string("'") + EDGE_SHARPENER_CLI + "' --quiet '" + input.string() +
                              "' '" + output.string() + "'",
                          dir / "stderr.txt");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  es::Mesh out;
  EXPECT_EQ(es::io::loadMesh(output.string(), out), vcg::tri::io::Mask::IOM_VERTCOLOR);
  ASSERT_GT(out.vn, m.vn);  // sharpened: vertices were added
  int red = 0;
  for (const auto &v : out.vert) {
    EXPECT_EQ(v.cC()[2], 7);
    EXPECT_EQ(v.cC()[3], 255);
    red = std::max(red, int(v.cC()[0]));
  }
  EXPECT_GT(red, 100);  // the gradient came through
  // Unmoved input vertices keep their colours exactly.
  std::map<std::array<float, 3>, vcg::Color4b> colourAt;
  for (const auto &v : m.vert) colourAt[{v.cP()[0], v.cP()[1], v.cP()[2]}] = v.cC();
  std::size_t unmoved = 0;
  for (const auto &v : out.vert) {
    const auto it = colourAt.find({v.cP()[0], v.cP()[1], v.cP()[2]});
    if (it == colourAt.end()) continue;
    ++unmoved;
    EXPECT_EQ(v.cC(), it->second);
  }
  EXPECT_GT(unmoved, std::size_t(m.vn) / 2);
}

// --sharp-edges writes the restored sharp edges as OBJ lines: on a marching-cubes
// cube they run along the cube's twelve edges, and they are the edges the core
// reports for the same input (restoredEdges).
TEST(ReliabilityUnusualInput, CliWritesTheRestoredSharpEdges) {
  const fs::path dir = scratchDir("sharp-edges");
  const std::string generated = std::string(EDGE_SHARPENER_SOURCE_DIR) + "/test_meshes/generated/";
  const fs::path input = dir / "cube.ply", output = dir / "out.ply", edges = dir / "edges.obj";
  fs::copy_file(generated + "cube_mc2.ply", input);
  const RunResult r = run(std::string("'") + EDGE_SHARPENER_CLI + "' --quiet '" + input.string() +
                              "' '" + output.string() + "' --sharp-edges '" + edges.string() + "'",
                          dir / "stderr.txt");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  ASSERT_TRUE(fs::exists(output));

  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 2>> lines;
  std::ifstream obj(edges);
  for (std::string kind; obj >> kind;) {
    if (kind == "v") {
      std::array<double, 3> p{};
      obj >> p[0] >> p[1] >> p[2];
      points.push_back(p);
    } else if (kind == "l") {
      std::array<std::size_t, 2> l{};
      obj >> l[0] >> l[1];
      lines.push_back(l);
    } else {
      obj.ignore(std::numeric_limits<std::streamsize>::max(), '\n');  // a comment
    }
  }
  ASSERT_FALSE(lines.empty());

  // The same input sharpened in process: the core's restored edges.
  es::Mesh m;
  es::io::loadMesh(input.string(), m);
  vcg::tri::UpdateTopology<es::Mesh>::FaceFace(m);
  auto h = vcg::tri::Allocator<es::Mesh>::AddPerVertexAttribute<std::uint8_t>(
      m, es::kRestoredVertexAttribute);
  es::sharpen(m, es::SharpenOptions{});
  std::vector<std::uint8_t> restored(m.vert.size());
  for (std::size_t v = 0; v < m.vert.size(); ++v) restored[v] = h[v];
  vcg::tri::Allocator<es::Mesh>::DeletePerVertexAttribute(m, h);
  EXPECT_EQ(lines.size(), es::restoredEdges(m, restored).size());

  // Every point lies on one of the reference cube's edges (two of its faces),
  // every line joins two points of one edge, and each of the twelve has some.
  es::Mesh cube;
  es::io::loadMesh(generated + "cube_reference.ply", cube);
  vcg::tri::UpdateBounding<es::Mesh>::Box(cube);
  const double tolerance = 1e-3 * cube.bbox.Diag();  // a twentieth of the cell (2% of it)
  const auto facesOf = [&](const std::array<double, 3> &p) {
    std::array<int, 3> side{};  // -1 / +1 on the box's low / high face of each axis, else 0
    for (int c = 0; c < 3; ++c) {
      if (std::abs(p[c] - cube.bbox.min[c]) <= tolerance) side[c] = -1;
      if (std::abs(p[c] - cube.bbox.max[c]) <= tolerance) side[c] = 1;
    }
    return side;
  };
  std::vector<char> used(points.size(), 0);
  std::map<std::array<int, 3>, int> linesPerEdge;
  for (const auto &[a, b] : lines) {
    ASSERT_TRUE(a >= 1 && a <= points.size() && b >= 1 && b <= points.size());
    used[a - 1] = used[b - 1] = 1;
    const auto sa = facesOf(points[a - 1]), sb = facesOf(points[b - 1]);
    std::array<int, 3> common{};
    int shared = 0;
    for (int c = 0; c < 3; ++c)
      if (sa[c] != 0 && sa[c] == sb[c]) common[c] = sa[c], ++shared;
    EXPECT_GE(shared, 2) << "a line off the cube's edges";
    if (shared == 2) ++linesPerEdge[common];
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_TRUE(used[i]) << "point " << i + 1 << " on no line";
    const auto s = facesOf(points[i]);
    EXPECT_GE(std::count_if(s.begin(), s.end(), [](int x) { return x != 0; }), 2)
        << "point " << i + 1 << " off the cube's edges";
  }
  EXPECT_EQ(linesPerEdge.size(), 12u);
}

// --sharp-edges needs a sharpening and a file of its own: refused before
// anything is written.
TEST(ReliabilityBadInput, CliSharpEdgesNeedSharpeningAndTheirOwnFile) {
  const fs::path dir = scratchDir("sharp-edges-refused");
  const fs::path input = dir / "cube.ply", output = dir / "out.ply";
  fs::copy_file(std::string(EDGE_SHARPENER_SOURCE_DIR) + "/test_meshes/generated/cube_mc2.ply",
                input);
  const std::string bytes = readBytes(input.string());
  const std::string cli = std::string("'") + EDGE_SHARPENER_CLI + "' '" + input.string() + "' '" +
                          output.string() + "' --sharp-edges ";
  const struct {
    std::string arguments, message;
  } cases[] = {
      {"'" + (dir / "e.obj").string() + "' --detect-only", "needs sharpening"},
      {"'" + output.string() + "'", "the output are the same file"},
      {"'" + input.string() + "'", "overwrite the input"},
      {"'" + (dir / "missing" / "e.obj").string() + "'", "cannot write"},
  };
  for (const auto &c : cases) {
    const RunResult r = run(cli + c.arguments, dir / "stderr.txt");
    EXPECT_EQ(r.exitCode, 1) << c.arguments;
    EXPECT_NE(r.stderrText.find(c.message), std::string::npos) << r.stderrText;
    EXPECT_FALSE(fs::exists(output)) << c.arguments;
    EXPECT_FALSE(fs::exists(dir / "e.obj")) << c.arguments;
    EXPECT_EQ(readBytes(input.string()), bytes);
  }
}

// Colours as floats in [0, 1] (some writers), alpha absent: read as bytes,
// alpha opaque; out of range or not finite, clamped.
TEST(ReliabilityUnusualInput, PlyFloatColoursAreReadAsBytes) {
  const fs::path dir = scratchDir("float-colours");
  const fs::path path = dir / "float_colours.ply";
  std::ofstream(path) << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                         "property float y\nproperty float z\nproperty float red\n"
                         "property float green\nproperty float blue\nelement face 1\n"
                         "property list uchar int vertex_indices\nend_header\n"
                         "0 0 0 1 0.5 0\n1 0 0 2 -1 nan\n0 1 0 0.2 0.2 0.2\n3 0 1 2\n";
  es::Mesh m;
  EXPECT_EQ(es::io::loadMesh(path.string(), m), vcg::tri::io::Mask::IOM_VERTCOLOR);
  ASSERT_EQ(m.vn, 3);
  EXPECT_EQ(m.vert[0].cC(), vcg::Color4b(255, 128, 0, 255));
  EXPECT_EQ(m.vert[1].cC(), vcg::Color4b(255, 0, 0, 255));
  EXPECT_EQ(m.vert[2].cC(), vcg::Color4b(51, 51, 51, 255));
}

// Colours in the text formats: COFF (bytes, or floats after an N header's
// normal), OBJ's "v x y z r g b" (vertices without one: white).
TEST(ReliabilityUnusualInput, OffAndObjColoursAreRead) {
  const fs::path dir = scratchDir("text-colours");
  const std::string triangle = "3 0 1 2\n";
  std::ofstream(dir / "bytes.off") << "COFF\n3 1 0\n0 0 0 255 128 0 255\n1 0 0 10 20 30\n"
                                      "0 1 0 0 0 0 0\n"
                                   << triangle;
  std::ofstream(dir / "floats.off") << "CNOFF\n3 1 0\n0 0 0 0 0 1 1.0 0.5 0.0 1.0\n"
                                       "1 0 0 0 0 1 0.2 0.2 0.2 1.0\n0 1 0 0 0 1 0 0 0 0.5\n"
                                    << triangle;
  std::ofstream(dir / "colours.obj") << "v 0 0 0\nv 1 0 0 1.0 0.5 0.0\nv 0 1 0 0.2 0.2 0.2\n"
                                        "f 1 2 3\n";
  const vcg::Color4b expected[3][3] = {
      {vcg::Color4b(255, 128, 0, 255), vcg::Color4b(10, 20, 30, 255), vcg::Color4b(0, 0, 0, 0)},
      {vcg::Color4b(255, 128, 0, 255), vcg::Color4b(51, 51, 51, 255), vcg::Color4b(0, 0, 0, 128)},
      {vcg::Color4b(255, 255, 255, 255), vcg::Color4b(255, 128, 0, 255),
       vcg::Color4b(51, 51, 51, 255)}};
  const char *files[3] = {"bytes.off", "floats.off", "colours.obj"};
  for (int k = 0; k < 3; ++k) {
    es::Mesh m;
    EXPECT_EQ(es::io::loadMesh((dir / files[k]).string(), m), vcg::tri::io::Mask::IOM_VERTCOLOR)
        << files[k];
    ASSERT_EQ(m.vn, 3) << files[k];
    for (int v = 0; v < 3; ++v) EXPECT_EQ(m.vert[v].cC(), expected[k][v]) << files[k] << " " << v;
  }
  std::ofstream(dir / "plain.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n" << triangle;
  std::ofstream(dir / "uncoloured.off") << "COFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n" << triangle;
  es::Mesh m;
  EXPECT_EQ(es::io::loadMesh((dir / "plain.off").string(), m), 0);
  EXPECT_THROW(es::io::loadMesh((dir / "uncoloured.off").string(), m), std::runtime_error);
}

// The CLI refuses to write over its input, and leaves it intact.
TEST(ReliabilityBadInput, CliNeverOverwritesItsInput) {
  const fs::path dir = scratchDir("overwrite");
  const fs::path input = dir / "quads.off";
  fs::copy_file(dataDir() + "quads.off", input);
  const std::string bytes = readBytes(input.string());
  const fs::path link = dir / "link.off";
  fs::create_symlink(input, link);
  for (const fs::path &out : {input, link}) {
    const RunResult r = run(
        std::string("'") + EDGE_SHARPENER_CLI + "' '" + input.string() + "' '" + out.string() + "'",
        dir / "stderr.txt");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.stderrText.find("overwrite the input"), std::string::npos) << r.stderrText;
    EXPECT_EQ(readBytes(input.string()), bytes);
  }
}
