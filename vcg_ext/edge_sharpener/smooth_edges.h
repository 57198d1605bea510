// Stage 1: the smooth-edge ("brown") test of Edge-Sharpener.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "report.h"
#include "util/fast_topology.h"
#include "util/mesh_labels.h"

namespace edge_sharpener {

/// Unit normal of every face in double precision, stored in labels.normal
/// until labelSmoothEdges() has read them (later readers evaluate them on
/// demand, the same bits); zero-area faces get a zero normal (their edges can
/// then never be smooth). Runs in parallel.
/// \return the number of zero-area faces.
template <class MeshType>
std::size_t computeFaceNormals(MeshType &, MeshLabels<MeshType> &labels) {
  return labels.normal.fill();
}

namespace detail {

/// The normal angle of edge i of face f (f the owner of that edge), or
/// `degenerate` when a face of it has zero area.
template <class MeshType>
double edgeNormalAngle(const MeshLabels<MeshType> &labels, const typename MeshType::FaceType *f,
                       int i, double degenerate) {
  const Vec3 na = labels.normal[f], nb = labels.normal[f->cFFp(i)];
  return na.SquaredNorm() == 0 || nb.SquaredNorm() == 0 ? degenerate : angleBetween(na, nb);
}

/// Sentinels of the edge-angle table (exact in float, below every angle).
constexpr double kBoundaryEdge = -2.0, kDegenerateEdge = -1.0, kNotOwner = -3.0;

/// Faces per block of the edge-angle pass: the double angles of one block
/// are held for the serial sum.
constexpr std::int64_t kAngleBlock = std::int64_t(1) << 17;

/// The angle of every edge of faces [b0, b1) that its face visits in
/// forEachEdge (boundary, or the lower face address of the two), else
/// kNotOwner: in double into block[3 (f - b0) + i], in float into
/// angle[3 f + i]. On every core. `stored`: the face normals, or null
/// (evaluated on demand).
template <class MeshType>
void measureEdgeAngles(const MeshType &m, const Vec3 *stored, std::int64_t b0, std::int64_t b1,
                       double *block, float *angle) {
  const std::int64_t nf = std::int64_t(m.face.size());
  const auto *f0 = m.face.data();
  const auto normalOf = [&](const typename MeshType::FaceType *f) {
    return stored ? stored[f - f0] : faceUnitNormal(*f);
  };
#pragma omp parallel for schedule(static, 4096) if (nf > kParallelMin)
  for (std::int64_t fi = b0; fi < b1; ++fi) {
    const auto *f = &m.face[fi];
    for (int i = 0; i < 3; ++i) {
      double a = kNotOwner;
      if (!f->IsD()) {
        const auto *g = f->cFFp(i);
        if (g == f) {
          a = kBoundaryEdge;
        } else if (f < g) {
          const Vec3 na = normalOf(f), nb = normalOf(g);
          a = na.SquaredNorm() == 0 || nb.SquaredNorm() == 0 ? kDegenerateEdge
                                                             : angleBetween(na, nb);
        }
      }
      block[3 * (fi - b0) + i] = a;
      angle[3 * fi + i] = float(a);  // the sentinels are exact in float
    }
  }
}

/// Counts the edges of one block of angles [begin, end) into `s` and adds
/// the measurable angles to the running sum, serially in edge order.
inline void tallyEdgeAngles(const double *begin, const double *end, SmoothEdgeStats &s,
                            double &angleSum, std::size_t &angleCount) {
  for (const double *p = begin; p < end; ++p) {
    const double a = *p;
    if (a == kNotOwner) continue;
    ++s.edges;
    if (a == kBoundaryEdge) {
      ++s.boundaryEdges;
    } else if (a == kDegenerateEdge) {
      ++s.degenerateEdges;
    } else {
      angleSum += a;
      ++angleCount;
    }
  }
}

/// Labels Smooth every visited edge whose angle lies below `threshold` (or
/// is zero), deciding in double where the float angle is too close to tell.
/// On every core. \return the number of smooth edges.
template <class MeshType>
std::int64_t labelEdgesBelow(MeshType &m, MeshLabels<MeshType> &labels, const float *angle,
                             double threshold) {
  const std::int64_t nf = std::int64_t(m.face.size());
  std::int64_t smooth = 0;
  // A float is within 2^-24 (relative) of its double: beyond 1e-6 of the
  // threshold, the float and the double fall on the same side of it.
  const double undecided = 1e-6 * threshold;
  // A positive double whose float is zero is below this (flat faces give 0).
  constexpr double kFloatZeroBound = 1e-45;
#pragma omp parallel for schedule(static, 4096) reduction(+ : smooth) if (nf > kParallelMin)
  for (std::int64_t fi = 0; fi < nf; ++fi) {
    for (int i = 0; i < 3; ++i) {
      const double af = angle[3 * fi + i];
      if (af < 0) continue;  // not visited here, boundary or degenerate
      bool isSmooth;
      if (af == 0 && threshold >= kFloatZeroBound) {
        isSmooth = true;  // a == 0, or a < kFloatZeroBound <= threshold
      } else if (af == 0 || std::abs(af - threshold) <= undecided) {
        const double a = edgeNormalAngle(labels, &m.face[fi], i, kDegenerateEdge);
        isSmooth = a < threshold || a == 0.0;
      } else {
        isSmooth = af < threshold;
      }
      if (isSmooth) {
        // Each edge is set by its one visiting face: no two threads write
        // the same label.
        labels.setEdge(&m.face[fi], i, EdgeLabel::Smooth);
        ++smooth;
      }
    }
  }
  return smooth;
}

}  // namespace detail

/// Labels Smooth every interior edge whose normal angle is below
/// `multiplier` x the mesh-wide mean of that angle (paper: "twice the
/// average"). Boundary edges and edges next to zero-area faces are never
/// smooth and do not enter the mean. Exactly coplanar faces always are.
/// Each edge's angle is computed once, in parallel, block by block; the mean
/// is summed serially in edge order (forEachEdge), so it does not depend on
/// the thread count. The angles are kept in single precision for the
/// threshold test: an angle whose float is too close to the threshold to
/// decide (or is zero) is recomputed in double, so every decision is the
/// one the double angle gives. Releases the stored face normals
/// (computeFaceNormals()) once the angles are known.
/// \pre FF topology up to date.
template <class MeshType>
SmoothEdgeStats labelSmoothEdges(MeshType &m, MeshLabels<MeshType> &labels, double multiplier) {
  const std::int64_t nf = std::int64_t(m.face.size());
  // Every entry is written by the first pass (no serial initialisation).
  const std::unique_ptr<float[]> angle(new float[3 * m.face.size()]);
  SmoothEdgeStats s;
  double angleSum = 0;
  std::size_t angleCount = 0;
  std::vector<double> block(3 * std::size_t(std::min(nf, detail::kAngleBlock)));
  const Vec3 *stored = labels.normal.stored();
  for (std::int64_t b0 = 0; b0 < nf; b0 += detail::kAngleBlock) {
    const std::int64_t b1 = std::min(nf, b0 + detail::kAngleBlock);
    detail::measureEdgeAngles(m, stored, b0, b1, block.data(), angle.get());
    detail::tallyEdgeAngles(block.data(), block.data() + 3 * (b1 - b0), s, angleSum, angleCount);
  }
  std::vector<double>().swap(block);
  labels.normal.release();
  s.meanAngleRad = angleCount ? angleSum / double(angleCount) : 0.0;
  s.thresholdRad = multiplier * s.meanAngleRad;
  s.smoothEdges = std::size_t(detail::labelEdgesBelow(m, labels, angle.get(), s.thresholdRad));
  return s;
}

}  // namespace edge_sharpener
