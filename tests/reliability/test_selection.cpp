// Sharpening only a selection (issue 61, point 2): the user deselects the
// faces of a designed bevel; its features are left whole, its vertices come
// out bit for bit as they came, every other feature is sharpened as without a
// selection, and the output is not farther from the exact shape than the input.
// And what the user sees before choosing (point 1): Detect selects the faces
// Sharpen changes, and both paint each feature by its verdict.
#include <gtest/gtest.h>
#include <vcg/complex/complex.h>
// (append.h is included by complex.h)

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "edge_sharpener/colorize.h"
#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/restored_edges.h"
#include "edge_sharpener/util/mesh_types.h"
#include "mesh_distance.h"
#include "reliability/invariants.h"
#include "same_mesh.h"
#include "test_meshes/designed_faces.h"
#include "test_meshes/shapes.h"

namespace es = edge_sharpener;
namespace shapes = edge_sharpener::test_meshes;
using edge_sharpener::testing::sameMesh;
using edge_sharpener::testing::samePositions;

namespace {

void copy(es::Mesh &to, const es::Mesh &from) {
  vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(to, const_cast<es::Mesh &>(from));
}

/// bevelled_block (rotated, as in the benchmark) by marching cubes at 1% cells.
const es::Mesh &bevelledBlock() {
  static es::Mesh *mesh = [] {
    auto *m = new es::Mesh;
    const shapes::Shape &shape = shapes::shapeByName("bevelled_block");
    shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, 0.01), *m);
    return m;
  }();
  return *mesh;
}

/// A designed bevel of bevelled_block, named (an index into its designedFinishes()).
struct Bevel {
  const char *name;
  std::size_t finish;
};

void PrintTo(const Bevel &bevel, std::ostream *os) {
  *os << bevel.name;
}

std::vector<char> bevelFaces(const es::Mesh &m, const Bevel &bevel) {
  const shapes::Shape &shape = shapes::shapeByName("bevelled_block");
  const auto &prism = *shapes::finishedPrism("bevelled_block");
  return shapes::designedFaces(m, prism, {shapes::designedFinishes(prism)[bevel.finish]},
                               shapes::cellSizeForDiagonalFraction(shape, 0.01));
}

es::SharpenReport sharpenSelected(const es::Mesh &input, es::Mesh &out,
                                  const std::vector<char> &selected,
                                  es::Method method = es::Method::Auto) {
  copy(out, input);
  for (std::size_t f = 0; f < out.face.size(); ++f) {
    if (selected[f])
      out.face[f].SetS();
    else
      out.face[f].ClearS();
  }
  es::SharpenOptions opt;
  opt.method = method;
  opt.selectedFacesOnly = true;
  return es::sharpen(out, opt);
}

double maxDistance(es::Mesh &m, es::Mesh &reference) {
  es::DistanceOptions dopt;
  dopt.faceSamples = 60000;
  return es::measureDistance(m, reference, dopt).max();
}

using P = std::tuple<float, float, float>;
P key(const es::Mesh::VertexType &v) {
  return {v.cP()[0], v.cP()[1], v.cP()[2]};
}

class SelectionWithoutABevel : public ::testing::TestWithParam<Bevel> {};

