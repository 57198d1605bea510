// Two-sided surface distance between two triangle meshes, the way Metro measures it
// (Cignoni, Rocchini, Scopigno 1998): points sampled on one surface (all its vertices, points
// along its edges and points spread over its faces in proportion to area) are looked up on
// the other surface through a uniform grid. Built on vcglib's HausdorffSampler and
// SurfaceSampling; a fixed seed makes the result deterministic.
// Two ways of spreading the samples (DistanceSampling): the project's own (stratified face
// subdivision, a quarter as many edge samples) and MeshLab's "Hausdorff Distance" filter's
// (the same count of vertex, edge and Montecarlo face samples), so that figures can be compared
// with what a MeshLab user measures.
#pragma once

#include <vcg/complex/complex.h>
// (vcglib's algorithm headers need complex.h first)
#include <vcg/complex/algorithms/point_sampling.h>
#include <vcg/complex/algorithms/update/bounding.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace edge_sharpener {

/// How the sampled side's points are spread.
enum class DistanceSampling {
  /// Every vertex, N/4 points along the edges (by length), N points by stratified subdivision of
  /// the faces (FaceSubdivision, random point per cell).
  uniform,
  /// As MeshLab 2020.09's "Hausdorff Distance" filter with vertices, edges and faces sampled
  /// (filter_sampling.cpp): VertexUniform(N) (every vertex when N >= vertex count), EdgeUniform(N)
  /// over the non-faux unique edges, Montecarlo(N) over the faces.
  meshlab,
};

/// vcglib's MarsenneTwisterRNG default seed: the state of MeshLab's sampling generator when
/// its first Hausdorff Distance filter runs in a fresh meshlabserver.
constexpr unsigned kMeshLabSeed = 5489u;

inline const char *distanceSamplingName(DistanceSampling mode) {
  return mode == DistanceSampling::meshlab ? "meshlab" : "uniform";
}

struct DistanceOptions {
  DistanceSampling sampling = DistanceSampling::uniform;
  /// Points spread over the faces of each sampled mesh, in proportion to face area.
  /// Edges get a quarter as many points, in proportion to length.
  std::size_t faceSamples = 200000;
  bool sampleVertices = true;
  bool sampleEdges = true;
  bool sampleFaces = true;
  /// Seeds vcglib's sampling generator: same seed, same numbers. Uniform mode seeds it before
  /// each side; MeshLab mode once, before the forward side, and the backward side continues
  /// the sequence, as two Hausdorff Distance filters run one after the other in one MeshLab
  /// session do (kMeshLabSeed is where a fresh MeshLab's generator starts).
  unsigned seed = 1;
};

/// Distances from the points sampled on one mesh to the other mesh's surface.
struct OneSidedDistance {
  double min = 0;
  double max = 0;
  double mean = 0;
  double rms = 0;
  std::size_t samples = 0;
};

struct DistanceReport {
  /// A sampled, measured against the reference.
  OneSidedDistance forward;
  /// The reference sampled, measured against A.
  OneSidedDistance backward;
  /// Bounding-box diagonal of the reference: the unit of the percentages.
  double referenceDiagonal = 0;

  /// The Hausdorff distance.
  double max() const { return std::max(forward.max, backward.max); }
  double mean() const { return 0.5 * (forward.mean + backward.mean); }
  double rms() const {
    return std::sqrt(0.5 * (forward.rms * forward.rms + backward.rms * backward.rms));
  }

  double percentOfDiagonal(double distance) const {
    return referenceDiagonal > 0 ? 100.0 * distance / referenceDiagonal : 0.0;
  }
  double maxPercent() const { return percentOfDiagonal(max()); }
  double meanPercent() const { return percentOfDiagonal(mean()); }
  double rmsPercent() const { return percentOfDiagonal(rms()); }
};

namespace detail {

/// Feeds sample points to a HausdorffSampler without touching the sampled mesh: vcglib's
/// own AddVert stores the distance in the vertex quality.
template <class M>
class DistanceSampleSink {
 public:
  using CoordType = typename M::CoordType;

  explicit DistanceSampleSink(vcg::tri::HausdorffSampler<M> &sampler) : sampler_(sampler) {}

  void AddVert(const typename M::VertexType &v) { sampler_.AddSample(v.cP(), CoordType(0, 0, 0)); }
  void AddFace(const typename M::FaceType &f, const CoordType &barycentric) {
    const CoordType p =
        f.cP(0) * barycentric[0] + f.cP(1) * barycentric[1] + f.cP(2) * barycentric[2];
    sampler_.AddSample(p, CoordType(0, 0, 0));
  }

 private:
  vcg::tri::HausdorffSampler<M> &sampler_;
};

}  // namespace detail

