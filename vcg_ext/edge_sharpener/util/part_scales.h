// Parts sampled at different scales: every rule of the methods is measured in
// sample spacings (the median edge length), one number for the mesh. When the
// connected parts of a mesh are sampled at spacings that differ by more than
// kPartSpacingRatio, each such part is brought to the spacing of the largest
// for the run (scaled about its box and laid beside the other parts, so that
// no two overlap) and put back after: each part is then judged at its own spacing. The
// vertices the run did not move get their input coordinates back bit for bit.
#pragma once

#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "disjoint_sets.h"

namespace edge_sharpener {

/// Parts whose median edge lengths differ by more than this factor are each
/// sharpened at their own spacing (an input-handling constant, not a rule:
/// within it one spacing serves all).
constexpr double kPartSpacingRatio = 2.0;

/// A part with fewer faces than this keeps the spacing of the mesh (its own
/// median edge is no measure).
constexpr std::size_t kMinPartFaces = 50;

template <class MeshType>
class PartScales {
 public:
  using Coord = typename MeshType::CoordType;

  /// Measures the parts of `m` and, where their spacings differ, rescales
  /// them in place. \pre m compact.
  explicit PartScales(MeshType &m) : m_(m), inputVertices_(m.vert.size()) {
    const std::size_t nv = m.vert.size();
    part_.assign(nv, 0);
    detail::DisjointSets vertices(nv);
    for (const auto &f : m.face)
      for (int i = 1; i < 3; ++i)
        vertices.join(std::uint32_t(vcg::tri::Index(m, f.cV(i))),
                      std::uint32_t(vcg::tri::Index(m, f.cV(0))));
    std::vector<std::size_t> partOfRoot(nv, kNone);
    for (std::size_t v = 0; v < nv; ++v) {
      std::size_t &p = partOfRoot[vertices.find(std::uint32_t(v))];
      if (p == kNone) p = parts_++;
      part_[v] = p;
    }
    if (parts_ < 2) return;
    std::vector<std::vector<double>> edges(parts_);
    std::vector<std::size_t> faces(parts_, 0);
    for (const auto &f : m.face) {
      const std::size_t p = part_[vcg::tri::Index(m, f.cV(0))];
      ++faces[p];
      for (int i = 0; i < 3; ++i) edges[p].push_back(vcg::Distance(f.cP(i), f.cP((i + 1) % 3)));
    }
    std::vector<double> spacing(parts_, 0);
    std::size_t largest = 0;
    for (std::size_t p = 0; p < parts_; ++p) {
      if (faces[p] > faces[largest]) largest = p;
      if (edges[p].empty()) continue;
      std::nth_element(edges[p].begin(), edges[p].begin() + edges[p].size() / 2, edges[p].end());
      spacing[p] = edges[p][edges[p].size() / 2];
    }
    scale_.assign(parts_, 1.0);
    for (std::size_t p = 0; p < parts_; ++p) {
      if (faces[p] < kMinPartFaces || !(spacing[p] > 0) || !(spacing[largest] > 0)) continue;
      const double ratio = spacing[largest] / spacing[p];
      if (ratio > kPartSpacingRatio || ratio < 1 / kPartSpacingRatio) {
        scale_[p] = ratio;
        ++rescaled_;
      }
    }
    if (rescaled_ == 0) {
      scale_.clear();
      return;
    }
    place();
  }

  /// How many parts the mesh has, and how many of them were brought to the
  /// largest part's spacing for the run (0: one spacing served).
  std::size_t parts() const { return parts_; }
  std::size_t rescaled() const { return rescaled_; }