TEST_P(SelectionWithoutABevel, LeavesTheBevelAndSharpensTheRest) {
  const Bevel bevel = GetParam();
  const es::Mesh &input = bevelledBlock();
  const std::vector<char> onBevel = bevelFaces(input, bevel);
  std::vector<char> selected(onBevel.size());
  std::size_t deselected = 0;
  for (std::size_t f = 0; f < selected.size(); ++f) {
    selected[f] = !onBevel[f];
    deselected += onBevel[f];
  }
  ASSERT_GT(deselected, 20u);

  es::Mesh whole, masked, in;
  copy(in, input);
  copy(whole, input);
  const es::SharpenReport rw = es::sharpen(whole);
  const es::SharpenReport r = sharpenSelected(input, masked, selected);
  EXPECT_TRUE(r.selectedFacesOnly);
  EXPECT_EQ(r.selectedFaces, input.face.size() - deselected);
  const std::size_t outside = r.evidence.count(es::Verdict::OutsideSelection);
  EXPECT_GE(outside, 1u);
  EXPECT_NE(es::formatInputNotes(r).find("selection: "), std::string::npos);

  // The bevel's vertices, bit for bit as they came.
  std::size_t bevelVertices = 0;
  std::set<std::size_t> onBevelVertex;
  for (std::size_t f = 0; f < input.face.size(); ++f)
    if (onBevel[f])
      for (int i = 0; i < 3; ++i) onBevelVertex.insert(vcg::tri::Index(input, input.face[f].cV(i)));
  for (const std::size_t v : onBevelVertex) {
    ++bevelVertices;
    EXPECT_EQ(masked.vert[v].cP(), input.vert[v].cP()) << "bevel vertex " << v << " moved";
  }
  EXPECT_GT(bevelVertices, 20u);

  // Every other feature as without a selection: the restored ones are
  // restored there too (fewer by those left for the selection and the
  // corners of those), and every vertex that moved in the whole run, away
  // from the bevel, lies where it lies there.
  const std::size_t restored = r.evidence.count(es::Verdict::Restored);
  const std::size_t restoredWhole = rw.evidence.count(es::Verdict::Restored);
  EXPECT_LT(restored, restoredWhole);
  EXPECT_GE(restored + outside + r.evidence.count(es::Verdict::CornerOfWeakEdge), restoredWhole);
  std::set<P> maskedPositions;
  for (const auto &v : masked.vert) maskedPositions.insert(key(v));
  const shapes::Shape &shape = shapes::shapeByName("bevelled_block");
  const double cell = shapes::cellSizeForDiagonalFraction(shape, 0.01);
  std::size_t compared = 0, elsewhere = 0;
  for (std::size_t v = 0; v < whole.vert.size(); ++v) {
    double nearest = 1e9;
    for (const std::size_t b : onBevelVertex)
      nearest = std::min<double>(nearest, vcg::Distance(whole.vert[v].cP(), input.vert[b].cP()));
    if (nearest < 3 * cell) continue;  // the ends of edges running into the bevel's corners
    ++compared;
    elsewhere += maskedPositions.count(key(whole.vert[v])) == 0;
  }
  EXPECT_GT(compared, input.vert.size() / 2);
  EXPECT_EQ(elsewhere, 0u) << "vertices away from the bevel placed otherwise than without a "
                              "selection";

  // Not worse than the input, and no worse than without a selection where
  // that one harms the designed bevel.
  es::Mesh reference, inputCopy;
  shapes::buildReference(shape, reference);
  copy(inputCopy, input);
  const double before = maxDistance(inputCopy, reference);
  const double after = maxDistance(masked, reference);
  EXPECT_LE(after, before * 1.001);
  std::printf(
      "SELECTION %s: %zu faces deselected, %zu features outside, %zu restored (%zu "
      "without a selection); max %.4f -> %.4f (without a selection %.4f) x diagonal\n",
      bevel.name, deselected, outside, restored, restoredWhole, before / shape.diagonal(),
      after / shape.diagonal(), maxDistance(whole, reference) / shape.diagonal());
}

// The workflow: Detect selects the faces Sharpen changes, the user deselects
// the bevel's, Sharpen affects only the selected faces. The faces Detect
// leaves unselected hold no move: the same output as with every face but the
// bevel's selected.
TEST_P(SelectionWithoutABevel, DetectThenDeselectGivesTheSame) {
  const es::Mesh &input = bevelledBlock();
  const std::vector<char> onBevel = bevelFaces(input, GetParam());
  es::Mesh detected;
  copy(detected, input);
  es::detectChamfers(detected);
  std::vector<char> detectedButBevel(onBevel.size()), allButBevel(onBevel.size());
  std::size_t selectedFaces = 0, bevelSelected = 0;
  for (std::size_t f = 0; f < onBevel.size(); ++f) {
    detectedButBevel[f] = detected.face[f].IsS() && !onBevel[f];
    allButBevel[f] = !onBevel[f];
    selectedFaces += detected.face[f].IsS();
    bevelSelected += detected.face[f].IsS() && onBevel[f];
  }
  ASSERT_GT(selectedFaces, 100u);
  ASSERT_LT(selectedFaces, input.face.size() / 2);
  EXPECT_GT(bevelSelected, 0u) << "the default restores no feature of the bevel: nothing to show";
  es::Mesh viaDetect, viaAll;
  const es::SharpenReport rd = sharpenSelected(input, viaDetect, detectedButBevel);
  const es::SharpenReport ra = sharpenSelected(input, viaAll, allButBevel);
  EXPECT_EQ(rd.evidence.count(es::Verdict::Restored), ra.evidence.count(es::Verdict::Restored));
  ASSERT_TRUE(samePositions(viaDetect, viaAll));
}