/// The box to build a closest-face grid of `target` on, for queries at points of `queries`:
/// both meshes' boxes with a margin. vcglib's grid spans only the target by default, and a
/// query point just inside its far border can be rounded into a cell past its end (a crash).
/// \pre both bounding boxes are up to date.
template <class M>
vcg::Box3<typename M::ScalarType> closestFaceGridBox(const M &target, const M &queries) {
  using Scalar = typename M::ScalarType;
  vcg::Box3<Scalar> span = target.bbox;
  span.Add(queries.bbox);
  span.Offset(span.Diag() * Scalar(0.05) + Scalar(1e-6));
  return span;
}

namespace detail {

template <class M>
OneSidedDistance summarize(const vcg::tri::HausdorffSampler<M> &sampler) {
  OneSidedDistance result;
  result.samples = static_cast<std::size_t>(sampler.n_total_samples);
  if (result.samples == 0) return result;
  result.min = sampler.min_dist;
  result.max = sampler.max_dist;
  result.mean = sampler.mean_dist / sampler.n_total_samples;
  // HausdorffSampler accumulates the sum of squares in RMS_dist.
  result.rms = std::sqrt(sampler.RMS_dist / sampler.n_total_samples);
  return result;
}

template <class M>
OneSidedDistance sampleDistance(M &sampled, M &target, double searchRadius,
                                const DistanceOptions &options, bool seedGenerator) {
  using Sink = DistanceSampleSink<M>;
  using Sampling = vcg::tri::SurfaceSampling<M, Sink>;

  vcg::tri::HausdorffSampler<M> sampler(&target);
  sampler.unifGridFace.Set(target.face.begin(), target.face.end(),
                           closestFaceGridBox(target, sampled));
  // Samples at this distance or farther are dropped, and the member starts uninitialised.
  sampler.dist_upper_bound = static_cast<typename M::ScalarType>(searchRadius);
  Sink sink(sampler);

  if (options.sampling == DistanceSampling::meshlab) {
    if (seedGenerator) Sampling::SamplingRandomGenerator().initialize(options.seed);
    const int n = static_cast<int>(options.faceSamples);
    if (options.sampleVertices) Sampling::VertexUniform(sampled, sink, n);
    if (sampled.fn > 0 && n > 0) {
      if (options.sampleEdges) Sampling::EdgeUniform(sampled, sink, n, /*sampleFauxEdge=*/false);
      if (options.sampleFaces) Sampling::Montecarlo(sampled, sink, n);
    }
    return detail::summarize(sampler);
  }
  Sampling::SamplingRandomGenerator().initialize(options.seed);
  if (options.sampleVertices) Sampling::AllVertex(sampled, sink);
  if (sampled.fn > 0) {
    if (options.sampleEdges && options.faceSamples >= 4)
      Sampling::EdgeUniform(sampled, sink, static_cast<int>(options.faceSamples / 4));
    if (options.sampleFaces && options.faceSamples > 0)
      Sampling::FaceSubdivision(sampled, sink, static_cast<int>(options.faceSamples),
                                /*randSample=*/true);
  }

  return detail::summarize(sampler);
}

}  // namespace detail

/// Twice the total area of the mesh's live faces.
template <class M>
double doubleSurfaceArea(const M &m) {
  double sum = 0;
  for (const auto &f : m.face)
    if (!f.IsD()) sum += vcg::DoubleArea(f);
  return sum;
}

/// Two-sided distance between `a` and `reference`. Positions are not modified; bounding
/// boxes and face normals of both meshes are updated. Requires per-face marks.
/// \throw std::invalid_argument when either mesh has no surface (no face of non-zero
///        area): vcglib's area-proportional sampling never ends on one.
template <class M>
DistanceReport measureDistance(M &a, M &reference, const DistanceOptions &options = {}) {
  vcg::tri::RequirePerFaceMark(a);
  vcg::tri::RequirePerFaceMark(reference);
  for (const M *m : {&a, &reference})
    if (!(doubleSurfaceArea(*m) > 0))
      throw std::invalid_argument(
          "mesh has zero surface area (every face is degenerate): no distance to measure");
  vcg::tri::UpdateBounding<M>::Box(a);
  vcg::tri::UpdateBounding<M>::Box(reference);

  // No point of either mesh is farther than this from any point of the other.
  vcg::Box3<typename M::ScalarType> both = a.bbox;
  both.Add(reference.bbox);
  const double searchRadius = 2.0 * std::max<double>(both.Diag(), 1e-30) + 1e-30;

  DistanceReport report;
  report.referenceDiagonal = reference.bbox.Diag();
  report.forward = detail::sampleDistance(a, reference, searchRadius, options, true);
  report.backward = detail::sampleDistance(reference, a, searchRadius, options,
                                           options.sampling != DistanceSampling::meshlab);
  return report;
}

}  // namespace edge_sharpener
