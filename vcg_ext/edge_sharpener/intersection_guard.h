// Stage 6b: no new self-intersections. Placing inserted vertices on plane
// intersections (and, in the extended method, projecting zone vertices onto
// their region's plane) can push a triangle through another one where two
// features come close (a thin wall, a concave corner, a coarse sphere). This
// stage finds every face incident to a moved vertex that intersects another
// face of the mesh (vcglib's face-face test, the one tri::Clean::
// SelfIntersections uses) and sends the responsible vertex back to its rest
// position on the input surface, repeating on the faces it changed until no
// such intersection is left.
//
// Cost: one pass over all faces against a hashed grid of the boxes the
// faces of moved vertices sweep on their way back to rest, so near-linear in
// the mesh size; the rounds then test only the face pairs this pass found
// (the first round: all of them; later rounds: those of the faces of
// vertices that retreated).
#pragma once

#include <vcg/complex/complex.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>
// (vcglib's algorithm headers need complex.h first)
#include <vcg/complex/algorithms/clean.h>

#include "mesh_labels.h"
#include "options.h"
#include "parallel.h"
#include "report.h"
#include "subdivision.h"

namespace edge_sharpener {

namespace detail {

/// Axis-aligned box in double precision: of a point, grown to hold a face
/// or the faces a moving vertex sweeps.
struct FaceBox {
  double lo[3], hi[3];
  FaceBox() = default;
  /// The box of one point.
  explicit FaceBox(const Vec3 &p) {
    for (int c = 0; c < 3; ++c) lo[c] = hi[c] = p[c];
  }
  /// Grows this box to hold `b`.
  void unite(const FaceBox &b) {
    for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], b.lo[c]), hi[c] = std::max(hi[c], b.hi[c]);
  }
  bool overlaps(const FaceBox &b) const {
    for (int c = 0; c < 3; ++c)
      if (lo[c] > b.hi[c] || b.lo[c] > hi[c]) return false;
    return true;
  }
};

/// Whether two triangles sharing no vertex meet (touching included):
/// Moeller's test, unless trianglesApart() finds a gap between them.
inline bool trianglesMeet(const std::array<Vec3, 3> &p, const std::array<Vec3, 3> &q) {
  return !trianglesApart(p, q) && vcg::NoDivTriTriIsect(p[0], p[1], p[2], q[0], q[1], q[2]);
}

/// Whether two distinct faces intersect: vcglib's test (the one
/// tri::Clean::SelfIntersections() applies: TestFaceFaceIntersection), on
/// the coordinates in double precision. Faces sharing an edge are not tested;
/// faces sharing one vertex intersect when the edge opposite the shared
/// vertex in one, pulled halfway towards it, crosses the other; other faces
/// by Moeller's triangle-triangle test, touching included, unless
/// trianglesApart() finds a gap between them. (In float,
/// Moeller's test reports nearly coplanar faces millimetres apart as
/// intersecting: its interval arithmetic divides by the tiny distances to
/// the other face's plane.) `position(vertex pointer)` gives the
/// coordinates to test at.
template <class MeshType, class FaceType = typename MeshType::FaceType, class Position>
bool facesIntersect(FaceType *f, FaceType *g, Position &&position) {
  const int shared = vcg::face::CountSharedVertex(f, g);
  if (shared == 2) return false;
  if (shared == 3) return true;
  std::array<Vec3, 3> p, q;
  for (int k = 0; k < 3; ++k) p[k] = position(f->cV(k)), q[k] = position(g->cV(k));
  if (shared == 0) return trianglesMeet(p, q);
  int i0 = 0, i1 = 0;
  vcg::face::FindSharedVertex(f, g, i0, i1);
  // As vcglib: the first segment that meets the other face decides.
  const Vec3 half = p[i0] * 0.5;
  for (int side = 0; side < 2; ++side) {
    const Vec3 *a = side == 0 ? p.data() : q.data(), *b = side == 0 ? q.data() : p.data();
    const int ia = side == 0 ? i0 : i1;
    const vcg::Segment3<double> seg(a[(ia + 1) % 3] * 0.5 + half, a[(ia + 2) % 3] * 0.5 + half);
    double u, v;
    if (vcg::IntersectionSegmentTriangle(seg, vcg::Triangle3<double>(b[0], b[1], b[2]), u, v)) {
      constexpr double kEps = 1e-6;  // vcglib's EPSIL
      return !(u + v >= 1 || u <= kEps || v <= kEps);
    }
  }
  return false;
}

