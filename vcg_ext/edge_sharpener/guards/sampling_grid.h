// The sampling grid of a marching-cubes mesh, and the guard that keeps a
// sharpened surface consistent with it (extended method).
//
// Marching cubes puts every vertex on an edge of an axis-aligned grid, where
// the sampled surface crosses that edge: two of its coordinates lie on grid
// lines, and of the two grid nodes bracketing it, the one its normal points
// to is outside the solid and the other inside. A sharpened surface that
// sweeps over such a node contradicts the sampling: the true surface does
// not pass there. That is what tells a blend or a designed bevel hardly
// larger than a cell (the paper's Figure 11) from a chamfer cut by the
// sampler: squaring off a fillet 1.7 cells in radius puts a node the sampler
// saw outside (0.65 cells away) inside the solid; restoring a truly sharp
// edge leaves every node where it was (the project's marching cubes of its
// exact sharp shapes: no vertex sent back).
//
// Limits: the nodes are sparse witnesses (a squared-off blend is caught only
// where a node falls between the blend and its sharp corner), and the signs
// are those of the function the grid sampled: a resampling of the true solid
// (Uniform Mesh Resampling, the marching cubes of a distance field), not a
// reconstruction's smoothed function (Screened Poisson), whose signs keep
// real features rounded. Hence opt-in (SharpenOptions::samplingGridGuard).
// Marching cubes: Lorensen and Cline, SIGGRAPH 1987; the nodes' signs as the
// exact data of a volume sampling are also what Extended Marching Cubes
// (Kobbelt et al., SIGGRAPH 2001) builds its sharp features on.
#pragma once

#include <vcg/complex/complex.h>
#include <vcg/space/distance3.h>
#include <vcg/space/triangle3.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "../report.h"
#include "../subdivision.h"
#include "../util/attributes.h"
#include "../util/geometry.h"
#include "../util/mesh_labels.h"
#include "vertex_moves.h"

namespace edge_sharpener {

/// Grid lines along one axis: {origin + i * step}. step 0: none found.
struct AxisLattice {
  double origin = 0;
  double step = 0;

  bool valid() const { return step > 0; }
  /// Lattice coordinate of x (the grid line index where it is whole).
  double coordinate(double x) const { return (x - origin) / step; }
  /// Whether x lies on a grid line, within `tolerance` steps.
  bool contains(double x, double tolerance = 1e-3) const {
    const double t = coordinate(x);
    return valid() && std::abs(t - std::round(t)) <= tolerance;
  }
};

/// The grid lines among sampled coordinates along one axis: values shared by
/// several vertices, most of them a common step apart. Pure function.
/// \param values one coordinate of many vertices (any order; copied).
/// \return the lattice fitted (least squares) to the shared values that lie
///   on it, or an invalid one when fewer than three lines are found.
inline AxisLattice fitAxisLattice(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  std::vector<double> lines;  // values shared by at least two vertices
  for (std::size_t i = 0; i < values.size();) {
    std::size_t j = i;
    while (j < values.size() && values[j] == values[i]) ++j;
    if (j - i >= 2) lines.push_back(values[i]);
    i = j;
  }
  AxisLattice lattice;
  if (lines.size() < 3) return lattice;
  // The step: the gap between consecutive lines that recurs most (within
  // 0.1%), found by a window over the sorted gaps.
  std::vector<double> gaps;
  for (std::size_t i = 1; i < lines.size(); ++i) gaps.push_back(lines[i] - lines[i - 1]);
  std::sort(gaps.begin(), gaps.end());
  std::size_t best = 0, bestCount = 0;
  for (std::size_t i = 0, j = 0; i < gaps.size(); ++i) {
    j = std::max(j, i);
    while (j + 1 < gaps.size() && gaps[j + 1] <= gaps[i] * 1.002) ++j;
    if (j - i + 1 > bestCount) bestCount = j - i + 1, best = i;
  }
  if (bestCount < 2 || !(gaps[best] > 0) || !std::isfinite(gaps[best])) return lattice;
  double step = 0;
  for (std::size_t k = best; k < best + bestCount; ++k) step += gaps[k];
  step /= double(bestCount);
  // The origin: the phase most lines share (in thousandths of a step).
  std::unordered_map<long, std::size_t> phases;
  long bestPhase = 0;
  std::size_t bestPhaseCount = 0;
  for (double x : lines) {
    double phase = std::fmod(x / step, 1.0);
    if (!std::isfinite(phase)) continue;
    if (phase < 0) phase += 1.0;
    const long key = std::lround(phase * 1000.0) % 1000;
    const std::size_t c = ++phases[key];
    if (c > bestPhaseCount || (c == bestPhaseCount && key < bestPhase))
      bestPhaseCount = c, bestPhase = key;
  }
  lattice = AxisLattice{bestPhase / 1000.0 * step, step};
  // Least squares on the lines that lie on it: x = origin + i * step.
  double n = 0, si = 0, sx = 0, sii = 0, six = 0;
  for (double x : lines) {
    if (!lattice.contains(x, 0.01)) continue;
    const double i = std::round(lattice.coordinate(x));
    n += 1, si += i, sx += x, sii += i * i, six += i * x;
  }
  const double det = n * sii - si * si;
  if (n >= 3 && det > 0) {
    const double fitStep = (n * six - si * sx) / det;
    if (fitStep > 0) lattice = AxisLattice{(sx - fitStep * si) / n, fitStep};
  }
  return lattice;
}

/// The axis-aligned grid a marching-cubes mesh was sampled on, when it was.
struct SamplingGrid {
  std::array<AxisLattice, 3> axis;
  /// Fraction of the vertices examined that lie on exactly two grid lines.
  double onGridFraction = 0;
  /// Whether the mesh was found to come from such a grid.
  bool found = false;

