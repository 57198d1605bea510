// Stage 1: the smooth-edge ("brown") test of Edge-Sharpener.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "fast_topology.h"
#include "mesh_labels.h"
#include "report.h"

namespace edge_sharpener {

/// Unit normal of every face in double precision; zero-area faces get a zero
/// normal (their edges can then never be smooth). Runs in parallel.
/// \return the number of zero-area faces.
template <class MeshType>
std::size_t computeFaceNormals(MeshType &m, MeshLabels<MeshType> &labels) {
  std::int64_t degenerate = 0;
  const std::int64_t nf = std::int64_t(m.face.size());
#pragma omp parallel for schedule(static, 4096) reduction(+ : degenerate) if (nf > kParallelMin)
  for (std::int64_t fi = 0; fi < nf; ++fi) {
    auto &f = m.face[fi];
    if (f.IsD()) continue;
    const Vec3 p0 = positionOf(f.cV(0)), p1 = positionOf(f.cV(1)), p2 = positionOf(f.cV(2));
    const Vec3 n = (p1 - p0) ^ (p2 - p0);
    const double scale = std::max({(p1 - p0).SquaredNorm(), (p2 - p1).SquaredNorm(),
                                   (p0 - p2).SquaredNorm()});
    const double len = n.Norm();
    // A relative test: |n| / longest^2 is about the sine of the smallest angle.
    if (!(len > 1e-12 * scale) || !std::isfinite(len)) {
      labels.normal[&f] = Vec3(0, 0, 0);
      ++degenerate;
    } else {
      labels.normal[&f] = n / len;
    }
  }
  return std::size_t(degenerate);
}

/// Labels Smooth every interior edge whose normal angle is below
/// `multiplier` x the mesh-wide mean of that angle (paper: "twice the
/// average"). Boundary edges and edges next to zero-area faces are never
/// smooth and do not enter the mean. Exactly coplanar faces always are.
/// Each edge's angle is computed once, in parallel; the mean is summed
/// serially in edge order (forEachEdge), so it does not depend on the
/// thread count.
/// \pre FF topology up to date; computeFaceNormals() ran.
template <class MeshType>
SmoothEdgeStats labelSmoothEdges(MeshType &m, MeshLabels<MeshType> &labels, double multiplier) {
  constexpr double kBoundary = -2.0, kDegenerate = -1.0, kNotOwner = -3.0;
  const std::int64_t nf = std::int64_t(m.face.size());
  // angle[3f + i]: angle of edge i of face f when f visits it in forEachEdge
  // (boundary, or the lower face address of the two), else kNotOwner.
  std::vector<double> angle(3 * m.face.size(), kNotOwner);
#pragma omp parallel for schedule(static, 4096) if (nf > kParallelMin)
  for (std::int64_t fi = 0; fi < nf; ++fi) {
    auto *f = &m.face[fi];
    if (f->IsD()) continue;
    for (int i = 0; i < 3; ++i) {
      auto *g = f->FFp(i);
      double &a = angle[3 * fi + i];
      if (g == f) {
        a = kBoundary;
      } else if (f < g) {
        const Vec3 &na = labels.normal[f];
        const Vec3 &nb = labels.normal[g];
        a = na.SquaredNorm() == 0 || nb.SquaredNorm() == 0 ? kDegenerate : angleBetween(na, nb);
      }
    }
  }
  SmoothEdgeStats s;
  double angleSum = 0;
  std::size_t angleCount = 0;
  for (const double a : angle) {
    if (a == kNotOwner) continue;
    ++s.edges;
    if (a == kBoundary) {
      ++s.boundaryEdges;
    } else if (a == kDegenerate) {
      ++s.degenerateEdges;
    } else {
      angleSum += a;
      ++angleCount;
    }
  }
  s.meanAngleRad = angleCount ? angleSum / double(angleCount) : 0.0;
  s.thresholdRad = multiplier * s.meanAngleRad;
  std::int64_t smooth = 0;
  const double threshold = s.thresholdRad;
#pragma omp parallel for schedule(static, 4096) reduction(+ : smooth) if (nf > kParallelMin)
  for (std::int64_t fi = 0; fi < nf; ++fi) {
    for (int i = 0; i < 3; ++i) {
      const double a = angle[3 * fi + i];
      if (a < 0) continue;  // not visited here, boundary or degenerate
      if (a < threshold || a == 0.0) {
        // Each edge is set by its one visiting face: no two threads write
        // the same label.
        labels.setEdge(&m.face[fi], i, EdgeLabel::Smooth);
        ++smooth;
      }
    }
  }
  s.smoothEdges = std::size_t(smooth);
  return s;
}

}  // namespace edge_sharpener