/// Whether two faces cross rather than only touch: they still meet when
/// each shrinks towards its centroid by 1e-6 of its size (faces sharing a
/// vertex then share none).
template <class MeshType, class FaceType = typename MeshType::FaceType, class Position>
bool facesCross(FaceType *f, FaceType *g, Position &&position) {
  std::array<Vec3, 3> p, q;
  const auto shrink = [&](FaceType *face, std::array<Vec3, 3> &t) {
    for (int k = 0; k < 3; ++k) t[k] = position(face->cV(k));
    const Vec3 centroid = (t[0] + t[1] + t[2]) / 3.0;
    for (Vec3 &x : t) x = centroid + (x - centroid) * (1 - 1e-6);
  };
  shrink(f, p);
  shrink(g, q);
  return trianglesMeet(p, q);
}

/// Calls visit(thread, slot, gi) for every face gi of the mesh whose box
/// overlaps boxes[slot] (once per pair). A face's box is the union of
/// vertexBox(v) over its vertices v: the vertex's position, or, where
/// moving[v], the segment it may move along. `stillExtent` bounds the
/// extent, along each axis, of every face without a moving vertex (infinity
/// when unknown).
///
/// Near-linear in the mesh size: the boxes go into a hashed grid (cell: their
/// mean extent) and blocks of 4^3 cells; a vertex is flagged when its
/// position lies in a block within `stillExtent` of a box. A face of still
/// vertices that are not all flagged cannot reach a box: it is turned away
/// after reading three flags. The others look up the cells their box covers.
template <class MeshType, class VertexBox, class Visit>
void forEachBoxOverlap(const MeshType &m, const std::vector<FaceBox> &boxes, VertexBox &&vertexBox,
                       const std::vector<char> &moving, double stillExtent, Visit &&visit) {
  if (boxes.empty()) return;
  FaceBox all = boxes[0];
  double extentSum = 0;
  for (const FaceBox &b : boxes) {
    double extent = 0;
    for (int c = 0; c < 3; ++c) {
      all.lo[c] = std::min(all.lo[c], b.lo[c]);
      all.hi[c] = std::max(all.hi[c], b.hi[c]);
      extent = std::max(extent, b.hi[c] - b.lo[c]);
    }
    extentSum += extent;
  }
  double span = 0;
  for (int c = 0; c < 3; ++c) span = std::max(span, all.hi[c] - all.lo[c]);
  // Cell: twice the mean box extent (measured fastest between 1x and 4x on
  // the 1M-face benchmark mesh: fewer cells to look up, a few more boxes to
  // test), at least 2^-20 of the span (cell indices fit in 21 bits).
  double cell = std::max(2 * extentSum / double(boxes.size()), span / double(1 << 20));
  if (!(cell > 0) || !std::isfinite(cell)) cell = 1;
  // The vertex flags pay where a still face spans at most a few cells.
  constexpr int kBlockShift = 2;
  const bool flagVertices = stillExtent >= 0 && stillExtent <= 4 * cell;
  // How far from a box a vertex of a still face reaching it can lie (with a
  // margin for rounding); the grid also covers those vertices.
  const double reach = stillExtent + 1e-6 * (stillExtent + cell);
  if (flagVertices) {
    for (int c = 0; c < 3; ++c) all.lo[c] -= reach, all.hi[c] += reach;
    span += 2 * reach;
    cell = std::max(cell, span / double(1 << 20));
  }
  const double inv = 1.0 / cell;
  double top[3];         // extent of `all` in cells
  std::int32_t last[3];  // largest cell index inside `all`
  for (int c = 0; c < 3; ++c) {
    top[c] = std::min((all.hi[c] - all.lo[c]) * inv, double(1 << 20));
    last[c] = std::int32_t(top[c]);
  }
  // Cell index along axis c; -1 / last + 1 outside `all` (and for NaN: -1).
  // (Outside means beyond `top`, not beyond `last`: a point in the last,
  // partial cell is inside.)
  const auto cellOf = [&](double x, int c) -> std::int32_t {
    const double t = (x - all.lo[c]) * inv;
    if (!(t >= 0)) return -1;
    return t > top[c] ? last[c] + 1 : std::min(std::int32_t(t), last[c]);
  };
  const auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    return std::uint64_t(x) | std::uint64_t(y) << 21 | std::uint64_t(z) << 42;
  };
  const auto hash = [](std::uint64_t k) { return k * 0x9E3779B97F4A7C15ull; };
  // Occupancy bitmaps, hashed (a collision only costs a look-up): of the
  // cells the boxes cover, and of the blocks within stillExtent of a box.
  constexpr std::uint64_t kBits = std::uint64_t(1) << 20;
  const auto bit = [&](std::uint64_t k) { return hash(k) >> 44; };
  const auto isSet = [](const std::vector<std::uint64_t> &bits, std::uint64_t b) {
    return (bits[b >> 6] >> (b & 63) & 1) != 0;
  };
  const auto set = [](std::vector<std::uint64_t> &bits, std::uint64_t b) {
    bits[b >> 6] |= std::uint64_t(1) << (b & 63);
  };
  std::vector<std::uint64_t> occupied(kBits / 64, 0), nearBlock(kBits / 64, 0);
  constexpr std::int64_t kMaxCellsPerBox = 4096, kMaxCellsPerFace = 64;
  // Cells of the box [lo - grow, hi + grow], clamped to the grid.
  const auto cellRange = [&](const FaceBox &b, double grow, std::int32_t *lo, std::int32_t *hi) {
    std::int64_t cells = 1;
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::max(cellOf(b.lo[c] - grow, c), 0);
      hi[c] = std::min(cellOf(b.hi[c] + grow, c), last[c]);
      cells *= std::int64_t(hi[c]) - lo[c] + 1;
    }
    return cells;
  };
  const auto forEachCell = [&](const std::int32_t *lo, const std::int32_t *hi, auto &&f) {
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) f(key(x, y, z));
  };
  const auto blockRange = [&](const std::int32_t *lo, const std::int32_t *hi, std::int32_t *blockLo,
                              std::int32_t *blockHi) {
    for (int c = 0; c < 3; ++c)
      blockLo[c] = lo[c] >> kBlockShift, blockHi[c] = hi[c] >> kBlockShift;
  };
  // Entries (cell key, slot) bucketed by the cell's hash: a counting sort,
  // slots in increasing order within each bucket.
  std::vector<std::uint32_t> oversized;  // slots in too many cells: tested by every face
  std::vector<char> isOversized(boxes.size(), 0);
  std::size_t cellCount = 0;
  for (std::size_t q = 0; q < boxes.size(); ++q) {
    std::int32_t lo[3], hi[3];
    const std::int64_t cells = cellRange(boxes[q], 0, lo, hi);
    if (cells > kMaxCellsPerBox) {
      oversized.push_back(std::uint32_t(q));
      isOversized[q] = 1;
      continue;
    }
    cellCount += std::size_t(cells);
  }
  std::size_t bucketCount = 16;
  int bucketBits = 4;
  while (bucketCount < cellCount) bucketCount *= 2, ++bucketBits;
  const auto bucketOf = [&](std::uint64_t k) { return std::size_t(hash(k) >> (64 - bucketBits)); };
  std::vector<std::uint32_t> bucketStart(bucketCount + 1, 0);
  for (std::size_t q = 0; q < boxes.size(); ++q) {
    if (isOversized[q]) continue;
    std::int32_t lo[3], hi[3], blockLo[3], blockHi[3];
    cellRange(boxes[q], 0, lo, hi);
    forEachCell(lo, hi, [&](std::uint64_t k) {
      ++bucketStart[bucketOf(k) + 1];
      set(occupied, bit(k));
    });
    if (!flagVertices) continue;
    cellRange(boxes[q], reach, lo, hi);
    blockRange(lo, hi, blockLo, blockHi);
    forEachCell(blockLo, blockHi, [&](std::uint64_t k) { set(nearBlock, bit(k)); });
  }
  for (std::size_t b = 0; b < bucketCount; ++b) bucketStart[b + 1] += bucketStart[b];
  std::vector<std::pair<std::uint64_t, std::uint32_t>> entries(cellCount);
  {
    std::vector<std::uint32_t> fill(bucketStart.begin(), bucketStart.end() - 1);
    for (std::size_t q = 0; q < boxes.size(); ++q) {
      if (isOversized[q]) continue;
      std::int32_t lo[3], hi[3];
      cellRange(boxes[q], 0, lo, hi);
      forEachCell(lo, hi, [&](std::uint64_t k) {
        entries[fill[bucketOf(k)]++] = {k, std::uint32_t(q)};
      });
    }
  }
  // Per vertex: 1 where it moves, 2 where it lies in a block near a box
  // (3: both); without the flags, every face looks its cells up.
  constexpr char kMoving = 1, kNear = 2;
  const std::int64_t vertexCount = std::int64_t(m.vert.size());
  std::vector<char> flag(m.vert.size(), kNear);
  if (flagVertices) {
#pragma omp parallel for schedule(static, 8192) if (vertexCount > kParallelMin)
    for (std::int64_t v = 0; v < vertexCount; ++v) {
      if (m.vert[v].IsD()) continue;
      if (moving[v]) {
        flag[v] = kMoving;
        continue;
      }
      const Vec3 p = positionOf(&m.vert[v]);
      std::int32_t block[3];
      bool inside = true;
      for (int c = 0; c < 3; ++c) {
        const std::int32_t k = cellOf(p[c], c);
        inside &= k >= 0 && k <= last[c];
        block[c] = k >> kBlockShift;
      }
      flag[v] = inside && isSet(nearBlock, bit(key(block[0], block[1], block[2]))) ? kNear : 0;
    }
  }

  // The pass over the faces runs on every core; each thread keeps its own
  // once-per-pair stamps and tells `visit` its number.
  const int threads = std::int64_t(m.face.size()) >= kParallelMin ? maxThreads() : 1;
  std::vector<std::vector<std::uint32_t>> stamps(
      threads, std::vector<std::uint32_t>(boxes.size(), std::numeric_limits<std::uint32_t>::max()));
  const std::int64_t faceCount = std::int64_t(m.face.size());