  double minStep() const { return std::min({axis[0].step, axis[1].step, axis[2].step}); }
  /// Position of the grid node with lattice indices `ijk`.
  Vec3 node(const std::array<long, 3> &ijk) const {
    return Vec3(axis[0].origin + ijk[0] * axis[0].step, axis[1].origin + ijk[1] * axis[1].step,
                axis[2].origin + ijk[2] * axis[2].step);
  }
  /// Grid line index at or below (`up` false) or at or above (`up` true) x
  /// along `axis`; false when it lies beyond kMaxLineIndex lines from the
  /// origin (no grid spans that many: such a point is far off the mesh).
  bool lineIndex(int a, double x, bool up, long &index) const {
    const double t = axis[a].coordinate(x);
    const double r = up ? std::ceil(t) : std::floor(t);
    if (!(std::abs(r) <= double(kMaxLineIndex))) return false;
    index = long(r);
    return true;
  }
  static constexpr long kMaxLineIndex = 1 << 20;
  /// The axis along which p lies on a grid edge (the other two coordinates
  /// on grid lines), or -1.
  int edgeAxis(const Vec3 &p) const {
    int free = -1, on = 0;
    for (int a = 0; a < 3; ++a) {
      if (axis[a].contains(p[a]))
        ++on;
      else
        free = a;
    }
    return on == 2 ? free : -1;
  }
};

/// Minimum fraction of vertices on grid edges for a mesh to count as
/// sampled on a grid (marching cubes: all but the few on grid nodes).
constexpr double kMinOnGridFraction = 0.9;

/// Infers the sampling grid from at most `maxSamples` vertices (an even
/// stride over the vertex vector, so the result is deterministic).
/// Each axis is fitted twice: first on every coordinate, then only on the
/// vertices that lie on a grid edge along another axis, whose coordinate
/// along this one is a grid line (the first fit also sees the repeated
/// coordinates of large flat faces).
template <class MeshType>
SamplingGrid detectSamplingGrid(const MeshType &m, std::size_t maxSamples = 100000) {
  SamplingGrid grid;
  std::vector<Vec3> pts;
  const std::size_t nv = m.vert.size();
  if (nv < 16) return grid;
  const std::size_t stride = std::max<std::size_t>(1, nv / maxSamples);
  for (std::size_t v = 0; v < nv; v += stride)
    if (!m.vert[v].IsD()) pts.push_back(positionOf(&m.vert[v]));
  std::vector<double> values;
  for (int a = 0; a < 3; ++a) {
    values.clear();
    for (const Vec3 &p : pts) values.push_back(p[a]);
    grid.axis[a] = fitAxisLattice(values);
  }
  for (int round = 0; round < 2; ++round)
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      if (!grid.axis[b].valid() || !grid.axis[c].valid()) continue;
      values.clear();
      for (const Vec3 &p : pts)
        if (grid.axis[b].contains(p[b]) != grid.axis[c].contains(p[c])) values.push_back(p[a]);
      if (values.size() >= 16) {
        const AxisLattice refined = fitAxisLattice(values);
        if (refined.valid()) grid.axis[a] = refined;
      }
    }
  if (!grid.axis[0].valid() || !grid.axis[1].valid() || !grid.axis[2].valid()) return grid;
  std::size_t onEdge = 0;
  for (const Vec3 &p : pts) onEdge += grid.edgeAxis(p) >= 0;
  grid.onGridFraction = double(onEdge) / double(pts.size());
  grid.found = grid.onGridFraction >= kMinOnGridFraction;
  return grid;
}

