// The intersection guard's broad phase: which faces of the mesh may reach
// which query boxes. The boxes go into a hashed grid (cell: twice their mean
// extent) grouped in blocks of 4^3 cells; one pass over the faces then looks
// up the cells each face's box covers, after turning away, by three vertex
// flags, the still faces too far from every box. Near-linear in the mesh
// size.
#pragma once

#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "../util/attributes.h"
#include "../util/fast_topology.h"
#include "../util/parallel.h"

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

/// A hashed grid over a fixed set of query boxes, and the pass over a mesh's
/// faces that finds, for each face, the boxes its own box overlaps.
class BoxHashGrid {
 public:
  /// Hashes `boxes` (not empty; kept by reference). `stillExtent` bounds the
  /// extent, along each axis, of every face without a moving vertex
  /// (infinity when unknown): within it of a box, blocks are flagged.
  BoxHashGrid(const std::vector<FaceBox> &boxes, double stillExtent) : boxes_(boxes) {
    chooseCells(stillExtent);
    const std::size_t cellCount = setAsideOversized();
    countEntriesAndMarkCells(cellCount);
    fillEntries(cellCount);
  }

  /// Calls visit(thread, slot, gi) for every face gi of `m` whose box
  /// overlaps boxes[slot] (once per pair). A face's box is the union of
  /// vertexBox(v) over its vertices v: the vertex's position, or, where
  /// moving[v], the segment it may move along. Runs on every core; each
  /// thread keeps its own once-per-pair stamps and tells `visit` its number.
  template <class MeshType, class VertexBox, class Visit>
  void forEachOverlap(const MeshType &m, VertexBox &&vertexBox, const std::vector<char> &moving,
                      Visit &&visit) const {
    const std::vector<char> flag = flagVertices(m, moving);
    const int threads = std::int64_t(m.face.size()) >= kParallelMin ? maxThreads() : 1;
    std::vector<std::vector<std::uint32_t>> stamps(
        threads,
        std::vector<std::uint32_t>(boxes_.size(), std::numeric_limits<std::uint32_t>::max()));
    const std::int64_t faceCount = std::int64_t(m.face.size());
#pragma omp parallel for schedule(static, 8192) num_threads(threads)
    for (std::int64_t gi = 0; gi < faceCount; ++gi) {
      const auto &g = m.face[gi];
      if (g.IsD()) continue;
      const std::size_t v[3] = {vcg::tri::Index(m, g.cV(0)), vcg::tri::Index(m, g.cV(1)),
                                vcg::tri::Index(m, g.cV(2))};
      const char any = flag[v[0]] | flag[v[1]] | flag[v[2]];
      const char every = flag[v[0]] & flag[v[1]] & flag[v[2]];
      if (!(any & kMoving) && !(every & kNear) && oversized_.empty()) continue;
      const int thread = threadNumber();
      FaceBox gb = vertexBox(v[0]);
      for (int k = 1; k < 3; ++k) gb.unite(vertexBox(v[k]));
      visitBoxesOf(gi, gb, stamps[thread],
                   [&](std::uint32_t q) { visit(thread, q, std::uint32_t(gi)); });
    }
  }

 private:
  // Per vertex: 1 where it moves, 2 where it lies in a block near a box
  // (3: both); without the flags, every face looks its cells up.
  static constexpr char kMoving = 1, kNear = 2;
  static constexpr int kBlockShift = 2;  // blocks of 4^3 cells
  static constexpr std::uint64_t kBits = std::uint64_t(1) << 20;
  static constexpr std::int64_t kMaxCellsPerBox = 4096, kMaxCellsPerFace = 64;

  /// The grid's bounds and cell size, and whether vertices are flagged.
  void chooseCells(double stillExtent) {
    all_ = boxes_[0];
    double extentSum = 0;
    for (const FaceBox &b : boxes_) {
      double extent = 0;
      for (int c = 0; c < 3; ++c) {
        all_.lo[c] = std::min(all_.lo[c], b.lo[c]);
        all_.hi[c] = std::max(all_.hi[c], b.hi[c]);
        extent = std::max(extent, b.hi[c] - b.lo[c]);
      }
      extentSum += extent;
    }
    double span = 0;
    for (int c = 0; c < 3; ++c) span = std::max(span, all_.hi[c] - all_.lo[c]);
    // Cell: twice the mean box extent (fewer cells to look up, a few more
    // boxes to test), at least 2^-20 of the span (indices fit in 21 bits).
    double cell = std::max(2 * extentSum / double(boxes_.size()), span / double(1 << 20));
    if (!(cell > 0) || !std::isfinite(cell)) cell = 1;
    // The vertex flags pay where a still face spans at most a few cells.
    flagVertices_ = stillExtent >= 0 && stillExtent <= 4 * cell;
    // How far from a box a vertex of a still face reaching it can lie (with
    // a margin for rounding); the grid also covers those vertices.
    reach_ = stillExtent + 1e-6 * (stillExtent + cell);
    if (flagVertices_) {
      for (int c = 0; c < 3; ++c) all_.lo[c] -= reach_, all_.hi[c] += reach_;
      span += 2 * reach_;
      cell = std::max(cell, span / double(1 << 20));
    }
    inv_ = 1.0 / cell;
    for (int c = 0; c < 3; ++c) {
      top_[c] = std::min((all_.hi[c] - all_.lo[c]) * inv_, double(1 << 20));
      last_[c] = std::int32_t(top_[c]);
    }
  }