  /// After the run: every part back at its place and size; a vertex the run
  /// did not move gets its input coordinates exactly. \pre the run kept the
  /// input vertices' indices and appended the new ones.
  void restore() {
    if (scale_.empty()) return;
    const std::size_t nv = m_.vert.size();
    std::vector<std::size_t> part(nv, kNone);
    for (std::size_t v = 0; v < inputVertices_; ++v) part[v] = part_[v];
    // A new vertex belongs to the part of a face it shares with an input
    // vertex, or with a new vertex placed so already.
    for (bool changed = true; changed;) {
      changed = false;
      for (const auto &f : m_.face) {
        if (f.IsD()) continue;
        std::size_t p = kNone;
        for (int i = 0; i < 3 && p == kNone; ++i) p = part[vcg::tri::Index(m_, f.cV(i))];
        if (p == kNone) continue;
        for (int i = 0; i < 3; ++i) {
          std::size_t &q = part[vcg::tri::Index(m_, f.cV(i))];
          if (q == kNone) {
            q = p;
            changed = true;
          }
        }
      }
    }
    for (std::size_t v = 0; v < nv; ++v) {
      auto &vert = m_.vert[v];
      if (vert.IsD() || part[v] == kNone) continue;
      if (v < inputVertices_ && vert.cP() == placed_[v]) {
        vert.P() = input_[v];
        continue;
      }
      const std::size_t p = part[v];
      const vcg::Point3d q = vcg::Point3d::Construct(vert.cP());
      vert.P() = Coord::Construct((q - offset_[p]) / scale_[p] + origin_[p]);
    }
  }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

  /// Scales each rescaled part about its box's minimum corner and lays them
  /// in a row along x beside the box of the parts that keep their scale, on
  /// the side where the row's coordinates are the smaller, the parts apart by
  /// a tenth of the largest size: float coordinates round in proportion to
  /// their size, and a part brought down in scale far from the origin would
  /// round at a larger fraction of its spacing than in its own run.
  void place() {
    origin_.assign(parts_, vcg::Point3d(0, 0, 0));
    offset_.assign(parts_, vcg::Point3d(0, 0, 0));
    std::vector<vcg::Box3d> box(parts_);
    vcg::Box3d kept;
    for (std::size_t v = 0; v < inputVertices_; ++v) {
      const vcg::Point3d q = vcg::Point3d::Construct(m_.vert[v].cP());
      box[part_[v]].Add(q);
      if (scale_[part_[v]] == 1) kept.Add(q);
    }
    double gap = kept.Diag();
    for (std::size_t p = 0; p < parts_; ++p)
      if (scale_[p] != 1) gap = std::max(gap, box[p].Diag() * scale_[p]);
    gap *= 0.1;
    double row = -gap;  // the row's length along x
    for (std::size_t p = 0; p < parts_; ++p)
      if (scale_[p] != 1) row += box[p].DimX() * scale_[p] + gap;
    const double after = kept.max.X() + gap, before = kept.min.X() - gap - row;
    const double largestAfter = std::max(std::abs(after), std::abs(after + row));
    const double largestBefore = std::max(std::abs(before), std::abs(before + row));
    double x = largestBefore < largestAfter ? before : after;
    for (std::size_t p = 0; p < parts_; ++p) {
      if (scale_[p] == 1) continue;
      origin_[p] = box[p].min;
      offset_[p] = vcg::Point3d(x, kept.min.Y(), kept.min.Z());
      x += box[p].DimX() * scale_[p] + gap;
    }
    input_.resize(inputVertices_);
    placed_.resize(inputVertices_);
    for (std::size_t v = 0; v < inputVertices_; ++v) {
      input_[v] = m_.vert[v].cP();
      const std::size_t p = part_[v];
      const vcg::Point3d q = vcg::Point3d::Construct(input_[v]);
      m_.vert[v].P() = Coord::Construct((q - origin_[p]) * scale_[p] + offset_[p]);
      placed_[v] = m_.vert[v].cP();
    }
  }

  MeshType &m_;
  std::size_t inputVertices_ = 0;
  std::size_t parts_ = 0, rescaled_ = 0;
  std::vector<std::size_t> part_;  ///< per input vertex
  std::vector<double> scale_;      ///< per part; empty: nothing rescaled
  std::vector<vcg::Point3d> origin_, offset_;
  std::vector<Coord> input_, placed_;
};

}  // namespace edge_sharpener
