// Stage 1: the smooth-edge ("brown") test of Edge-Sharpener.
#pragma once

#include <cmath>
#include <limits>

#include "mesh_labels.h"
#include "report.h"

namespace edge_sharpener {

/// Unit normal of every face in double precision; zero-area faces get a zero
/// normal (their edges can then never be smooth).
/// \return the number of zero-area faces.
template <class MeshType>
std::size_t computeFaceNormals(MeshType &m, MeshLabels<MeshType> &labels) {
  std::size_t degenerate = 0;
  for (auto &f : m.face) {
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
  return degenerate;
}

/// Labels Smooth every interior edge whose normal angle is below
/// `multiplier` x the mesh-wide mean of that angle (paper: "twice the
/// average"). Boundary edges and edges next to zero-area faces are never
/// smooth and do not enter the mean. Exactly coplanar faces always are.
/// \pre FF topology up to date; computeFaceNormals() ran.
template <class MeshType>
SmoothEdgeStats labelSmoothEdges(MeshType &m, MeshLabels<MeshType> &labels, double multiplier) {
  SmoothEdgeStats s;
  double angleSum = 0;
  std::size_t angleCount = 0;
  const auto edgeAngle = [&](typename MeshType::FaceType *f, int i) {
    const Vec3 &a = labels.normal[f];
    const Vec3 &b = labels.normal[f->FFp(i)];
    if (a.SquaredNorm() == 0 || b.SquaredNorm() == 0) return -1.0;
    return angleBetween(a, b);
  };
  forEachEdge(m, [&](auto *f, int i, bool boundary) {
    ++s.edges;
    if (boundary) {
      ++s.boundaryEdges;
      return;
    }
    const double angle = edgeAngle(f, i);
    if (angle < 0) {
      ++s.degenerateEdges;
      return;
    }
    angleSum += angle;
    ++angleCount;
  });
  s.meanAngleRad = angleCount ? angleSum / double(angleCount) : 0.0;
  s.thresholdRad = multiplier * s.meanAngleRad;
  forEachEdge(m, [&](auto *f, int i, bool boundary) {
    if (boundary) return;
    const double angle = edgeAngle(f, i);
    if (angle < 0) return;
    if (angle < s.thresholdRad || angle == 0.0) {
      labels.setEdge(f, i, EdgeLabel::Smooth);
      ++s.smoothEdges;
    }
  });
  return s;
}

}  // namespace edge_sharpener