namespace detail {

/// Whether q lies in the tetrahedron abcd (closed; false when it is flat).
inline bool inTetrahedron(const Vec3 &q, const Vec3 &a, const Vec3 &b, const Vec3 &c,
                          const Vec3 &d) {
  const auto vol = [](const Vec3 &p0, const Vec3 &p1, const Vec3 &p2, const Vec3 &p3) {
    return ((p1 - p0) ^ (p2 - p0)) * (p3 - p0);
  };
  const double total = vol(a, b, c, d);
  if (total == 0) return false;
  const double s = total > 0 ? 1.0 : -1.0;
  return s * vol(q, b, c, d) >= 0 && s * vol(a, q, c, d) >= 0 && s * vol(a, b, q, d) >= 0 &&
         s * vol(a, b, c, q) >= 0;
}

}  // namespace detail

/// Whether q lies in the volume a triangle sweeps when its corners move
/// linearly from `before` to `after` (three tetrahedra of the prism). Pure.
inline bool inSweptPrism(const Vec3 &q, const std::array<Vec3, 3> &before,
                         const std::array<Vec3, 3> &after) {
  const Vec3 &a0 = before[0], &b0 = before[1], &c0 = before[2];
  const Vec3 &a1 = after[0], &b1 = after[1], &c1 = after[2];
  return detail::inTetrahedron(q, a0, b0, c0, a1) || detail::inTetrahedron(q, b0, c0, a1, b1) ||
         detail::inTetrahedron(q, c0, a1, b1, c1);
}

/// Distance from q to the triangle t (vcglib's TrianglePointDistance). Pure.
inline double pointTriangleDistance(const Vec3 &q, const std::array<Vec3, 3> &t) {
  double distance = 0;
  Vec3 closest;
  vcg::TrianglePointDistance(vcg::Triangle3<double>(t[0], t[1], t[2]), q, distance, closest);
  return distance;
}

namespace detail {

/// Hash key of a grid node: 21 bits per lattice index (enough for
/// SamplingGrid::kMaxLineIndex).
inline std::uint64_t nodeKey(const std::array<long, 3> &ijk) {
  return (std::uint64_t(ijk[0] & 0x1fffff) << 42) | (std::uint64_t(ijk[1] & 0x1fffff) << 21) |
         std::uint64_t(ijk[2] & 0x1fffff);
}

/// The steps of revertGridContradictions(), sharing what they build: the
/// moved faces, the input vertices among their corners with their input
/// normals, and the grid nodes the input's sampling classified.
template <class MeshType>
class GridContradictionGuard {
 public:
  using VertexType = typename MeshType::VertexType;
  using FaceType = typename MeshType::FaceType;

  GridContradictionGuard(MeshType &m, VertexMoves<MeshType> &moves, const SamplingGrid &grid,
                         double tolerance, GridGuardStats &stats)
      : m_(m),
        moves_(moves),
        grid_(grid),
        tolerance_(tolerance),
        stats_(stats),
        slot_(moves.firstInserted(), kNone) {}

  /// Collects the faces with a moved vertex and the input vertices among
  /// their corners. \return whether any face moved.
  bool collectMovedFaces() {
    for (std::size_t fi = 0; fi < m_.face.size(); ++fi) {
      const FaceType &f = m_.face[fi];
      if (f.IsD() || !hasMovedVertex(f)) continue;
      changed_.push_back(std::uint32_t(fi));
      for (int k = 0; k < 3; ++k) {
        const std::size_t v = indexOf(f.cV(k));
        if (isInput(v) && slot_[v] == kNone) {
          slot_[v] = std::uint32_t(sampled_.size());
          sampled_.push_back(std::uint32_t(v));
        }
      }
    }
    return !changed_.empty();
  }