#pragma omp parallel for schedule(static, 8192) num_threads(threads)
  for (std::int64_t gi = 0; gi < faceCount; ++gi) {
    const auto &g = m.face[gi];
    if (g.IsD()) continue;
    const std::size_t v[3] = {vcg::tri::Index(m, g.cV(0)), vcg::tri::Index(m, g.cV(1)),
                              vcg::tri::Index(m, g.cV(2))};
    const char any = flag[v[0]] | flag[v[1]] | flag[v[2]];
    const char every = flag[v[0]] & flag[v[1]] & flag[v[2]];
    if (!(any & kMoving) && !(every & kNear) && oversized.empty()) continue;
    const int thread = threadNumber();
    std::vector<std::uint32_t> &stamp = stamps[thread];
    FaceBox gb = vertexBox(v[0]);
    for (int k = 1; k < 3; ++k) gb.unite(vertexBox(v[k]));
    const auto test = [&](std::uint32_t q) {
      if (stamp[q] == gi) return;
      stamp[q] = std::uint32_t(gi);
      if (gb.overlaps(boxes[q])) visit(thread, q, std::uint32_t(gi));
    };
    for (const std::uint32_t q : oversized) test(q);
    std::int32_t lo[3], hi[3];
    const std::int64_t cells = cellRange(gb, 0, lo, hi);
    bool outside = false;
    for (int c = 0; c < 3; ++c) outside |= lo[c] > hi[c];
    if (outside) continue;
    if (cells > kMaxCellsPerFace) {
      for (std::size_t q = 0; q < boxes.size(); ++q) test(std::uint32_t(q));
      continue;
    }
    forEachCell(lo, hi, [&](std::uint64_t k) {
      if (!isSet(occupied, bit(k))) return;
      const std::size_t b = bucketOf(k);
      for (std::uint32_t e = bucketStart[b]; e < bucketStart[b + 1]; ++e)
        if (entries[e].first == k) test(entries[e].second);
    });
  }
}