  /// Boxes in too many cells go to `oversized_` (tested by every face);
  /// returns how many (cell, box) entries the others make.
  std::size_t setAsideOversized() {
    isOversized_.assign(boxes_.size(), 0);
    std::size_t cellCount = 0;
    for (std::size_t q = 0; q < boxes_.size(); ++q) {
      std::int32_t lo[3], hi[3];
      const std::int64_t cells = cellRange(boxes_[q], 0, lo, hi);
      if (cells > kMaxCellsPerBox) {
        oversized_.push_back(std::uint32_t(q));
        isOversized_[q] = 1;
        continue;
      }
      cellCount += std::size_t(cells);
    }
    return cellCount;
  }

  /// Bucket sizes (entries are bucketed by the cell's hash), and the
  /// occupancy bitmaps: of the cells the boxes cover, and of the blocks
  /// within reach of a box.
  void countEntriesAndMarkCells(std::size_t cellCount) {
    std::size_t bucketCount = 16;
    bucketBits_ = 4;
    while (bucketCount < cellCount) bucketCount *= 2, ++bucketBits_;
    bucketStart_.assign(bucketCount + 1, 0);
    occupied_.assign(kBits / 64, 0);
    nearBlock_.assign(kBits / 64, 0);
    for (std::size_t q = 0; q < boxes_.size(); ++q) {
      if (isOversized_[q]) continue;
      std::int32_t lo[3], hi[3], blockLo[3], blockHi[3];
      cellRange(boxes_[q], 0, lo, hi);
      forEachCell(lo, hi, [&](std::uint64_t k) {
        ++bucketStart_[bucketOf(k) + 1];
        set(occupied_, bit(k));
      });
      if (!flagVertices_) continue;
      cellRange(boxes_[q], reach_, lo, hi);
      for (int c = 0; c < 3; ++c)
        blockLo[c] = lo[c] >> kBlockShift, blockHi[c] = hi[c] >> kBlockShift;
      forEachCell(blockLo, blockHi, [&](std::uint64_t k) { set(nearBlock_, bit(k)); });
    }
    for (std::size_t b = 0; b < bucketCount; ++b) bucketStart_[b + 1] += bucketStart_[b];
  }

  /// Entries (cell key, slot) by a counting sort: slots in increasing order
  /// within each bucket.
  void fillEntries(std::size_t cellCount) {
    entries_.resize(cellCount);
    std::vector<std::uint32_t> fill(bucketStart_.begin(), bucketStart_.end() - 1);
    for (std::size_t q = 0; q < boxes_.size(); ++q) {
      if (isOversized_[q]) continue;
      std::int32_t lo[3], hi[3];
      cellRange(boxes_[q], 0, lo, hi);
      forEachCell(lo, hi, [&](std::uint64_t k) {
        entries_[fill[bucketOf(k)]++] = {k, std::uint32_t(q)};
      });
    }
  }