  /// The collected input vertices' normals in the input: the split keeps
  /// each face's area and normal in its children, so the faces around a
  /// vertex at rest sum to the input's.
  void sumInputNormals() {
    normal_.assign(sampled_.size(), Vec3(0, 0, 0));
    for (const FaceType &f : m_.face) {
      if (f.IsD()) continue;
      std::size_t vi[3];
      bool wanted = false;
      for (int k = 0; k < 3; ++k) {
        vi[k] = indexOf(f.cV(k));
        wanted = wanted || isSampled(vi[k]);
      }
      if (!wanted) continue;
      const Vec3 p0 = moves_.exactRest(vi[0]), p1 = moves_.exactRest(vi[1]),
                 p2 = moves_.exactRest(vi[2]);
      const Vec3 n = (p1 - p0) ^ (p2 - p0);
      for (int k = 0; k < 3; ++k)
        if (isSampled(vi[k])) normal_[slot_[vi[k]]] += n;
    }
  }

  /// The two nodes bracketing each collected vertex on its grid edge: the
  /// one its normal points to is outside, the other inside (0: seen both
  /// ways). Only the nodes witness: marching cubes knows their side exactly,
  /// while it interpolates where the surface crosses the edge (near a sharp
  /// edge, a tenth of a cell off).
  void classifyNodes() {
    for (std::size_t s = 0; s < sampled_.size(); ++s) {
      const Vec3 p = moves_.exactRest(sampled_[s]);
      const int a = grid_.edgeAxis(p);
      const Vec3 &n = normal_[s];
      if (a < 0 || !(std::abs(n[a]) > 0.2 * n.Norm())) continue;
      std::array<long, 3> lo{};
      bool inRange = true;
      for (int k = 0; k < 3; ++k)
        inRange = inRange && (k == a ? grid_.lineIndex(k, p[k], false, lo[k])
                                     : grid_.lineIndex(k, p[k] + 0.5 * grid_.axis[k].step, false,
                                                       lo[k]));  // the nearest line
      if (!inRange) continue;
      std::array<long, 3> hi = lo;
      hi[a] += 1;
      const int loSide = n[a] > 0 ? -1 : 1;
      for (const auto &[ijk, nodeSide] : {std::pair{lo, loSide}, std::pair{hi, -loSide}}) {
        const auto [it, added] = side_.emplace(nodeKey(ijk), nodeSide);
        if (!added && it->second != nodeSide) it->second = 0;
      }
    }
  }

  /// Sends back the moved vertices of every face that sweeps a classified
  /// node, round after round, until none does (at rest, none does).
  void sendBackSweepingFaces() {
    constexpr int kMaxRounds = 8;
    std::vector<std::size_t> back;
    for (int round = 0; round < kMaxRounds; ++round) {
      back.clear();
      collectSweepingVertices(round == 0, back);
      if (back.empty()) break;
      ++stats_.rounds;
      std::sort(back.begin(), back.end());
      back.erase(std::unique(back.begin(), back.end()), back.end());
      for (const std::size_t v : back) sendBack(v);
    }
  }

 private:
  static constexpr std::uint32_t kNone = ~std::uint32_t(0);
  /// Lines per axis beyond which the box of a motion is not searched (a
  /// face spans a cell or two).
  static constexpr long kMaxNodesPerAxis = 8;

  std::size_t indexOf(const VertexType *v) const { return std::size_t(vcg::tri::Index(m_, v)); }
  bool isInput(std::size_t v) const { return v < moves_.firstInserted(); }
  bool isSampled(std::size_t v) const { return isInput(v) && slot_[v] != kNone; }
  bool hasMovedVertex(const FaceType &f) const {
    return moves_.isMoved(indexOf(f.cV(0))) || moves_.isMoved(indexOf(f.cV(1))) ||
           moves_.isMoved(indexOf(f.cV(2)));
  }

  /// Appends to `back` the moved vertices of the moved faces that sweep a
  /// classified node; drops the faces no longer moved. `firstRound`: counts
  /// the nodes tested and the sweeping faces.
  void collectSweepingVertices(bool firstRound, std::vector<std::size_t> &back) {
    std::size_t kept = 0;
    for (const std::uint32_t fi : changed_) {
      const FaceType &f = m_.face[fi];
      if (!hasMovedVertex(f)) continue;
      changed_[kept++] = fi;
      std::array<Vec3, 3> before, after;
      for (int k = 0; k < 3; ++k) {
        before[k] = moves_.exactRest(indexOf(f.cV(k)));
        after[k] = positionOf(f.cV(k));
      }
      if (!sweepsClassifiedNode(before, after, firstRound)) continue;
      stats_.sweepingFaces += firstRound;
      for (int k = 0; k < 3; ++k)
        if (moves_.isMoved(indexOf(f.cV(k)))) back.push_back(indexOf(f.cV(k)));
    }
    changed_.resize(kept);
  }

