// A feature's cross-section as a fillet: the two flank planes rounded by an
// arc of radius r tangent to both. A sampler that cuts a sharp edge leaves
// its samples on the planes or rounds them near the edge; a designed fillet
// puts them on one arc, the same along the whole edge. Fitting r by least
// squares to a feature's samples tells how wide the rounding is; comparing
// it with the rounding the same sampler gives edges it meets alike tells a
// designed fillet from the sampler's. Pure.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "geometry.h"

namespace edge_sharpener {

/// One sample across an edge: how far it lies inside each flank's plane
/// (positive on the side a fillet rounds: inside a convex edge's solid,
/// outside a concave edge's), in any unit.
struct CrossSectionSample {
  double fromOwn = 0, fromOther = 0;
};

/// The signed distance of a sample to the wedge of two planes whose outward
/// normals have cosine `cosNormals`, rounded by a fillet of radius `radius`
/// (negative inside, zero on it). Radius 0: the sharp wedge.
inline double distanceToRoundedWedge(const CrossSectionSample &s, double cosNormals,
                                     double radius) {
  // Where the sample lies against the wedge eroded by the radius, whose apex
  // is the fillet's centre: along each outward normal.
  const double a = radius - s.fromOwn, b = radius - s.fromOther;
  if (a <= 0 && b <= 0) return std::max(a, b) - radius;
  const double c = std::clamp(cosNormals, -0.999, 0.999);
  // The sample's offset from the centre as a combination of the normals:
  // both weights positive, and the centre is the nearest point.
  const double wa = (a - c * b) / (1 - c * c), wb = (b - c * a) / (1 - c * c);
  const double outside =
      wa > 0 && wb > 0 ? std::sqrt(std::max(0.0, a * wa + b * wb)) : std::max(a, b);
  return outside - radius;
}

/// The width across a fillet of radius `radius` between planes whose outward
/// normals have cosine `cosNormals`: the chord between its tangent lines.
inline double filletWidth(double radius, double cosNormals) {
  return 2 * radius * std::sqrt(std::max(0.0, (1 - std::clamp(cosNormals, -1.0, 1.0)) / 2));
}

/// A fillet fitted to samples: its radius and the RMS of their distances to
/// it, in the samples' unit.
struct FilletFit {
  double radius = 0;
  double rms = 0;
  double wedgeRms = 0;  ///< ...and to the sharp wedge (radius 0)
};

/// The fillet radius in [0, maxRadius] that fits `samples` best (least
/// squares on distanceToRoundedWedge), found on steps of `step` and refined
/// around the best one; where several fit alike, the smallest (samples on
/// the planes alone fit every fillet narrower than their distance from the
/// edge, and the sharp wedge is the plainer model). Empty samples: radius 0.
inline FilletFit fitFillet(const std::vector<CrossSectionSample> &samples, double cosNormals,
                           double maxRadius, double step) {
  if (samples.empty() || !(step > 0)) return {};
  const auto meanSquare = [&](double r) {
    double sum = 0;
    for (const CrossSectionSample &s : samples) {
      const double d = distanceToRoundedWedge(s, cosNormals, r);
      sum += d * d;
    }
    return sum / double(samples.size());
  };
  const double wedge = meanSquare(0.0);
  double bestRadius = 0, bestMeanSquare = wedge;
  const auto scan = [&](double from, double to, double by) {
    for (double r = from; r <= to + 1e-12; r += by) {
      const double e = meanSquare(r);
      // A fit better by a relative 1e-9 only is the same fit.
      if (e < bestMeanSquare * (1 - 1e-9)) {
        bestRadius = r;
        bestMeanSquare = e;
      }
    }
  };
  scan(step, maxRadius, step);
  const double coarse = bestRadius;
  scan(std::max(0.0, coarse - step), std::min(maxRadius, coarse + step), step / 10);
  return {bestRadius, std::sqrt(bestMeanSquare), std::sqrt(wedge)};
}

/// Whether a grid sampler meets two edges alike: some symmetry of the cube
/// (the axes permuted, each turned either way) maps the flank normals of one
/// (a0, a1) onto those of the other (b0, b1), in either order, each within
/// the angle whose cosine is `minCos`. A grid samples such edges the same way
/// (up to where the edge lies between its nodes).
inline bool gridEquivalentEdges(const Vec3 &a0, const Vec3 &a1, const Vec3 &b0, const Vec3 &b1,
                                double minCos) {
  static constexpr std::array<std::array<int, 3>, 6> kPermutations{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (const auto &p : kPermutations)
    for (int signs = 0; signs < 8; ++signs) {
      const auto map = [&](const Vec3 &n) {
        Vec3 out;
        for (int i = 0; i < 3; ++i) out[i] = ((signs >> i) & 1 ? -1.0 : 1.0) * n[p[i]];
        return out;
      };
      const Vec3 c0 = map(b0), c1 = map(b1);
      if ((a0 * c0 >= minCos && a1 * c1 >= minCos) || (a0 * c1 >= minCos && a1 * c0 >= minCos))
        return true;
    }
  return false;
}

}  // namespace edge_sharpener
