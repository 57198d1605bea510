// Invariants every result of edge_sharpener::sharpen() must keep, checked from
// the outside (only the public API, the report and vcglib), shared by the
// reliability tests and the fuzz targets. Each check returns "" or a one-line
// description of the first violation.
#pragma once

#include <vcg/complex/complex.h>
// (vcglib's algorithm headers need complex.h first)
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/append.h>
#include <vcg/space/distance3.h>
#include <vcg/space/triangle3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "edge_sharpener/report.h"
#include "edge_sharpener/util/mesh_types.h"

namespace es_reliability {

using P3 = vcg::Point3d;

template <class V>
P3 pos(const V &v) {
  return P3::Construct(v.cP());
}

/// Smallest interior angle of triangle abc in radians (0 for a degenerate one).
inline double minAngle(const P3 &a, const P3 &b, const P3 &c) {
  const P3 p[3] = {a, b, c};
  double best = M_PI;
  for (int i = 0; i < 3; ++i) {
    const P3 u = p[(i + 1) % 3] - p[i], w = p[(i + 2) % 3] - p[i];
    const double nu = u.Norm(), nw = w.Norm();
    if (!(nu > 0) || !(nw > 0)) return 0;
    best = std::min(best, std::acos(std::clamp((u * w) / (nu * nw), -1.0, 1.0)));
  }
  return best;
}

/// Topological summary of a compact mesh (rebuilds FF adjacency).
struct Topology {
  int edges = 0, boundaryEdges = 0, nonManifoldEdges = 0, nonManifoldVertices = 0;
  bool oriented = false;
  bool manifold() const { return nonManifoldEdges == 0 && nonManifoldVertices == 0; }
};

template <class M>
Topology topologyOf(M &m) {
  Topology t;
  vcg::tri::UpdateTopology<M>::FaceFace(m);
  // CountEdgeNum, not CountNonManifoldEdgeFF (which leaks face bit flags).
  vcg::tri::Clean<M>::CountEdgeNum(m, t.edges, t.boundaryEdges, t.nonManifoldEdges);
  if (t.nonManifoldEdges == 0) {
    t.nonManifoldVertices = vcg::tri::Clean<M>::CountNonManifoldVertexFF(m, false, false);
    t.oriented = vcg::tri::Clean<M>::IsCoherentlyOrientedMesh(m);
  }
  return t;
}

template <class M>
bool allFinite(const M &m) {
  for (const auto &v : m.vert)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(double(v.cP()[k]))) return false;
  return true;
}

