// Two measures of the input's surface as a whole, read by the auto method's
// evidence guard (feature_evidence.h: refusedBound).
//
// Noise: a remesher, a marching-cubes extraction of an exact distance field
// or a Poisson reconstruction from exact points leave a surface whose
// curvature varies slowly from one vertex to the next (zero on a plane,
// nearly constant on a cylinder); a depth scan fused in a volume leaves bumps
// one sample wide (the fusion's ripples and the depth noise).
//
// Planar area: the share of the surface lying on planes. Sharpening
// extrapolates planes; on a part made of planes meeting at chamfered edges,
// a feature whose tests agree is what it seems, while on a freeform part
// (fillets, blends) the same agreement can come from a curved face.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "../rulebook.h"
#include "../util/attributes.h"
#include "../util/geometry.h"
#include "../util/statistics.h"
#include "../util/vertex_faces.h"

namespace edge_sharpener {

/// One vertex's umbrella curvature: the component, along its area-weighted
/// normal, of the offset from vertex v to the mean of its neighbours
/// (detail::forEachNeighbour, through its faces in `vf`). Zero on a plane;
/// about the mean curvature times the squared spacing on a smooth surface.
/// 0 for a vertex without faces or normal.
template <class MeshType>
double umbrellaCurvature(const MeshType &m, const VertexFaceTable &vf, std::size_t v) {
  Vec3 normal(0, 0, 0), sum(0, 0, 0);
  for (const std::uint32_t *f = vf.begin(v); f != vf.end(v); ++f) {
    const auto &face = m.face[*f];
    const Vec3 a = positionOf(face.cV(0)), b = positionOf(face.cV(1)), c = positionOf(face.cV(2));
    normal += (b - a) ^ (c - a);
    sum += a + b + c;
  }
  const std::size_t count = 2 * vf.degree(v);  // the neighbours, as forEachNeighbour visits them
  const double length = normal.Norm();
  if (count == 0 || !(length > 0)) return 0;
  const Vec3 p = positionOf(&m.vert[v]);
  const Vec3 mean = (sum - p * double(count / 2)) / double(count);
  return (mean - p) * normal / length;
}

/// The surface's noise in units of `spacing`: the median, over every
/// `stride`-th vertex with faces in `vf`, of how far its umbrella curvature
/// differs from its neighbours' mean. Slowly varying curvature cancels;
/// bumps one sample wide do not. 0 without such a vertex.
/// \pre stride >= 1, spacing > 0.
template <class MeshType>
double surfaceNoiseSpacings(const MeshType &m, const VertexFaceTable &vf, double spacing,
                            std::size_t stride) {
  // One entry per sampled vertex, each written by one thread: the same
  // median for any thread count. Negative: a vertex without faces.
  const std::int64_t count = std::int64_t((m.vert.size() + stride - 1) / stride);
  std::vector<double> noise(std::size_t(count), -1.0);
#pragma omp parallel for schedule(static, 256) if (count > 4096)
  for (std::int64_t k = 0; k < count; ++k) {
    const std::size_t v = std::size_t(k) * stride;
    if (vf.degree(v) == 0) continue;
    double around = 0;
    detail::forEachNeighbour(m, vf, v,
                             [&](std::size_t u) { around += umbrellaCurvature(m, vf, u); });
    around /= double(2 * vf.degree(v));
    noise[std::size_t(k)] = std::abs(umbrellaCurvature(m, vf, v) - around);
  }
  noise.erase(std::remove_if(noise.begin(), noise.end(), [](double x) { return x < 0; }),
              noise.end());
  return detail::medianOf(noise) / spacing;
}

/// The share of the surface's area lying on planes: per region (`regionOf`
/// per face, negative: none), the faces whose normal lies within
/// `maxAngleRad` of the region's area-weighted mean normal. A flat region
/// counts whole; a curved one only the faces near its mean direction.
/// `areaVector[f]` is face f's normal times twice its area. Pure.
inline double planarAreaFraction(const std::vector<Vec3> &areaVector,
                                 const std::vector<int> &regionOf, double maxAngleRad) {
  int regions = 0;
  for (int r : regionOf) regions = std::max(regions, r + 1);
  std::vector<Vec3> sum(std::size_t(regions), Vec3(0, 0, 0));
  double total = 0;
  for (std::size_t f = 0; f < areaVector.size(); ++f) {
    total += areaVector[f].Norm();
    if (regionOf[f] >= 0) sum[std::size_t(regionOf[f])] += areaVector[f];
  }
  if (!(total > 0)) return 0;
  const double minCos = std::cos(maxAngleRad);
  double planar = 0;
  for (std::size_t f = 0; f < areaVector.size(); ++f) {
    if (regionOf[f] < 0) continue;
    const Vec3 &mean = sum[std::size_t(regionOf[f])];
    const double area = areaVector[f].Norm(), meanNorm = mean.Norm();
    if (area > 0 && meanNorm > 0 && areaVector[f] * mean >= minCos * area * meanNorm)
      planar += area;
  }
  return planar / total;
}

/// Both measures of an input mesh.
struct SurfaceMeasures {
  double noiseSpacings = 0;   ///< surfaceNoiseSpacings
  double planarFraction = 0;  ///< planarAreaFraction
};

/// The input mesh's measures: `vf` each vertex's faces, `faceRegion` each
/// face's smooth region (negative: none), `spacing` its sample spacing.
/// Both from an even sample of about `samples` vertices and faces: a
/// statistic of the whole surface.
template <class MeshType>
SurfaceMeasures measureSurface(const MeshType &m, const VertexFaceTable &vf,
                               const std::vector<int> &faceRegion, double spacing,
                               std::size_t samples = 5000) {
  SurfaceMeasures out;
  if (spacing > 0)
    out.noiseSpacings =
        surfaceNoiseSpacings(m, vf, spacing, std::max<std::size_t>(1, m.vert.size() / samples));
  std::vector<Vec3> areaVector;
  std::vector<int> regionOf;
  const std::size_t stride = std::max<std::size_t>(1, m.face.size() / samples);
  for (std::size_t f = 0; f < m.face.size(); f += stride) {
    const auto &face = m.face[f];
    const Vec3 a = positionOf(face.cV(0)), b = positionOf(face.cV(1)), c = positionOf(face.cV(2));
    areaVector.push_back((b - a) ^ (c - a));
    regionOf.push_back(faceRegion[f]);
  }
  out.planarFraction = planarAreaFraction(areaVector, regionOf, WholeMeshRules::kPlanarAngleRad);
  return out;
}

}  // namespace edge_sharpener