/// For each of n query slots, a sorted list of face indices (compressed rows).
struct NearLists {
  std::vector<std::uint32_t> offset, face;
  const std::uint32_t *begin(std::size_t q) const { return face.data() + offset[q]; }
  const std::uint32_t *end(std::size_t q) const { return face.data() + offset[q + 1]; }

  /// From per-thread lists of (slot, face) pairs; the result does not
  /// depend on how the pairs were split among threads.
  static NearLists fromPairs(
      std::size_t n,
      const std::vector<PerThread<std::vector<std::pair<std::uint32_t, std::uint32_t>>>> &pairs) {
    NearLists near;
    near.offset.assign(n + 1, 0);
    for (const auto &list : pairs)
      for (const auto &[q, gi] : list.value) ++near.offset[q + 1];
    for (std::size_t q = 0; q < n; ++q) near.offset[q + 1] += near.offset[q];
    near.face.resize(near.offset[n]);
    std::vector<std::uint32_t> fill(near.offset.begin(), near.offset.end() - 1);
    for (const auto &list : pairs)
      for (const auto &[q, gi] : list.value) near.face[fill[q]++] = gi;
    for (std::size_t q = 0; q < n; ++q)
      std::sort(near.face.begin() + near.offset[q], near.face.begin() + near.offset[q + 1]);
    return near;
  }
};

}  // namespace detail