INSTANTIATE_TEST_SUITE_P(BevelledBlock, SelectionWithoutABevel,
                         ::testing::Values(Bevel{"narrow_bevel", shapes::kNarrowBevel},
                                           Bevel{"wide_bevel", shapes::kWideBevel}),
                         [](const auto &info) { return std::string(info.param.name); });

// No face selected: nothing runs, the mesh is left as it came, and the report
// says so.
TEST(Selection, NoFaceSelectedLeavesTheMesh) {
  const es::Mesh &input = bevelledBlock();
  es::Mesh out;
  const es::SharpenReport r = sharpenSelected(input, out, std::vector<char>(input.face.size(), 0));
  EXPECT_EQ(r.selectedFaces, 0u);
  ASSERT_TRUE(sameMesh(out, input));
  EXPECT_NE(es::formatVerdictSummary(r).find("nothing selected"), std::string::npos);
}

// Every face selected: the same output as without a selection, every method.
TEST(Selection, EveryFaceSelectedIsTheWholeRun) {
  const es::Mesh &input = bevelledBlock();
  for (const es::Method method : {es::Method::Paper, es::Method::Extended, es::Method::Auto}) {
    SCOPED_TRACE(int(method));
    es::Mesh whole, all;
    copy(whole, input);
    es::SharpenOptions opt;
    opt.method = method;
    es::sharpen(whole, opt);
    sharpenSelected(input, all, std::vector<char>(input.face.size(), 1), method);
    ASSERT_TRUE(samePositions(all, whole));
    ASSERT_EQ(all.face.size(), whole.face.size());
  }
}

// The paper and extended methods judge no feature: the faces outside the
// selection are neither split nor moved (same vertices, bit-identical
// positions), the selected ones are sharpened.
TEST(Selection, PaperAndExtendedKeepEveryFaceOutsideIt) {
  const es::Mesh &input = bevelledBlock();
  const std::vector<char> onBevel = bevelFaces(input, Bevel{"wide_bevel", shapes::kWideBevel});
  std::vector<char> selected(onBevel.size());
  for (std::size_t f = 0; f < selected.size(); ++f) selected[f] = !onBevel[f];
  std::set<std::array<std::size_t, 3>> unselected;
  for (std::size_t f = 0; f < input.face.size(); ++f)
    if (!selected[f])
      unselected.insert({vcg::tri::Index(input, input.face[f].cV(0)),
                         vcg::tri::Index(input, input.face[f].cV(1)),
                         vcg::tri::Index(input, input.face[f].cV(2))});
  for (const es::Method method : {es::Method::Paper, es::Method::Extended}) {
    SCOPED_TRACE(int(method));
    es::Mesh out, in;
    copy(in, input);
    const es::SharpenReport r = sharpenSelected(input, out, selected, method);
    if (method == es::Method::Paper) {  // (its check takes original vertices as never moving)
      EXPECT_EQ(es_reliability::sharpenProblem(in, out, r, es::SharpenOptions().degenerateAngleRad),
                "");
    }
    EXPECT_GT(r.outputVertices, r.inputVertices) << "nothing was sharpened";
    std::set<std::array<std::size_t, 3>> outFaces;
    for (const auto &f : out.face)
      if (!f.IsD())
        outFaces.insert({vcg::tri::Index(out, f.cV(0)), vcg::tri::Index(out, f.cV(1)),
                         vcg::tri::Index(out, f.cV(2))});
    for (const auto &face : unselected) {
      ASSERT_EQ(outFaces.count(face), 1u) << "a face outside the selection was split";
      for (const std::size_t v : face) ASSERT_EQ(out.vert[v].cP(), input.vert[v].cP());
    }
  }
}