  /// kMoving / kNear per vertex (every vertex kNear without the flags): a
  /// face of still vertices that are not all near a box cannot reach one.
  template <class MeshType>
  std::vector<char> flagVertices(const MeshType &m, const std::vector<char> &moving) const {
    const std::int64_t vertexCount = std::int64_t(m.vert.size());
    std::vector<char> flag(m.vert.size(), kNear);
    if (!flagVertices_) return flag;
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
        inside &= k >= 0 && k <= last_[c];
        block[c] = k >> kBlockShift;
      }
      flag[v] = inside && isSet(nearBlock_, bit(key(block[0], block[1], block[2]))) ? kNear : 0;
    }
    return flag;
  }

  /// Calls found(q) for every box q that `gb`, the box of face gi, overlaps
  /// (once per face: `stamp` remembers the last face that tested q).
  template <class Found>
  void visitBoxesOf(std::int64_t gi, const FaceBox &gb, std::vector<std::uint32_t> &stamp,
                    Found &&found) const {
    const auto test = [&](std::uint32_t q) {
      if (stamp[q] == gi) return;
      stamp[q] = std::uint32_t(gi);
      if (gb.overlaps(boxes_[q])) found(q);
    };
    for (const std::uint32_t q : oversized_) test(q);
    std::int32_t lo[3], hi[3];
    const std::int64_t cells = cellRange(gb, 0, lo, hi);
    bool outside = false;
    for (int c = 0; c < 3; ++c) outside |= lo[c] > hi[c];
    if (outside) return;
    if (cells > kMaxCellsPerFace) {
      for (std::size_t q = 0; q < boxes_.size(); ++q) test(std::uint32_t(q));
      return;
    }
    forEachCell(lo, hi, [&](std::uint64_t k) {
      if (!isSet(occupied_, bit(k))) return;
      const std::size_t b = bucketOf(k);
      for (std::uint32_t e = bucketStart_[b]; e < bucketStart_[b + 1]; ++e)
        if (entries_[e].first == k) test(entries_[e].second);
    });
  }

  /// Cell index along axis c; -1 / last + 1 outside the bounds (and for NaN:
  /// -1). (Outside means beyond `top_`, not beyond `last_`: a point in the
  /// last, partial cell is inside.)
  std::int32_t cellOf(double x, int c) const {
    const double t = (x - all_.lo[c]) * inv_;
    if (!(t >= 0)) return -1;
    return t > top_[c] ? last_[c] + 1 : std::min(std::int32_t(t), last_[c]);
  }
  /// Cells of the box [lo - grow, hi + grow], clamped to the grid; returns
  /// their number.
  std::int64_t cellRange(const FaceBox &b, double grow, std::int32_t *lo, std::int32_t *hi) const {
    std::int64_t cells = 1;
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::max(cellOf(b.lo[c] - grow, c), 0);
      hi[c] = std::min(cellOf(b.hi[c] + grow, c), last_[c]);
      cells *= std::int64_t(hi[c]) - lo[c] + 1;
    }
    return cells;
  }
  template <class F>
  static void forEachCell(const std::int32_t *lo, const std::int32_t *hi, F &&f) {
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) f(key(x, y, z));
  }
  static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) {
    return std::uint64_t(x) | std::uint64_t(y) << 21 | std::uint64_t(z) << 42;
  }
  static std::uint64_t hash(std::uint64_t k) {
    return k * 0x9E3779B97F4A7C15ull;
  }
  std::size_t bucketOf(std::uint64_t k) const {
    return std::size_t(hash(k) >> (64 - bucketBits_));
  }
  // Occupancy bitmaps, hashed: a collision only costs a look-up.
  static std::uint64_t bit(std::uint64_t k) {
    return hash(k) >> 44;
  }
  static bool isSet(const std::vector<std::uint64_t> &bits, std::uint64_t b) {
    return (bits[b >> 6] >> (b & 63) & 1) != 0;
  }
  static void set(std::vector<std::uint64_t> &bits, std::uint64_t b) {
    bits[b >> 6] |= std::uint64_t(1) << (b & 63);
  }

  const std::vector<FaceBox> &boxes_;
  FaceBox all_;           // bounds of the grid
  double inv_ = 1;        // 1 / cell size
  double top_[3];         // extent of `all_` in cells
  std::int32_t last_[3];  // largest cell index inside `all_`
  bool flagVertices_ = false;
  double reach_ = 0;
  std::vector<std::uint64_t> occupied_, nearBlock_;
  std::vector<std::uint32_t> oversized_;
  std::vector<char> isOversized_;
  int bucketBits_ = 4;
  std::vector<std::uint32_t> bucketStart_;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> entries_;
};

/// Calls visit(thread, slot, gi) for every face gi of the mesh whose box
/// overlaps boxes[slot] (once per pair); see BoxHashGrid.
template <class MeshType, class VertexBox, class Visit>
void forEachBoxOverlap(const MeshType &m, const std::vector<FaceBox> &boxes, VertexBox &&vertexBox,
                       const std::vector<char> &moving, double stillExtent, Visit &&visit) {
  if (boxes.empty()) return;
  BoxHashGrid(boxes, stillExtent).forEachOverlap(m, vertexBox, moving, visit);
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
}  // namespace edge_sharpener
