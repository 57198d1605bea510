// The study behind the auto method's evidence guard (feature_evidence.h):
// sharpens an input as the auto method does but with the guard not reverting
// anything, and prints one JSON line per feature with its evidence (Feature)
// and what its moves did against the true shape: the summed and the largest
// change of the moved vertices' distance to the reference, in sample
// spacings (negative: closer). bench/study/evidence_study.py runs it over the
// quality benchmark's cached inputs of one half.
// With --vertices it prints one line per moved inserted vertex of a feature
// the guard keeps instead: its move and lift, and its own change of distance
// to the reference (a per-vertex bound's study); for an edge vertex also how
// far its rest position lies from its two sources' planes, the angle they
// meet at, and how far the move runs along their line (a target on other
// planes than the fits': the own planes of onRegionPlanes).
// With --sources it prints one line per (feature, source vertex) pair
// instead: where the source lies, how far from its own plane and from the
// nearest plane of the vertex's other sources (both in sample spacings), and
// the feature's verdicts: a sampler's cut between two flanks lies as far from
// either plane, a blend's sample absorbed by one flank's region nearer its own.
// With both planes' signed distances and normals, each line is a sample of
// the feature's cross-section (util/fillet_fit.h: the fillet study).
//   evidence-study INPUT REFERENCE [CASE-NAME] [--vertices | --sources]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <set>
#include <string>

#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/util/mesh_types.h"
#include "mesh_distance.h"
#include "mesh_io.h"

namespace es = edge_sharpener;

/// --sources: one JSON line per (feature, source vertex) pair, each pair once.
template <class MeshType>
void printSources(const std::string &name, const MeshType &m,
                  const es::VertexMoves<MeshType> &moves, const es::SupportPlanes &support,
                  const std::vector<std::uint32_t> &featureOf,
                  const std::vector<es::Feature> &features, const std::vector<char> &weak,
                  const std::vector<char> &weakOtherwise) {
  const es::SplitPlan &plan = moves.plan();
  const double spacing = es::spacingUnit(support);
  const auto offPlane = [&](const es::Plane &pl, std::size_t s) {
    return std::abs(pl.normal * (moves.exactRest(s) - pl.point)) / spacing;
  };
  std::set<std::pair<std::uint32_t, std::size_t>> seen;
  for (std::size_t k = 0; k < featureOf.size(); ++k) {
    if (m.vert[moves.firstInserted() + k].IsD()) continue;
    const es::InsertedVertexSource &source = plan.inserted[k];
    for (int i = 0; i < source.originalCount; ++i) {
      const std::size_t s = source.original[i];
      const es::Plane &own = support.plane(s);
      if (own.normal.SquaredNorm() == 0 || !seen.insert({featureOf[k], s}).second) continue;
      double other = -1;       // the nearest other source's plane; -1: none
      double otherCos = 1;     // the cosine of the angle between the two planes' normals
      double otherSigned = 0;  // the signed distance from that plane (positive: along its normal)
      es::Vec3 otherNormal(0, 0, 0);
      const es::Vec3 p = moves.exactRest(s);
      for (int j = 0; j < source.originalCount; ++j) {
        const es::Plane &pl = support.plane(source.original[j]);
        if (j == i || pl.normal.SquaredNorm() == 0) continue;
        const double signedDistance = pl.normal * (p - pl.point) / spacing;
        if (other < 0 || std::abs(signedDistance) < other) {
          other = std::abs(signedDistance);
          otherCos = pl.normal * own.normal;
          otherSigned = signedDistance;
          otherNormal = pl.normal;
        }
      }
      const std::uint32_t c = featureOf[k];
      std::printf(
          "{\"case\": \"%s\", \"feature\": %u, \"corner\": %d, \"weak\": %d, "
          "\"weak_otherwise\": %d, \"source\": %zu, \"region\": %d, \"off_plane\": %.4f, "
          "\"off_other_plane\": %.4f, \"planes_cos\": %.4f, \"own_signed\": %.4f, "
          "\"other_signed\": %.4f, \"x\": [%.6g, %.6g, %.6g], \"normal\": [%.4f, %.4f, "
          "%.4f], \"other_normal\": [%.4f, %.4f, %.4f]}\n",
          name.c_str(), c, int(features[c].corner), int(weak[c]), int(weakOtherwise[c]), s,
          s < support.region.size() ? support.region[s] : -1, offPlane(own, s), other, otherCos,
          own.normal * (p - own.point) / spacing, otherSigned, p[0], p[1], p[2], own.normal[0],
          own.normal[1], own.normal[2], otherNormal[0], otherNormal[1], otherNormal[2]);
    }
  }
}