/// Bit-identical positions (NaN included) and connectivity.
template <class M>
bool identical(const M &a, const M &b) {
  if (a.vert.size() != b.vert.size() || a.face.size() != b.face.size()) return false;
  for (std::size_t i = 0; i < a.vert.size(); ++i) {
    const auto pa = a.vert[i].cP(), pb = b.vert[i].cP();
    if (std::memcmp(&pa, &pb, sizeof pa) != 0 || a.vert[i].IsD() != b.vert[i].IsD()) return false;
  }
  for (std::size_t i = 0; i < a.face.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (vcg::tri::Index(a, a.face[i].cV(k)) != vcg::tri::Index(b, b.face[i].cV(k))) return false;
  return true;
}

/// The faces of m at a non-manifold spot, as vertex-index triples rotated to
/// start at their lowest index: the faces at a vertex on an edge of three or
/// more faces, or whose faces do not form one fan joined by two-face edges.
/// Brute force over vertex-index pairs, independent of the core's FF walk.
template <class M>
std::set<std::array<std::size_t, 3>> facesAtNonManifoldSpots(const M &m) {
  const auto index = [&](const auto *v) { return std::size_t(vcg::tri::Index(m, v)); };
  std::map<std::pair<std::size_t, std::size_t>, int> edgeFaces;
  for (const auto &f : m.face)
    for (int k = 0; k < 3; ++k) {
      std::size_t a = index(f.cV(k)), b = index(f.cV((k + 1) % 3));
      ++edgeFaces[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::vector<std::size_t>> around(m.vert.size());
  for (std::size_t fi = 0; fi < m.face.size(); ++fi)
    for (int k = 0; k < 3; ++k) around[index(m.face[fi].cV(k))].push_back(fi);
  const auto triple = [&](const auto &f) {
    std::array<std::size_t, 3> t{index(f.cV(0)), index(f.cV(1)), index(f.cV(2))};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  std::set<std::array<std::size_t, 3>> out;
  for (std::size_t v = 0; v < m.vert.size(); ++v) {
    const auto &faces = around[v];
    bool spot = false;
    std::vector<std::size_t> group(faces.size());
    std::iota(group.begin(), group.end(), 0);
    const auto root = [&](std::size_t i) {
      while (group[i] != i) i = group[i];
      return i;
    };
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        const std::size_t w = index(m.face[faces[i]].cV(k));
        if (w == v) continue;
        const int n = edgeFaces[{std::min(v, w), std::max(v, w)}];
        if (n > 2) spot = true;
        if (n != 2) continue;
        for (std::size_t j = 0; j < faces.size(); ++j)
          for (int l = 0; l < 3; ++l)
            if (j != i && index(m.face[faces[j]].cV(l)) == w) group[root(i)] = root(j);
      }
    for (std::size_t i = 0; i < faces.size(); ++i) spot |= root(i) != root(0);
    if (spot)
      for (std::size_t fi : faces) out.insert(triple(m.face[fi]));
  }
  return out;
}

/// Distance from p to the nearest face of m (brute force: for a few points).
template <class M>
double distanceToSurface(const M &m, const P3 &p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto &f : m.face) {
    if (f.IsD()) continue;
    vcg::Triangle3<double> t(pos(*f.cV(0)), pos(*f.cV(1)), pos(*f.cV(2)));
    double d;
    P3 closest;
    vcg::TrianglePointDistance(t, p, d, closest);
    best = std::min(best, d);
  }
  return best;
}

template <class M>
double bboxDiagonal(const M &m) {
  vcg::Box3d box;
  for (const auto &v : m.vert)
    if (!v.IsD()) box.Add(pos(v));
  return box.IsNull() ? 0.0 : box.Diag();
}

/// Whether output face f, with an angle below `bound`, is a child of an input
/// sliver that no vertex at rest would cure (what cleanup leaves in place): its
/// shortest edge joins two original vertices a and b, and its third vertex,
/// put back at some place it may rest (the midpoint of an input edge or the
/// centroid of an input face, at a or b), leaves an angle below `bound` too.
template <class M, class F>
bool inputSliverAtRest(const M &input, const M &output, const F &f, double bound) {
  int shortest = 0;
  for (int k = 1; k < 3; ++k)
    if ((pos(*f.cV((k + 1) % 3)) - pos(*f.cV(k))).SquaredNorm() <
        (pos(*f.cV((shortest + 1) % 3)) - pos(*f.cV(shortest))).SquaredNorm())
      shortest = k;
  const std::size_t a = vcg::tri::Index(output, f.cV(shortest));
  const std::size_t b = vcg::tri::Index(output, f.cV((shortest + 1) % 3));
  if (a >= input.vert.size() || b >= input.vert.size()) return false;
  const P3 A = pos(input.vert[a]), B = pos(input.vert[b]);
  for (const auto &g : input.face) {
    std::size_t at = 3;  // which corner of g is a or b
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = vcg::tri::Index(input, g.cV(k));
      if (v == a || v == b) at = std::size_t(k);
    }
    if (at == 3) continue;
    const P3 corner = pos(*g.cV(int(at)));
    const P3 rests[3] = {(corner + pos(*g.cV(int(at + 1) % 3))) / 2,
                         (corner + pos(*g.cV(int(at + 2) % 3))) / 2,
                         (pos(*g.cV(0)) + pos(*g.cV(1)) + pos(*g.cV(2))) / 3};
    for (const P3 &rest : rests)
      if (minAngle(A, B, rest) < bound) return true;
  }
  return false;
}

/// Checks `output` = sharpen(copy of `input`) with report `r`:
///  - finite coordinates; original vertices keep index and bit-identical position;
///  - vertex/face counts equal the report's, and the report's arithmetic holds;
///  - output is compact, a 2-manifold if the input was, consistently oriented if the
///    input was; every face of the input at a non-manifold spot comes out as it was
///    (the same vertex indices), and the report counts them; closed stays closed, and an open input
///    gains boundary edges only by splitting (a boundary chamfer edge becomes two), never more than
///    it had;
///  - no face with an angle below `degenerateAngleRad` contains a moved vertex: every
///    vertex of such a face lies on the input surface (inserted vertices start on it, at
///    an edge midpoint or face centroid, and leave it only when placed), unless the face
///    is an input sliver's child that stays below that angle at rest too
///    (inputSliverAtRest); r.cleanup.remaining is 0.
/// Rebuilds FF adjacency of both meshes.
template <class M>
std::string sharpenProblem(M &input, M &output, const edge_sharpener::SharpenReport &r,
                           double degenerateAngleRad) {
  if (!allFinite(output)) return "output has a NaN or infinite coordinate";
  if (output.vert.size() < input.vert.size()) return "output lost original vertices";
  for (std::size_t i = 0; i < input.vert.size(); ++i)
    if (!(output.vert[i].cP() == input.vert[i].cP()))
      return "original vertex " + std::to_string(i) + " moved";
  if (output.vn != int(output.vert.size()) || output.fn != int(output.face.size()))
    return "output is not compact";
  if (r.inputVertices != input.vert.size() || r.inputFaces != input.face.size())
    return "report's input counts differ from the input";
  if (r.outputVertices != output.vert.size() || r.outputFaces != output.face.size())
    return "report's output counts differ from the output";
  if (r.outputVertices != r.inputVertices + r.subdivision.insertedVertices - r.cleanup.collapses -
                              r.evidence.verticesRemoved)
    return "vertex count arithmetic does not hold";
  if (r.outputFaces !=
      r.inputFaces + r.subdivision.addedFaces - r.cleanup.removedFaces - r.evidence.facesRemoved)
    return "face count arithmetic does not hold";
  if (r.cleanup.remaining != 0)
    return "cleanup left " + std::to_string(r.cleanup.remaining) + " degenerate faces";
  for (const auto &f : output.face)
    for (int k = 0; k < 3; ++k) {
      const auto *v = f.cV(k);
      if (v < &output.vert.front() || v > &output.vert.back()) return "face points outside vert";
      if (v->IsD()) return "face references a deleted vertex";
    }
  const auto spotFaces = facesAtNonManifoldSpots(input);
  if (!spotFaces.empty()) {
    const auto outputSpots = facesAtNonManifoldSpots(output);
    for (const auto &t : spotFaces)
      if (!outputSpots.count(t))
        return "face (" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " +
               std::to_string(t[2]) + ") at a non-manifold spot did not come out as it was";
    if (outputSpots.size() != spotFaces.size()) return "the non-manifold spots changed";
    if (r.nonManifold.heldFaces < spotFaces.size())
      return "report holds " + std::to_string(r.nonManifold.heldFaces) + " faces, " +
             std::to_string(spotFaces.size()) + " at spots";
  }
  const Topology in = topologyOf(input), out = topologyOf(output);
  if (in.manifold() && !out.manifold()) return "output is not a 2-manifold";
  if (in.oriented && !out.oriented) return "output is not consistently oriented";
  if (out.boundaryEdges < in.boundaryEdges || out.boundaryEdges > 2 * in.boundaryEdges)
    return "boundary edges " + std::to_string(in.boundaryEdges) + " -> " +
           std::to_string(out.boundaryEdges);
  const double tolerance = 1e-5 * std::max(bboxDiagonal(input), 1e-30);
  for (std::size_t i = 0; i < output.face.size(); ++i) {
    const auto &f = output.face[i];
    if (minAngle(pos(*f.cV(0)), pos(*f.cV(1)), pos(*f.cV(2))) >= degenerateAngleRad) continue;
    if (inputSliverAtRest(input, output, f, degenerateAngleRad)) continue;
    for (int k = 0; k < 3; ++k) {
      const std::size_t vi = vcg::tri::Index(output, f.cV(k));
      if (vi < input.vert.size()) continue;  // original vertex: never moved
      if (distanceToSurface(input, pos(*f.cV(k))) > tolerance)
        return "face " + std::to_string(i) + " has an angle below the threshold and a moved vertex";
    }
  }
  return "";
}

/// Number of faces of m that intersect another face: vcglib's
/// tri::Clean::SelfIntersections() on a double-precision copy. (On float
/// coordinates its Moeller test reports nearly coplanar faces millimetres
/// apart as intersecting, e.g. on the pyramid's flanks: docs/reliability.md.)
template <class M>
std::size_t selfIntersectingFaces(M &m) {
  edge_sharpener::MeshD d;
  vcg::tri::Append<edge_sharpener::MeshD, M>::MeshCopy(d, m);
  std::vector<edge_sharpener::MeshD::FacePointer> faces;
  vcg::tri::Clean<edge_sharpener::MeshD>::SelfIntersections(d, faces);
  std::sort(faces.begin(), faces.end());
  return std::unique(faces.begin(), faces.end()) - faces.begin();
}

}  // namespace es_reliability