  /// The lattice box [from, to] of the nodes a motion may sweep; false when
  /// it is out of range or too large to search.
  bool motionBox(const std::array<Vec3, 3> &before, const std::array<Vec3, 3> &after,
                 std::array<long, 3> &from, std::array<long, 3> &to) const {
    for (int a = 0; a < 3; ++a) {
      double lo = before[0][a], hi = lo;
      for (int k = 0; k < 3; ++k)
        lo = std::min({lo, before[k][a], after[k][a]}),
        hi = std::max({hi, before[k][a], after[k][a]});
      if (!(grid_.lineIndex(a, lo, true, from[a]) && grid_.lineIndex(a, hi, false, to[a]) &&
            to[a] - from[a] < kMaxNodesPerAxis))
        return false;
    }
    return true;
  }

  /// Whether the face moving from `before` to `after` swept over a
  /// classified node that ends more than the tolerance past it.
  bool sweepsClassifiedNode(const std::array<Vec3, 3> &before, const std::array<Vec3, 3> &after,
                            bool countTests) {
    std::array<long, 3> from{}, to{};
    if (!motionBox(before, after, from, to)) return false;
    std::array<long, 3> ijk{};
    for (ijk[0] = from[0]; ijk[0] <= to[0]; ++ijk[0])
      for (ijk[1] = from[1]; ijk[1] <= to[1]; ++ijk[1])
        for (ijk[2] = from[2]; ijk[2] <= to[2]; ++ijk[2]) {
          const auto it = side_.find(nodeKey(ijk));
          if (it == side_.end() || it->second == 0) continue;
          const Vec3 q = grid_.node(ijk);
          stats_.nodesTested += countTests;
          if (inSweptPrism(q, before, after) && pointTriangleDistance(q, after) > tolerance_)
            return true;
        }
    return false;
  }

  /// Puts v back at rest (the exact rest rounded as the mesh stores it).
  void sendBack(std::size_t v) {
    assert(MeshType::CoordType::Construct(moves_.exactRest(v)) == moves_.storedRest(v));
    moves_.sendBack(v, Placement::GridRevert);
    if (isInput(v))
      ++stats_.zoneReverted;
    else
      ++stats_.reverted;
  }

  MeshType &m_;
  VertexMoves<MeshType> &moves_;
  const SamplingGrid &grid_;
  const double tolerance_;
  GridGuardStats &stats_;
  std::vector<std::uint32_t> changed_;           ///< faces with a moved vertex
  std::vector<std::uint32_t> slot_;              ///< input vertex -> index in sampled_, or kNone
  std::vector<std::uint32_t> sampled_;           ///< input vertices of the moved faces
  std::vector<Vec3> normal_;                     ///< their normals in the input
  std::unordered_map<std::uint64_t, int> side_;  ///< node -> -1 inside, 1 outside, 0 both
};

}  // namespace detail

/// Stage 5b (extended method, inputs sampled on a grid): sends back to rest
/// every moved vertex (moves.isMoved: an inserted vertex placed on its
/// planes, or a projected zone vertex) of a face whose motion swept over a
/// grid node that the input's sampling classified (a node bracketing one of
/// the face's input vertices on its grid edge) by more than `toleranceSteps`
/// cells past the moved face. Repeats until no face sweeps a node (at rest,
/// none does). Deterministic: serial, in face order.
/// \pre placement and zone projection ran; subdivide() split the faces and
///   nothing else changed the connectivity since; the mesh is compact.
/// \return the counts; reverted inserted vertices get Placement::GridRevert.
template <class MeshType>
GridGuardStats revertGridContradictions(MeshType &m, VertexMoves<MeshType> &moves,
                                        const SamplingGrid &grid, double toleranceSteps) {
  GridGuardStats stats;
  stats.gridFound = grid.found;
  if (!grid.found) return stats;
  stats.step = grid.minStep();
  detail::GridContradictionGuard<MeshType> guard(m, moves, grid, toleranceSteps * stats.step,
                                                 stats);
  if (!guard.collectMovedFaces()) return stats;
  guard.sumInputNormals();
  guard.classifyNodes();
  guard.sendBackSweepingFaces();
  return stats;
}