int main(int argc, char **argv) {
  if (argc < 3) {
    std::cerr << "usage: evidence-study INPUT REFERENCE [CASE-NAME] [--vertices | --sources]\n";
    return 2;
  }
  const std::string name = argc > 3 ? argv[3] : argv[1];
  const std::string mode = argc > 4 ? argv[4] : "";
  const bool perVertex = mode == "--vertices", perSource = mode == "--sources";
  try {
    es::Mesh m, reference;
    es::io::loadMesh(argv[1], m);
    es::io::loadMesh(argv[2], reference);
    vcg::tri::UpdateBounding<es::Mesh>::Box(m);
    vcg::tri::UpdateBounding<es::Mesh>::Box(reference);
    vcg::tri::UpdateNormal<es::Mesh>::PerFaceNormalized(reference);

    es::SharpenOptions opt;
    opt.method = es::Method::Auto;
    // The same stages as sharpen(), up to the evidence guard.
    es::SharpenReport report = es::detail::validate(m, opt);
    es::MeshLabels<es::Mesh> labels(m);
    const es::FeatureZones zones = es::detail::detectByZones(m, labels, opt, report);
    const es::InputFaces<es::Mesh> inputFaces(m);
    const es::SurfaceMeasures measures =
        es::measureSurface(m, zones.inputFaces, zones.faceRegion, zones.support.sampleSpacing);
    const es::SplitPlan plan = es::planSplits(m, labels);
    report.subdivision = es::subdivide(m, plan, labels);
    es::VertexMoves<es::Mesh> moves(m, plan, labels, true);
    es::placeInsertedVertices(m, plan, labels, report.longestInputEdge, opt,
                              es::PlacementPolicy::autoMethod(opt), zones.support);
    es::refineExtendedPlacement(m, moves, zones, opt, report);
    // The evidence as the guard sees it (before the cleanup); the harm after every guard.
    const es::InputSurface surface{zones.inputFaces, inputFaces.faceVertices()};
    const es::HeldFaces noneHeld;
    es::EvidenceGuard<es::Mesh> guard(m, moves, zones.support, surface, measures,
                                      report.longestInputEdge, opt, noneHeld);
    const auto judged = guard.judge();
    const std::vector<es::Feature> &features = guard.features();
    const std::vector<std::uint32_t> &featureOf = guard.featureOf();
    const std::vector<double> &lifts = judged.lifts;
    std::vector<char> weak(features.size());
    for (std::size_t c = 0; c < features.size(); ++c) weak[c] = judged.left(c);
    // The same verdicts without the off-plane test, to study a replacement for it.
    es::SharpenOptions withoutOffPlane = opt;
    withoutOffPlane.rules.feature.maxFeatureOffPlaneSpacings = 1e30;
    const std::vector<es::Verdict> verdictsOtherwise =
        es::featureVerdicts(plan, features, featureOf, judged.stats.medianLift, measures,
                            withoutOffPlane, judged.stats.exactSampling);
    std::vector<char> weakOtherwise(features.size());
    for (std::size_t c = 0; c < features.size(); ++c)
      weakOtherwise[c] = verdictsOtherwise[c] != es::Verdict::Restored;
    // Each feature's source vertices' distances to their own plane, as the guard measured them.
    const std::vector<std::vector<double>> offPlane =
        es::sourceOffPlanes(m, moves, zones.support, featureOf, features.size());
    if (perSource) {
      printSources(name, m, moves, zones.support, featureOf, features, weak, weakOtherwise);
      return 0;
    }
    const double refused = judged.stats.refusedFraction;
    // Median distance and lift of each feature's moves (distance in sample spacings).
    std::vector<std::vector<double>> moveLengths(features.size()), featureLifts(features.size());
    for (std::size_t k = 0; k < featureOf.size(); ++k) {
      const std::size_t v = moves.firstInserted() + k;
      if (!m.vert[v].IsD() && moves.isMoved(v))
        moveLengths[featureOf[k]].push_back(
            (es::positionOf(&m.vert[v]) - plan.inserted[k].rest).Norm() /
            zones.support.sampleSpacing);
      featureLifts[featureOf[k]].push_back(lifts[k]);
    }
    report.cleanup = es::removeDegenerateTriangles(m, moves, opt.degenerateAngleRad);
    report.intersections =
        es::revertSelfIntersections(m, moves, opt.degenerateAngleRad, report.longestInputEdge);

    vcg::tri::UpdateBounding<es::Mesh>::Box(m);
    vcg::tri::HausdorffSampler<es::Mesh> sampler(&reference);
    sampler.unifGridFace.Set(reference.face.begin(), reference.face.end(),
                             es::closestFaceGridBox(reference, m));
    sampler.dist_upper_bound = reference.bbox.Diag();
    const double spacing = zones.support.sampleSpacing;
    const auto distance = [&](const es::Vec3 &p) {
      return double(sampler.AddSample(vcg::Point3f::Construct(p), vcg::Point3f(0, 0, 0)));
    };
    std::vector<double> sum(features.size(), 0), worst(features.size(), -1e30),
        before(features.size(), 0);
    std::vector<char> seen(plan.originalVertexCount, 0);
    const auto account = [&](std::size_t c, std::size_t v) {
      const double d0 = distance(moves.exactRest(v)), d1 = distance(es::positionOf(&m.vert[v]));
      sum[c] += (d1 - d0) / spacing;
      before[c] += d0 / spacing;
      worst[c] = std::max(worst[c], (d1 - d0) / spacing);
    };
    if (perVertex) {
      for (std::size_t k = 0; k < plan.inserted.size(); ++k) {
        const std::size_t v = moves.firstInserted() + k;
        const std::size_t c = featureOf[k];
        if (m.vert[v].IsD() || !moves.isMoved(v) || weak[c]) continue;
        const es::Vec3 target = es::positionOf(&m.vert[v]), rest = plan.inserted[k].rest;
        const auto own = guard.vertexEvidence(k);
        if (own.sourceOffPlaneSpacings > opt.rules.feature.maxFeatureOffPlaneSpacings)
          continue;  // a far sample's
        double reach = 0;
        for (int i = 0; i < plan.inserted[k].originalCount; ++i)
          reach = std::max(
              reach, (target - moves.exactRest(plan.inserted[k].original[i])).Norm() / spacing);
        const double d0 = distance(rest) / spacing, d1 = distance(target) / spacing;
        // How far the rest position lies from each source's plane, and the
        // angle those planes meet at (edge vertices).
        double restNear = 0, restFar = 0, flankDeg = 90, along = 0;
        if (plan.inserted[k].originalCount == 2) {
          const es::Plane &a = zones.support.plane(plan.inserted[k].original[0]);
          const es::Plane &b = zones.support.plane(plan.inserted[k].original[1]);
          const double da = std::abs(a.normal * (rest - a.point)) / spacing;
          const double db = std::abs(b.normal * (rest - b.point)) / spacing;
          restNear = std::min(da, db);
          restFar = std::max(da, db);
          flankDeg = es::planeMeetingAngle(a.normal, b.normal) * 180 / M_PI;
          es::Vec3 line = a.normal ^ b.normal;
          if (line.Norm() > 0) along = std::abs((target - rest) * line.Normalize()) / spacing;
        }
        std::printf(
            "{\"rest_near\": %.4f, \"rest_far\": %.4f, \"flank_deg\": %.2f, "
            "\"along\": %.4f, ",
            restNear, restFar, flankDeg, along);
        std::printf(
            "\"case\": \"%s\", \"feature\": %zu, \"corner\": %d, \"feature_vertices\": "
            "%zu, \"feature_lift\": %.4f, \"length\": %.4f, \"lift\": %.4f, \"source_off_plane\": "
            "%.4f, \"reach\": %.4f, \"sent_back\": %d, \"before\": %.5f, \"after\": %.5f, \"x\": "
            "[%.6g, %.6g, "
            "%.6g]}\n",
            name.c_str(), c, int(features[c].corner), features[c].vertices,
            es::medianLift(featureLifts[c]), own.moveSpacings, lifts[k], own.sourceOffPlaneSpacings,
            reach, int(guard.vertexIsWeak(k)), d0, d1, target[0], target[1], target[2]);
      }
      return 0;
    }
    for (std::size_t k = 0; k < plan.inserted.size(); ++k) {
      const std::size_t v = moves.firstInserted() + k;
      if (m.vert[v].IsD()) continue;
      if (moves.isMoved(v)) account(featureOf[k], v);
      for (int i = 0; i < plan.inserted[k].originalCount; ++i) {
        const std::size_t s = plan.inserted[k].original[i];
        if (seen[s] || m.vert[s].IsD() || !moves.isMoved(s)) continue;
        seen[s] = 1;
        account(featureOf[k], s);
      }
    }
    // Per moved edge vertex, how far its sources lie off their planes over how far they
    // lie from its target (0: samples on the flanks' planes; a bevel's or a blend's: large).
    std::vector<std::vector<double>> roundness(features.size());
    for (std::size_t k = 0; k < plan.inserted.size(); ++k) {
      const std::size_t v = moves.firstInserted() + k;
      if (m.vert[v].IsD() || !moves.isMoved(v) || plan.inserted[k].originalCount != 2) continue;
      double worstRatio = 0;
      for (int i = 0; i < 2; ++i) {
        const std::size_t s = plan.inserted[k].original[i];
        const double reach = (es::positionOf(&m.vert[v]) - moves.exactRest(s)).Norm();
        if (!(reach > 0)) continue;
        worstRatio =
            std::max(worstRatio, es::offPlaneSpacings(zones.support, moves, s) * spacing / reach);
      }
      roundness[featureOf[k]].push_back(worstRatio);
    }
    const auto quantile = [](std::vector<double> v, double q) {
      return es::detail::quantileOf(v, q);  // on a copy: it reorders
    };
    for (std::size_t c = 0; c < features.size(); ++c) {
      const es::Feature &f = features[c];
      if (f.moved == 0) continue;
      std::printf(
          "{\"off_plane_q50\": %.4f, \"off_plane_q75\": %.4f, \"off_plane_q90\": %.4f, "
          "\"round_q25\": %.4f, \"round_q50\": %.4f, \"round_q75\": %.4f, \"weak_otherwise\": %d, ",
          quantile(offPlane[c], 0.5), quantile(offPlane[c], 0.75), quantile(offPlane[c], 0.9),
          quantile(roundness[c], 0.25), quantile(roundness[c], 0.5), quantile(roundness[c], 0.75),
          int(weakOtherwise[c]));
      std::printf(
          "\"case\": \"%s\", \"refused\": %.4f, \"mesh_lift\": %.4f, \"noise\": %.4f, \"planar\": "
          "%.4f, "
          "\"feature\": %zu, "
          "\"corner\": %d, "
          "\"vertices\": %zu, \"moved\": %zu, "
          "\"max_off_plane\": %.4f, \"median_displacement\": %.4f, "
          "\"median_lift\": %.4f, \"weak\": %d, \"harm_sum\": %.5f, \"harm_max\": %.5f, "
          "\"before_sum\": %.5f, \"flank_angle_deg\": %.2f, \"line_chamfer_angle_deg\": %.2f, "
          "\"crossed\": %zu, \"fillet_width\": %.3f, \"fillet_rms\": %.4f, \"wedge_rms\": %.4f, "
          "\"peer_fillet_width\": %.3f, \"concave\": %d}\n",
          name.c_str(), refused, judged.stats.medianLift, judged.stats.noiseSpacings,
          judged.stats.planarFraction, c, int(f.corner), f.vertices, f.moved, f.maxOffPlane,
          es::detail::medianOf(moveLengths[c]), es::medianLift(featureLifts[c]), int(weak[c]),
          sum[c], worst[c], before[c], f.flankAngleRad * 180 / M_PI,
          f.lineChamferAngleRad * 180 / M_PI, f.crossed, f.filletWidthSpacings, f.filletRmsSpacings,
          f.wedgeRmsSpacings, f.peerFilletWidthSpacings, int(f.concave));
    }
  } catch (const std::exception &e) {
    std::cerr << "evidence-study: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