/// Stage 6b: moves vertices back towards rest until no face incident to a
/// moved vertex intersects another face (facesIntersect(): vcglib's test for
/// faces sharing a vertex, a contact-tolerant Moeller test otherwise). A
/// moved vertex is an inserted vertex placed by placeInsertedVertices()
/// (Placement::Moved), or an original vertex whose position differs from
/// `originalRest` (extended method: a projected zone vertex).
///
/// Each round finds the intersecting pairs among the faces that changed,
/// leaving alone those that also meet with every vertex at rest (in the
/// input: moving back would not resolve them; counted in `remaining`),
/// unless they only touched at rest and now cross (facesCross()).
/// Each pair retreats one moved vertex of its two faces along the segment to
/// its rest position: to the farthest multiple of 1/16 of its displacement
/// at which none of its faces intersects a face nearby (as above: where they
/// do not at rest), folds over (normal
/// turned against the one at rest) or gets an angle below
/// `degenerateAngleRad`; else to rest. Of the pair's moved vertices, the one
/// that can stay farthest out retreats (ties: the one in more pairs, then
/// the smaller displacement, then the lower index). A vertex sent to rest
/// that leaves a face below that angle sends the face's other moved
/// vertices to rest too, so cleanup's guarantee (no such face holds a moved
/// vertex) is kept. Inserted vertices that retreat are labelled
/// Placement::IntersectionRevert. Deterministic (serial, index order).
/// `longestInputEdge`: the input's longest edge (SharpenReport), which bounds
/// the faces the split did not make.
/// \pre removeDegenerateTriangles() ran (deleted elements not yet compacted).
template <class MeshType>
IntersectionStats revertSelfIntersections(
    MeshType &m, const SplitPlan &plan, MeshLabels<MeshType> &labels,
    const std::vector<typename MeshType::CoordType> &originalRest, double degenerateAngleRad,
    double longestInputEdge) {
  using Coord = typename MeshType::CoordType;
  IntersectionStats s;
  const std::size_t n0 = plan.originalVertexCount;
  std::vector<char> moved(m.vert.size(), 0);
  std::size_t movedCount = 0;
  for (std::size_t v = 0; v < m.vert.size(); ++v) {
    if (m.vert[v].IsD()) continue;
    moved[v] = v >= n0 ? labels.placement[&m.vert[v]] == Placement::Moved
                       : !originalRest.empty() && !(m.vert[v].cP() == originalRest[v]);
    movedCount += moved[v];
  }
  if (movedCount == 0) return s;

  // Faces of the moved vertices (in face order), and for each moved vertex
  // its faces (CSR); and a bound on the extent along an axis of the other
  // faces (for forEachBoxOverlap()): the input's faces are no wider than its
  // longest edge, and only the faces the split made (whose vertices cleanup
  // may have merged across two input faces) are measured.
  std::vector<std::uint32_t> query, offset(m.vert.size() + 1, 0), incident;
  double stillExtent = longestInputEdge;
  {
    const std::int64_t nf = std::int64_t(m.face.size());
    const int threads = nf >= kParallelMin ? detail::maxThreads() : 1;
    std::vector<detail::PerThread<std::vector<std::uint32_t>>> parts(threads);
#pragma omp parallel num_threads(threads) reduction(max : stillExtent)
    {
      std::vector<std::uint32_t> &part = parts[detail::threadNumber()].value;
#pragma omp for schedule(static, 8192)
      for (std::int64_t fi = 0; fi < nf; ++fi) {
        const auto &f = m.face[fi];
        if (f.IsD()) continue;
        bool any = false;
        for (int k = 0; k < 3; ++k) any |= moved[vcg::tri::Index(m, f.cV(k))] != 0;
        if (any) {
          part.push_back(std::uint32_t(fi));
          continue;
        }
        const FaceLabel label = labels.face[fi];
        if (label != FaceLabel::Chamfer && label != FaceLabel::Corner) continue;  // an input face
        const Vec3 p0 = positionOf(f.cV(0)), p1 = positionOf(f.cV(1)), p2 = positionOf(f.cV(2));
        for (int c = 0; c < 3; ++c)
          stillExtent = std::max(stillExtent,
                                 std::max({p0[c], p1[c], p2[c]}) - std::min({p0[c], p1[c], p2[c]}));
      }
    }
    for (const auto &part : parts) query.insert(query.end(), part.value.begin(), part.value.end());
    std::sort(query.begin(), query.end());
  }
  for (const std::uint32_t fi : query)
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = vcg::tri::Index(m, m.face[fi].cV(k));
      if (moved[v]) ++offset[v + 1];
    }
  for (std::size_t v = 0; v + 1 < offset.size(); ++v) offset[v + 1] += offset[v];
  incident.resize(offset.back());
  {
    std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
    for (const std::uint32_t fi : query)
      for (int k = 0; k < 3; ++k) {
        const std::size_t v = vcg::tri::Index(m, m.face[fi].cV(k));
        if (moved[v]) incident[fill[v]++] = fi;
      }
  }
  if (!std::isfinite(stillExtent)) stillExtent = std::numeric_limits<double>::infinity();
  const auto restOf = [&](std::size_t v) {
    return v >= n0 ? Coord::Construct(plan.inserted[v - n0].rest) : originalRest[v];
  };
  // Where every vertex was before sharpening moved it.
  const auto restPosition = [&](const auto *vp) {
    const std::size_t v = vcg::tri::Index(m, vp);
    const bool hasRest = v < n0 ? !originalRest.empty() : v - n0 < plan.inserted.size();
    return hasRest ? Vec3::Construct(restOf(v)) : positionOf(vp);
  };
  // How two faces meet: not at all, in a contact sharpening made, or in one
  // that is there at rest too (in the input: moving back would not resolve
  // it) — unless the faces only touched at rest and now cross.
  enum class Contact { None, New, AtRest };
  const auto contactOf = [&](std::uint32_t fi, std::uint32_t gi) {
    auto *f = &m.face[std::min(fi, gi)], *g = &m.face[std::max(fi, gi)];
    const auto here = [](const auto *vp) { return positionOf(vp); };
    if (!detail::facesIntersect<MeshType>(f, g, here)) return Contact::None;
    if (!detail::facesIntersect<MeshType>(f, g, restPosition)) return Contact::New;
    return detail::facesCross<MeshType>(f, g, restPosition) ||
                   !detail::facesCross<MeshType>(f, g, here)
               ? Contact::AtRest
               : Contact::New;
  };
  // Moved vertices only ever go back along the segment to rest, so a face
  // can only meet the faces its swept box (placed and rest positions of its
  // vertices) overlaps: one pass over the mesh finds them for all rounds.
  const detail::NearLists nearOfQuery = [&] {
    std::vector<detail::FaceBox> boxes;
    boxes.reserve(query.size());
    const auto sweptBox = [&](std::size_t v) {
      detail::FaceBox b(positionOf(&m.vert[v]));
      if (moved[v]) b.unite(detail::FaceBox(Vec3::Construct(restOf(v))));
      return b;
    };
    for (const std::uint32_t fi : query) {
      detail::FaceBox b = sweptBox(vcg::tri::Index(m, m.face[fi].cV(0)));
      for (int k = 1; k < 3; ++k) b.unite(sweptBox(vcg::tri::Index(m, m.face[fi].cV(k))));
      boxes.push_back(b);
    }
    std::vector<detail::PerThread<std::vector<std::pair<std::uint32_t, std::uint32_t>>>> hits(
        detail::maxThreads());
    detail::forEachBoxOverlap(m, boxes, sweptBox, moved, stillExtent,
                              [&](int thread, std::uint32_t q, std::uint32_t gi) {
                                if (gi != query[q]) hits[thread].value.emplace_back(q, gi);
                              });
    return detail::NearLists::fromPairs(query.size(), hits);
  }();
  // Slot of each face of a moved vertex in nearOfQuery.
  std::vector<std::uint32_t> querySlot(m.face.size(), 0);
  for (std::size_t q = 0; q < query.size(); ++q) querySlot[query[q]] = std::uint32_t(q);
  // Pairs of faces with at least one face in `faces` (faces of moved
  // vertices) in a new contact, smaller index first, sorted and unique.
  // Pairs in a contact there at rest too go to `atRest`.
  std::vector<char> inRound(m.face.size(), 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> atRest;
  const auto intersectingPairs = [&](const std::vector<std::uint32_t> &faces) {
    for (const std::uint32_t fi : faces) inRound[fi] = 1;
    std::vector<detail::PerThread<std::vector<std::pair<std::uint32_t, std::uint32_t>>>> found(
        detail::maxThreads()),
        foundAtRest(detail::maxThreads());
    const std::int64_t count = std::int64_t(faces.size());
#pragma omp parallel for schedule(dynamic, 64) if (count >= 4096)
    for (std::int64_t r = 0; r < count; ++r) {
      const std::uint32_t fi = faces[r];
      const std::uint32_t q = querySlot[fi];
      for (const std::uint32_t *near = nearOfQuery.begin(q); near != nearOfQuery.end(q); ++near) {
        const std::uint32_t gi = *near;
        if (inRound[gi] && gi < fi) continue;  // a pair of this round's faces: tested once
        const Contact contact = contactOf(fi, gi);
        if (contact == Contact::None) continue;
        (contact == Contact::AtRest ? foundAtRest : found)[detail::threadNumber()]
            .value.emplace_back(std::min(fi, gi), std::max(fi, gi));
      }
    }
    for (const std::uint32_t fi : faces) inRound[fi] = 0;
    for (const auto &list : foundAtRest)
      atRest.insert(atRest.end(), list.value.begin(), list.value.end());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (const auto &list : found) pairs.insert(pairs.end(), list.value.begin(), list.value.end());
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
  };
  // Position of each moved vertex as placed, and how far along it still is,
  // in steps of 1/kFull of its displacement (kFull: all the way).
  constexpr int kFull = 16;
  std::vector<Coord> placed(m.vert.size());
  std::vector<std::uint8_t> level(m.vert.size(), 0);
  for (std::size_t v = 0; v < m.vert.size(); ++v)
    if (moved[v]) placed[v] = m.vert[v].cP(), level[v] = kFull;
  const auto positionAt = [&](std::size_t v, int lv) {
    if (lv == kFull) return placed[v];
    const Vec3 r = Vec3::Construct(restOf(v));
    return lv == 0 ? restOf(v)
                   : Coord::Construct(r + (Vec3::Construct(placed[v]) - r) * (lv / double(kFull)));
  };
  const auto minAngleOf = [&](std::uint32_t fi) {
    const auto &f = m.face[fi];
    return minTriangleAngle(positionOf(f.cV(0)), positionOf(f.cV(1)), positionOf(f.cV(2)));
  };
  const auto normalOf = [&](std::uint32_t fi) {
    const auto &f = m.face[fi];
    const Vec3 a = positionOf(f.cV(0));
    return (positionOf(f.cV(1)) - a) ^ (positionOf(f.cV(2)) - a);
  };

  std::vector<std::uint32_t> changedNow;
  std::vector<char> justChanged(m.vert.size(), 0);
  const auto markChanged = [&](std::size_t v) {
    if (!justChanged[v]) changedNow.push_back(std::uint32_t(v)), justChanged[v] = 1;
  };
  const auto countRetreat = [&](std::size_t v) {
    if (v < n0) return;  // zone vertices: counted when back at rest (revert)
    if (labels.placement[&m.vert[v]] == Placement::Moved) ++s.reverted;
    labels.placement[&m.vert[v]] = Placement::IntersectionRevert;
  };

  // To rest, with the degenerate-face cascade.
  const auto revert = [&](std::size_t first) {
    std::vector<std::size_t> stack{first};
    while (!stack.empty()) {
      const std::size_t v = stack.back();
      stack.pop_back();
      if (!moved[v]) continue;
      countRetreat(v);
      if (v < n0) ++s.zoneReverted;
      moved[v] = 0;
      level[v] = 0;
      m.vert[v].P() = restOf(v);
      markChanged(v);
      for (std::uint32_t j = offset[v]; j < offset[v + 1]; ++j) {
        if (minAngleOf(incident[j]) >= degenerateAngleRad) continue;
        for (int k = 0; k < 3; ++k) {
          const std::size_t u = vcg::tri::Index(m, m.face[incident[j]].cV(k));
          if (moved[u]) stack.push_back(u);
        }
      }
    }
  };
  // The farthest level below the current one at which v's faces meet none
  // of the faces near them (their lists in nearOfQuery: those their swept
  // boxes overlap, all a face can meet on its way back to rest), fold over
  // or get too small an angle (0: none). v stays put.
  const auto feasibleLevel = [&](std::size_t v) {
    const Coord now = m.vert[v].cP();
    std::vector<Vec3> restNormal;
    m.vert[v].P() = restOf(v);
    for (std::uint32_t j = offset[v]; j < offset[v + 1]; ++j)
      restNormal.push_back(normalOf(incident[j]));
    int found = 0;
    for (int lv = level[v] - 1; lv > 0 && found == 0; --lv) {
      m.vert[v].P() = positionAt(v, lv);
      bool ok = true;
      for (std::uint32_t j = offset[v]; j < offset[v + 1] && ok; ++j) {
        const std::uint32_t fi = incident[j];
        ok = minAngleOf(fi) >= degenerateAngleRad && normalOf(fi) * restNormal[j - offset[v]] > 0;
        const std::uint32_t q = querySlot[fi];
        for (const std::uint32_t *o = nearOfQuery.begin(q); o != nearOfQuery.end(q) && ok; ++o)
          ok = contactOf(fi, *o) != Contact::New;
      }
      if (ok) found = lv;
    }
    m.vert[v].P() = now;
    return found;
  };

  std::vector<std::uint32_t> score(m.vert.size(), 0);
  constexpr int kMaxRounds = 1000;
  for (int round = 0; round < kMaxRounds && !query.empty(); ++round) {
    const auto pairs = intersectingPairs(query);
    if (round == 0) s.intersectingPairs = pairs.size();
    if (pairs.empty()) break;
    ++s.rounds;
    const auto forEachMoved = [&](const std::pair<std::uint32_t, std::uint32_t> &p, auto &&visit) {
      for (const std::uint32_t fi : {p.first, p.second})
        for (int k = 0; k < 3; ++k) {
          const std::size_t v = vcg::tri::Index(m, m.face[fi].cV(k));
          if (moved[v]) visit(v);
        }
    };
    // Score: in how many of this round's pairs a moved vertex is.
    std::vector<std::uint32_t> candidates;
    for (const auto &p : pairs)
      forEachMoved(p, [&](std::size_t v) {
        if (score[v]++ == 0) candidates.push_back(std::uint32_t(v));
      });
    changedNow.clear();
    for (const auto &p : pairs) {
      bool taken = false;  // a vertex of the pair moved this round: look again next round
      for (const std::uint32_t fi : {p.first, p.second})
        for (int k = 0; k < 3; ++k) taken |= justChanged[vcg::tri::Index(m, m.face[fi].cV(k))] != 0;
      if (taken) continue;
      // The vertex that can stay farthest out; ties: in more pairs, smaller
      // displacement, lower index.
      std::size_t best = std::numeric_limits<std::size_t>::max();
      int bestLevel = -1;
      double bestDisplacement = 0;
      forEachMoved(p, [&](std::size_t v) {
        if (v == best) return;
        const int lv = feasibleLevel(v);
        const double d = (positionOf(&m.vert[v]) - Vec3::Construct(restOf(v))).SquaredNorm();
        const bool better = lv != bestLevel           ? lv > bestLevel
                            : score[v] != score[best] ? score[v] > score[best]
                            : d != bestDisplacement   ? d < bestDisplacement
                                                      : v < best;
        if (better) best = v, bestLevel = lv, bestDisplacement = d;
      });
      if (best == std::numeric_limits<std::size_t>::max()) {
        atRest.push_back(p);  // no moved vertex left: the pair is there at rest
        continue;
      }
      if (bestLevel == 0) {
        revert(best);
        continue;
      }
      countRetreat(best);
      level[best] = std::uint8_t(bestLevel);
      m.vert[best].P() = positionAt(best, bestLevel);
      markChanged(best);
    }
    for (const std::uint32_t v : candidates) score[v] = 0;
    // Next round: the faces of the vertices just moved.
    query.clear();
    for (const std::uint32_t v : changedNow) {
      query.insert(query.end(), incident.begin() + offset[v], incident.begin() + offset[v + 1]);
      justChanged[v] = 0;
    }
    std::sort(query.begin(), query.end());
    query.erase(std::unique(query.begin(), query.end()), query.end());
  }
  std::sort(atRest.begin(), atRest.end());
  s.remaining = std::size_t(std::unique(atRest.begin(), atRest.end()) - atRest.begin());
  return s;
}

}  // namespace edge_sharpener