namespace detail {

/// Key of the pair of regions between sources i and j of an inserted vertex,
/// or kNoRegionPair (a source without a plane, or both in one region: an
/// internal crease, its own feature).
constexpr std::uint64_t kNoRegionPair = ~std::uint64_t(0);
inline std::uint64_t regionPairKey(const std::vector<int> &regionOf,
                                   const InsertedVertexSource &src, int i, int j) {
  const int a = regionOf[src.original[i]], b = regionOf[src.original[j]];
  if (a < 0 || b < 0 || a == b) return kNoRegionPair;
  return (std::uint64_t(std::min(a, b)) << 32) | std::uint64_t(std::max(a, b));
}

/// Per pair of regions: the chamfer-edge vertices moved between them, how
/// many of those the grid sent back, and whether the feature is blended.
struct FeatureTally {
  std::size_t moves = 0, reverted = 0;
  bool blended = false;
};
using FeatureTallies = std::unordered_map<std::uint64_t, FeatureTally>;

/// Tallies the chamfer-edge vertices (two sources) that moved or went back
/// as GridRevert, by the pair of regions they lie between.
template <class MeshType>
FeatureTallies tallyFeatureMoves(VertexMoves<MeshType> &moves, const std::vector<int> &regionOf) {
  FeatureTallies tally;
  const SplitPlan &plan = moves.plan();
  for (std::size_t k = 0; k < plan.inserted.size(); ++k) {
    const InsertedVertexSource &src = plan.inserted[k];
    const Placement p = moves.labels().placement[moves.firstInserted() + k];
    if (src.originalCount != 2 || (p != Placement::Moved && p != Placement::GridRevert)) continue;
    const std::uint64_t key = regionPairKey(regionOf, src, 0, 1);
    if (key == kNoRegionPair) continue;
    FeatureTally &t = tally[key];
    ++t.moves;
    t.reverted += p == Placement::GridRevert;
  }
  return tally;
}

/// Whether an inserted vertex lies between two regions whose feature is
/// blended (corners: any two of their three regions).
inline bool betweenBlendedRegions(const FeatureTallies &tally, const std::vector<int> &regionOf,
                                  const InsertedVertexSource &src) {
  for (int i = 0; i < src.originalCount; ++i)
    for (int j = i + 1; j < src.originalCount; ++j) {
      const auto it = tally.find(regionPairKey(regionOf, src, i, j));
      if (it != tally.end() && it->second.blended) return true;
    }
  return false;
}

}  // namespace detail

/// Stage 5b, second step: a feature between two regions is blended or sharp
/// along its whole length, while the grid nodes witness only where they
/// happen to fall between a blend and its squared-off edge. So when at least
/// `fraction` of the inserted vertices between two regions (by the regions
/// of their two source vertices' planes) went back to rest as GridRevert,
/// every other moved inserted vertex between them goes back too (corners:
/// when any two of their three regions form such a pair). Deterministic.
/// \pre revertGridContradictions() ran; `regionOf` is
///   SupportPlanes::region (one entry per input vertex).
/// Counts into `stats`: the blended pairs (blendedFeatures), and the
/// vertices it sends back (reverted and featureReverted).
template <class MeshType>
void revertBlendedFeatures(VertexMoves<MeshType> &moves, const std::vector<int> &regionOf,
                           double fraction, GridGuardStats &stats) {
  const SplitPlan &plan = moves.plan();
  const std::size_t n0 = moves.firstInserted();
  if (!(fraction > 0) || stats.reverted == 0 || regionOf.size() < n0) return;
  detail::FeatureTallies tally = detail::tallyFeatureMoves(moves, regionOf);
  for (auto &entry : tally) {
    detail::FeatureTally &t = entry.second;
    t.blended = t.reverted > 0 && double(t.reverted) >= fraction * double(t.moves);
    stats.blendedFeatures += t.blended;
  }
  for (std::size_t k = 0; k < plan.inserted.size(); ++k) {
    if (moves.labels().placement[n0 + k] != Placement::Moved) continue;
    if (!detail::betweenBlendedRegions(tally, regionOf, plan.inserted[k])) continue;
    moves.sendBack(n0 + k, Placement::GridRevert);
    ++stats.reverted;
    ++stats.featureReverted;
  }
}

}  // namespace edge_sharpener