// Detect's selection, taken as it is: Sharpen does with it what it does
// without a selection (the faces it leaves unselected hold no move), and
// says what Sharpen would do, the mesh unchanged.
TEST(Detect, ItsSelectionIsWhatSharpenChanges) {
  const es::Mesh &input = bevelledBlock();
  es::Mesh detected, whole;
  copy(detected, input);
  copy(whole, input);
  const es::SharpenReport rd = es::detectChamfers(detected);
  const es::SharpenReport rw = es::sharpen(whole);
  EXPECT_FALSE(rd.geometryChanged);
  EXPECT_EQ(rd.evidence.verdicts, rw.evidence.verdicts);
  for (std::size_t v = 0; v < input.vert.size(); ++v)
    ASSERT_EQ(detected.vert[v].cP(), input.vert[v].cP());
  std::vector<char> selected(input.face.size());
  for (std::size_t f = 0; f < selected.size(); ++f) selected[f] = detected.face[f].IsS();
  EXPECT_EQ(rd.detectedFaces, std::size_t(std::count(selected.begin(), selected.end(), 1)));
  EXPECT_NE(es::formatVerdictSummary(rd).find("detected, as Sharpen judges them: features: "),
            std::string::npos);
  es::Mesh viaDetect;
  sharpenSelected(input, viaDetect, selected);
  ASSERT_TRUE(samePositions(viaDetect, whole));
  ASSERT_EQ(viaDetect.face.size(), whole.face.size());
}

// A selection with no feature in it: the faces Detect leaves unselected,
// those Sharpen does not change. The mesh comes back as it came, and the
// report says every feature was left for the selection.
TEST(Detect, ItsComplementChangesNothing) {
  const es::Mesh &input = bevelledBlock();
  es::Mesh detected;
  copy(detected, input);
  es::detectChamfers(detected);
  std::vector<char> complement(input.face.size());
  for (std::size_t f = 0; f < complement.size(); ++f) complement[f] = !detected.face[f].IsS();
  es::Mesh out;
  const es::SharpenReport r = sharpenSelected(input, out, complement);
  EXPECT_EQ(r.evidence.count(es::Verdict::Restored), 0u);
  EXPECT_GT(r.evidence.count(es::Verdict::OutsideSelection), 0u);
  EXPECT_NE(es::formatVerdictSummary(r).find("outside the selection"), std::string::npos)
      << es::formatVerdictSummary(r);
  ASSERT_TRUE(sameMesh(out, input));
}

// The verdict colours: one per verdict and one for no feature, all distinct,
// so the legend reads each; where a face belongs to several features, a
// restored one wins.
TEST(VerdictColors, DistinctAndRestoredFirst) {
  std::set<std::tuple<int, int, int>> seen{
      {es::noFeatureColor()[0], es::noFeatureColor()[1], es::noFeatureColor()[2]}};
  for (int i = 0; i < es::kVerdictCount; ++i) {
    const vcg::Color4b c = es::verdictColor(es::Verdict(i));
    EXPECT_TRUE(seen.insert({c[0], c[1], c[2]}).second) << es::toString(es::Verdict(i));
  }
  const auto restored = std::int8_t(es::Verdict::Restored);
  const auto weak = std::int8_t(es::Verdict::OffItsPlanes);
  EXPECT_EQ(es::firstVerdict(weak, restored), restored);
  EXPECT_EQ(es::firstVerdict(restored, weak), restored);
  EXPECT_EQ(es::firstVerdict(es::kNoVerdict, weak), weak);
  EXPECT_EQ(es::firstVerdict(weak, es::kNoVerdict), weak);
  std::vector<es::FeatureRecord> features(2);
  features[0].verdict = es::Verdict::OffItsPlanes;
  features[0].faces = {1, 2};
  features[1].verdict = es::Verdict::Restored;
  features[1].faces = {2, 3, 9};  // 9: beyond the faces, ignored
  EXPECT_EQ(es::featureFaceVerdicts(features, 5),
            (es::FaceVerdicts{es::kNoVerdict, weak, restored, restored, es::kNoVerdict}));
}

