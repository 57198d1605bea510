// One record of every vertex sharpening may move: its rest position, whether
// it is away from it, and one way back (sendBack). Placement moves the
// inserted vertices, the extended method's zone projection moves original
// vertices of the feature zone; every guard that undoes a move (degenerate
// cleanup, intersection guard, evidence guard) goes through here, and
// the outcomes are counted once, at the end (countOutcomes).
#pragma once

#include <cstddef>
#include <vector>

#include "../report.h"
#include "../subdivision.h"
#include "../util/mesh_labels.h"

namespace edge_sharpener {

template <class MeshType>
class VertexMoves {
 public:
  using Coord = typename MeshType::CoordType;

  /// After subdivide(): the inserted vertices rest where the plan put them;
  /// with `originalsMayMove` (extended method) the original vertices rest
  /// where they are now, before zone projection.
  VertexMoves(MeshType &m, const SplitPlan &plan, MeshLabels<MeshType> &labels,
              bool originalsMayMove)
      : m_(m), plan_(plan), labels_(labels) {
    if (!originalsMayMove) return;
    originalRest_.reserve(plan.originalVertexCount);
    for (std::size_t v = 0; v < plan.originalVertexCount; ++v)
      originalRest_.push_back(m.vert[v].cP());
  }

  const SplitPlan &plan() const { return plan_; }
  MeshLabels<MeshType> &labels() { return labels_; }
  const MeshLabels<MeshType> &labels() const { return labels_; }
  std::size_t firstInserted() const { return plan_.originalVertexCount; }
  bool isInserted(std::size_t v) const {
    return v >= firstInserted() && v - firstInserted() < plan_.inserted.size();
  }
  /// Whether original vertices may move (extended method).
  bool originalsMayMove() const { return !originalRest_.empty(); }
  /// Whether v has a rest position to go back to.
  bool hasRest(std::size_t v) const {
    return v < firstInserted() ? originalsMayMove() : isInserted(v);
  }

  /// Whether v is moved: an inserted vertex placed on its planes
  /// (Placement::Moved; one the intersection guard took part of the way
  /// back is not, though it is not at rest either: isAtRest), or an original
  /// vertex that zone projection moved.
  bool isMoved(std::size_t v) const {
    if (v >= firstInserted()) return labels_.placement[&m_.vert[v]] == Placement::Moved;
    return originalsMayMove() && !(m_.vert[v].cP() == originalRest_[v]);
  }

  /// Whether v is where it rests, by position: unlike !isMoved(v), false for
  /// an inserted vertex the intersection guard moved only part of the way
  /// back (Placement::IntersectionRevert). True for a vertex without a rest.
  bool isAtRest(std::size_t v) const { return !hasRest(v) || m_.vert[v].cP() == storedRest(v); }

  /// v's rest position as the mesh stores it (an inserted vertex's midpoint
  /// rounded to the mesh's scalar). \pre hasRest(v).
  Coord storedRest(std::size_t v) const {
    return v >= firstInserted() ? Coord::Construct(plan_.inserted[v - firstInserted()].rest)
                                : originalRest_[v];
  }
  /// v's rest position in full precision (an inserted vertex's exact midpoint
  /// or centroid); the current position of a vertex without one.
  Vec3 exactRest(std::size_t v) const {
    if (v >= firstInserted()) return plan_.inserted[v - firstInserted()].rest;
    return v < originalRest_.size() ? Vec3::Construct(originalRest_[v]) : positionOf(&m_.vert[v]);
  }
  /// The original vertices' rest positions (empty for the paper's method).
  const std::vector<Coord> &originalRest() const { return originalRest_; }

  /// Puts v back at rest. An inserted vertex takes `why` as its outcome; an
  /// original vertex keeps Placement::Original. \pre hasRest(v).
  void sendBack(std::size_t v, Placement why) {
    m_.vert[v].P() = storedRest(v);
    if (v >= firstInserted()) labels_.placement[&m_.vert[v]] = why;
  }

  /// The outcome of every inserted vertex still there (cleanup collapses
  /// some), and how far the farthest moved one lies from rest (0 when none
  /// moved: one at rest lies on its rounded midpoint, a hair from the exact one).
  PlacementStats countOutcomes() const {
    PlacementStats s;
    for (std::size_t k = 0; k < plan_.inserted.size(); ++k) {
      const auto &v = m_.vert[firstInserted() + k];
      if (v.IsD()) continue;
      ++s.byOutcome[int(labels_.placement[&v])];
      if (!isMoved(firstInserted() + k)) continue;
      s.maxDisplacement =
          std::max(s.maxDisplacement, (positionOf(&v) - plan_.inserted[k].rest).Norm());
      s.movedAcrossBends += labels_.bentFlank[&v] != 0;
    }
    return s;
  }

  /// The original vertices away from rest (the extended method's projected
  /// zone vertices that no guard sent back): how many, and how far the
  /// farthest lies from rest.
  struct OriginalMoves {
    std::size_t count = 0;
    double longest = 0;
  };
  OriginalMoves originalMoves() const {
    OriginalMoves out;
    for (std::size_t v = 0; v < originalRest_.size(); ++v) {
      if (m_.vert[v].IsD() || !isMoved(v)) continue;
      ++out.count;
      out.longest = std::max(out.longest,
                             (positionOf(&m_.vert[v]) - Vec3::Construct(originalRest_[v])).Norm());
    }
    return out;
  }

 private:
  MeshType &m_;
  const SplitPlan &plan_;
  MeshLabels<MeshType> &labels_;
  std::vector<Coord> originalRest_;
};

}  // namespace edge_sharpener