std::size_t facesOfColor(const es::Mesh &m, const vcg::Color4b &c) {
  std::size_t n = 0;
  for (const auto &f : m.face) n += !f.IsD() && f.cC() == c;
  return n;
}

// Sharpen --colorize by verdict: the colours change no position; every face
// with a vertex placed on a sharp edge is restored green (or already-sharp
// blue); the features left show their reasons. Detect paints the input's
// faces from the same verdicts.
TEST(VerdictColors, PaintWhatTheRunDid) {
  const es::Mesh &input = bevelledBlock();
  es::Mesh plain, painted, detected;
  copy(plain, input);
  copy(painted, input);
  copy(detected, input);
  es::SharpenOptions opt;
  const es::SharpenReport r = es::sharpen(plain, opt);
  opt.colorize = true;
  auto restoredAttr = vcg::tri::Allocator<es::Mesh>::AddPerVertexAttribute<std::uint8_t>(
      painted, es::kRestoredVertexAttribute);
  es::sharpen(painted, opt);
  ASSERT_TRUE(samePositions(painted, plain));
  const vcg::Color4b green = es::verdictColor(es::Verdict::Restored);
  const vcg::Color4b blue = es::verdictColor(es::Verdict::AlreadySharp);
  std::size_t onRestored = 0;
  for (const auto &f : painted.face) {
    bool restoredVertex = false;
    for (int i = 0; i < 3; ++i) restoredVertex = restoredVertex || restoredAttr[f.cV(i)];
    if (!restoredVertex) continue;
    ++onRestored;
    EXPECT_TRUE(f.cC() == green || f.cC() == blue) << "face " << vcg::tri::Index(painted, f);
  }
  EXPECT_GT(onRestored, 100u);
  std::size_t leftVerdicts = 0, leftFaces = 0;
  for (int i = 1; i < es::kVerdictCount; ++i) {
    const std::size_t n = facesOfColor(painted, es::verdictColor(es::Verdict(i)));
    leftFaces += n;
    leftVerdicts += r.evidence.verdicts[i] > 0;
    if (r.evidence.verdicts[i] == 0) {
      EXPECT_EQ(n, 0u) << es::toString(es::Verdict(i));
    }
  }
  EXPECT_GT(leftVerdicts, 0u) << "bevelled_block has features left: the test needs them";
  EXPECT_GT(leftFaces, 0u);
  EXPECT_GT(facesOfColor(painted, es::noFeatureColor()), painted.face.size() / 2);

  es::detectChamfers(detected);
  const es::FaceVerdicts verdicts = es::featureFaceVerdicts(r.features, input.face.size());
  for (std::size_t f = 0; f < input.face.size(); ++f) {
    const vcg::Color4b expected = verdicts[f] == es::kNoVerdict
                                      ? es::noFeatureColor()
                                      : es::verdictColor(es::Verdict(verdicts[f]));
    ASSERT_EQ(detected.face[f].cC(), expected) << "face " << f;
  }
  vcg::tri::Allocator<es::Mesh>::DeletePerVertexAttribute(painted, restoredAttr);
}

// The paper's palette stays available: with colors = paper, Detect paints
// the zone labels as the extended method's Detect does, and selects what
// the default changes all the same.
TEST(VerdictColors, PaperPaletteOnRequest) {
  const es::Mesh &input = bevelledBlock();
  es::Mesh byVerdict, byPaper, extended;
  copy(byVerdict, input);
  copy(byPaper, input);
  copy(extended, input);
  es::detectChamfers(byVerdict);
  es::SharpenOptions opt;
  opt.colors = es::ColorScheme::Paper;
  es::detectChamfers(byPaper, opt);
  opt.method = es::Method::Extended;
  es::detectChamfers(extended, opt);
  std::size_t red = 0;
  for (std::size_t f = 0; f < input.face.size(); ++f) {
    ASSERT_EQ(byPaper.face[f].cC(), extended.face[f].cC()) << "face " << f;
    ASSERT_EQ(byPaper.face[f].IsS(), byVerdict.face[f].IsS()) << "face " << f;
    red += byPaper.face[f].cC() == es::faceLabelColor(es::FaceLabel::Red);
  }
  EXPECT_GT(red, input.face.size() / 2);
}

}  // namespace
