// Stage 6b: no new self-intersections. Placing inserted vertices on plane
// intersections (and, in the extended method, projecting zone vertices onto
// their region's plane) can push a triangle through another one where two
// features come close (a thin wall, a concave corner, a coarse sphere). This
// stage finds every face incident to a moved vertex that intersects another
// face of the mesh (vcglib's face-face test, the one tri::Clean::
// SelfIntersections uses) and sends the responsible vertex back towards its
// rest position on the input surface, repeating on the faces it changed
// until no such intersection is left.
//
// Cost: one pass over all faces against a hashed grid of the boxes the
// faces of moved vertices sweep on their way back to rest (box_hash_grid.h),
// so near-linear in the mesh size; the rounds then test only the face pairs
// this pass found (the first round: all of them; later rounds: those of the
// faces of vertices that retreated), by the tests of face_contact.h.
#pragma once

#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "../options.h"
#include "../report.h"
#include "../subdivision.h"
#include "../util/mesh_labels.h"
#include "../util/parallel.h"
#include "box_hash_grid.h"
#include "face_contact.h"
#include "vertex_moves.h"

namespace edge_sharpener {

namespace detail {

/// The intersection guard of revertSelfIntersections(), step by step:
/// collect the moved vertices and their faces, find the faces near each
/// (once, for all rounds), then in rounds find the new contacts among the
/// faces that changed and let one vertex of each retreat.
template <class MeshType>
class IntersectionGuard {
 public:
  IntersectionGuard(MeshType &m, VertexMoves<MeshType> &moves, double degenerateAngleRad,
                    double longestInputEdge, const std::vector<char> *retreatFirst = nullptr,
                    const std::vector<char> *onlyThese = nullptr)
      : m_(m),
        moves_(moves),
        n0_(moves.firstInserted()),
        degenerateAngleRad_(degenerateAngleRad),
        stillExtent_(longestInputEdge),
        retreatFirst_(retreatFirst),
        onlyThese_(onlyThese) {}

  IntersectionStats run() {
    if (collectMovedVertices() == 0) return stats_;
    collectQueryFaces();
    collectIncidentFaces();
    findNearFaces();
    recordPlacedPositions();
    constexpr int kMaxRounds = 1000;
    for (int round = 0; round < kMaxRounds && !query_.empty(); ++round) {
      const std::vector<FacePair> pairs = findContacts(query_);
      if (round == 0) stats_.intersectingPairs = pairs.size();
      if (pairs.empty()) break;
      ++stats_.rounds;
      retreatRound(pairs);
      query_ = facesOfChangedVertices();
    }
    std::sort(atRest_.begin(), atRest_.end());
    stats_.remaining = std::size_t(std::unique(atRest_.begin(), atRest_.end()) - atRest_.begin());
    return stats_;
  }

 private:
  using Coord = typename MeshType::CoordType;
  using FacePair = std::pair<std::uint32_t, std::uint32_t>;
  using PairLists = std::vector<PerThread<std::vector<FacePair>>>;
  /// How two faces meet: not at all, in a contact sharpening made, or in one
  /// that is there at rest too (in the input: moving back would not resolve
  /// it).
  enum class Contact { None, New, AtRest };
  /// How far along its displacement a retreating vertex still is, in steps
  /// of 1/kFull (kFull: as placed, 0: at rest).
  static constexpr int kFull = 16;
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

  // --- Collect -------------------------------------------------------------

  /// Flags the vertices away from rest; returns how many.
  std::size_t collectMovedVertices() {
    away_.assign(m_.vert.size(), 0);
    std::size_t count = 0;
    for (std::size_t v = 0; v < m_.vert.size(); ++v) {
      if (m_.vert[v].IsD()) continue;
      away_[v] = onlyThese_ ? (*onlyThese_)[v] && !moves_.isAtRest(v) : moves_.isMoved(v);
      count += away_[v];
    }
    return count;
  }

  /// The faces of the moved vertices (in face order), and a bound on the
  /// extent along an axis of the other faces (for the broad phase): the
  /// input's faces are no wider than its longest edge, and only the faces
  /// the split made (whose vertices cleanup may have merged across two input
  /// faces) are measured.
  void collectQueryFaces() {
    const std::int64_t nf = std::int64_t(m_.face.size());
    const int threads = nf >= kParallelMin ? maxThreads() : 1;
    std::vector<PerThread<std::vector<std::uint32_t>>> parts(threads);
    double stillExtent = stillExtent_;
#pragma omp parallel num_threads(threads) reduction(max : stillExtent)
    {
      std::vector<std::uint32_t> &part = parts[threadNumber()].value;
#pragma omp for schedule(static, 8192)
      for (std::int64_t fi = 0; fi < nf; ++fi) {
        const auto &f = m_.face[fi];
        if (f.IsD()) continue;
        bool any = false;
        for (int k = 0; k < 3; ++k) any |= away_[vcg::tri::Index(m_, f.cV(k))] != 0;
        if (any) {
          part.push_back(std::uint32_t(fi));
          continue;
        }
        const FaceLabel label = moves_.labels().face[fi];
        if (label != FaceLabel::Chamfer && label != FaceLabel::Corner) continue;  // an input face
        const Vec3 p0 = positionOf(f.cV(0)), p1 = positionOf(f.cV(1)), p2 = positionOf(f.cV(2));
        for (int c = 0; c < 3; ++c)
          stillExtent = std::max(stillExtent,
                                 std::max({p0[c], p1[c], p2[c]}) - std::min({p0[c], p1[c], p2[c]}));
      }
    }
    for (const auto &part : parts)
      query_.insert(query_.end(), part.value.begin(), part.value.end());
    std::sort(query_.begin(), query_.end());
    stillExtent_ =
        std::isfinite(stillExtent) ? stillExtent : std::numeric_limits<double>::infinity();
  }

  /// For each moved vertex, its faces (compressed rows, in face order).
  void collectIncidentFaces() {
    offset_.assign(m_.vert.size() + 1, 0);
    for (const std::uint32_t fi : query_)
      for (int k = 0; k < 3; ++k) {
        const std::size_t v = vcg::tri::Index(m_, m_.face[fi].cV(k));
        if (away_[v]) ++offset_[v + 1];
      }
    for (std::size_t v = 0; v + 1 < offset_.size(); ++v) offset_[v + 1] += offset_[v];
    incident_.resize(offset_.back());
    std::vector<std::uint32_t> fill(offset_.begin(), offset_.end() - 1);
    for (const std::uint32_t fi : query_)
      for (int k = 0; k < 3; ++k) {
        const std::size_t v = vcg::tri::Index(m_, m_.face[fi].cV(k));
        if (away_[v]) incident_[fill[v]++] = fi;
      }
  }

  /// Moved vertices only ever go back along the segment to rest, so a face
  /// can only meet the faces its swept box (placed and rest positions of its
  /// vertices) overlaps: one pass over the mesh finds them for all rounds.
  void findNearFaces() {
    std::vector<FaceBox> boxes;
    boxes.reserve(query_.size());
    const auto sweptBox = [&](std::size_t v) {
      FaceBox b(positionOf(&m_.vert[v]));
      if (away_[v]) b.unite(FaceBox(Vec3::Construct(moves_.storedRest(v))));
      return b;
    };
    for (const std::uint32_t fi : query_) {
      FaceBox b = sweptBox(vcg::tri::Index(m_, m_.face[fi].cV(0)));
      for (int k = 1; k < 3; ++k) b.unite(sweptBox(vcg::tri::Index(m_, m_.face[fi].cV(k))));
      boxes.push_back(b);
    }
    PairLists hits(maxThreads());
    forEachBoxOverlap(m_, boxes, sweptBox, away_, stillExtent_,
                      [&](int thread, std::uint32_t q, std::uint32_t gi) {
                        if (gi != query_[q]) hits[thread].value.emplace_back(q, gi);
                      });
    near_ = NearLists::fromPairs(query_.size(), hits);
    slot_.assign(m_.face.size(), 0);
    for (std::size_t q = 0; q < query_.size(); ++q) slot_[query_[q]] = std::uint32_t(q);
  }

  /// Each moved vertex's position as placed, all the way out.
  void recordPlacedPositions() {
    placed_.resize(m_.vert.size());
    level_.assign(m_.vert.size(), 0);
    for (std::size_t v = 0; v < m_.vert.size(); ++v)
      if (away_[v]) placed_[v] = m_.vert[v].cP(), level_[v] = kFull;
    inRound_.assign(m_.face.size(), 0);
    justChanged_.assign(m_.vert.size(), 0);
    score_.assign(m_.vert.size(), 0);
  }

  // --- Find contacts -------------------------------------------------------

  /// Where a vertex was before sharpening moved it.
  Vec3 restPosition(const typename MeshType::VertexType *vp) const {
    const std::size_t v = vcg::tri::Index(m_, vp);
    const bool mayMove = onlyThese_ ? (*onlyThese_)[v] != 0 : moves_.hasRest(v);
    return mayMove ? Vec3::Construct(moves_.storedRest(v)) : positionOf(vp);
  }

  /// How faces fi and gi meet now: a contact that is there at rest too
  /// counts as new when the faces only touched at rest and now cross.
  Contact contactOf(std::uint32_t fi, std::uint32_t gi) const {
    auto *f = &m_.face[std::min(fi, gi)], *g = &m_.face[std::max(fi, gi)];
    const auto here = [](const auto *vp) { return positionOf(vp); };
    const auto atRest = [this](const auto *vp) { return restPosition(vp); };
    if (!facesIntersect<MeshType>(f, g, here)) return Contact::None;
    if (!facesIntersect<MeshType>(f, g, atRest)) return Contact::New;
    return facesCross<MeshType>(f, g, atRest) || !facesCross<MeshType>(f, g, here) ? Contact::AtRest
                                                                                   : Contact::New;
  }

  /// Pairs of faces with at least one face in `faces` (faces of moved
  /// vertices) in a new contact, smaller index first, sorted and unique.
  /// Pairs in a contact there at rest too go to `atRest_`.
  std::vector<FacePair> findContacts(const std::vector<std::uint32_t> &faces) {
    for (const std::uint32_t fi : faces) inRound_[fi] = 1;
    PairLists found(maxThreads()), foundAtRest(maxThreads());
    const std::int64_t count = std::int64_t(faces.size());
#pragma omp parallel for schedule(dynamic, 64) if (count >= 4096)
    for (std::int64_t r = 0; r < count; ++r) {
      const std::uint32_t fi = faces[r];
      const std::uint32_t q = slot_[fi];
      for (const std::uint32_t *near = near_.begin(q); near != near_.end(q); ++near) {
        const std::uint32_t gi = *near;
        if (inRound_[gi] && gi < fi) continue;  // a pair of this round's faces: tested once
        const Contact contact = contactOf(fi, gi);
        if (contact == Contact::None) continue;
        (contact == Contact::AtRest ? foundAtRest : found)[threadNumber()].value.emplace_back(
            std::min(fi, gi), std::max(fi, gi));
      }
    }
    for (const std::uint32_t fi : faces) inRound_[fi] = 0;
    for (const auto &list : foundAtRest)
      atRest_.insert(atRest_.end(), list.value.begin(), list.value.end());
    std::vector<FacePair> pairs;
    for (const auto &list : found) pairs.insert(pairs.end(), list.value.begin(), list.value.end());
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
  }

  // --- Retreat -------------------------------------------------------------

  /// Each pair not touched by a vertex moved earlier in this round retreats
  /// one of its moved vertices (chooseRetreating()); a pair without one is
  /// there at rest.
  void retreatRound(const std::vector<FacePair> &pairs) {
    const std::vector<std::uint32_t> scored = scoreVertices(pairs);
    changed_.clear();
    for (const FacePair &p : pairs) {
      if (touchesChangedVertex(p)) continue;  // look again next round
      const auto [best, bestLevel] = chooseRetreating(p);
      if (best == kNone) {
        atRest_.push_back(p);
        continue;
      }
      if (bestLevel == 0)
        sendToRest(best);
      else
        retreatTo(best, bestLevel);
    }
    for (const std::uint32_t v : scored) score_[v] = 0;
  }

  /// Calls visit(v) for each moved vertex of the pair's faces.
  template <class Visit>
  void forEachMoved(const FacePair &p, Visit &&visit) const {
    for (const std::uint32_t fi : {p.first, p.second})
      for (int k = 0; k < 3; ++k) {
        const std::size_t v = vcg::tri::Index(m_, m_.face[fi].cV(k));
        if (away_[v]) visit(v);
      }
  }

  /// Scores each moved vertex by the number of `pairs` it is in; returns
  /// the vertices scored.
  std::vector<std::uint32_t> scoreVertices(const std::vector<FacePair> &pairs) {
    std::vector<std::uint32_t> scored;
    for (const FacePair &p : pairs)
      forEachMoved(p, [&](std::size_t v) {
        if (score_[v]++ == 0) scored.push_back(std::uint32_t(v));
      });
    return scored;
  }

  bool touchesChangedVertex(const FacePair &p) const {
    bool taken = false;
    for (const std::uint32_t fi : {p.first, p.second})
      for (int k = 0; k < 3; ++k)
        taken |= justChanged_[vcg::tri::Index(m_, m_.face[fi].cV(k))] != 0;
    return taken;
  }

  /// The pair's moved vertex that can stay farthest out, and that level;
  /// ties: flagged to retreat first (firstToRetreat), in more pairs,
  /// smaller displacement, lower index. (kNone, -1) when the pair has no
  /// moved vertex left.
  std::pair<std::size_t, int> chooseRetreating(const FacePair &p) {
    std::size_t best = kNone;
    int bestLevel = -1;
    double bestDisplacement = 0;
    forEachMoved(p, [&](std::size_t v) {
      if (v == best) return;
      const int lv = feasibleLevel(v);
      const double d =
          (positionOf(&m_.vert[v]) - Vec3::Construct(moves_.storedRest(v))).SquaredNorm();
      const bool better = lv != bestLevel                             ? lv > bestLevel
                          : firstToRetreat(v) != firstToRetreat(best) ? firstToRetreat(v)
                          : score_[v] != score_[best]                 ? score_[v] > score_[best]
                          : d != bestDisplacement                     ? d < bestDisplacement
                                                                      : v < best;
      if (better) best = v, bestLevel = lv, bestDisplacement = d;
    });
    return {best, bestLevel};
  }

  /// Whether v's move rests on weaker evidence than the others' (the
  /// caller's retreatFirst: the evidence guard's keptMoves).
  bool firstToRetreat(std::size_t v) const {
    return retreatFirst_ && v < retreatFirst_->size() && (*retreatFirst_)[v];
  }

  /// The farthest level below the current one at which v's faces meet none
  /// of the faces near them (their near lists: all a face can meet on its
  /// way back to rest), fold over or get too small an angle (0: none). v
  /// stays put.
  int feasibleLevel(std::size_t v) {
    const Coord now = m_.vert[v].cP();
    std::vector<Vec3> restNormal;
    m_.vert[v].P() = moves_.storedRest(v);
    for (std::uint32_t j = offset_[v]; j < offset_[v + 1]; ++j)
      restNormal.push_back(normalOf(incident_[j]));
    int found = 0;
    for (int lv = level_[v] - 1; lv > 0 && found == 0; --lv) {
      m_.vert[v].P() = positionAt(v, lv);
      if (facesFineAt(v, restNormal)) found = lv;
    }
    m_.vert[v].P() = now;
    return found;
  }

  /// Whether v's faces, as they stand, keep their angles and orientation
  /// and make no new contact with the faces near them.
  bool facesFineAt(std::size_t v, const std::vector<Vec3> &restNormal) const {
    bool ok = true;
    for (std::uint32_t j = offset_[v]; j < offset_[v + 1] && ok; ++j) {
      const std::uint32_t fi = incident_[j];
      ok = minAngleOf(fi) >= degenerateAngleRad_ && normalOf(fi) * restNormal[j - offset_[v]] > 0;
      const std::uint32_t q = slot_[fi];
      for (const std::uint32_t *o = near_.begin(q); o != near_.end(q) && ok; ++o)
        ok = contactOf(fi, *o) != Contact::New;
    }
    return ok;
  }

  /// Moves v part of the way back, to `level` (0 < level < its current one).
  void retreatTo(std::size_t v, int level) {
    countRetreat(v);
    level_[v] = std::uint8_t(level);
    m_.vert[v].P() = positionAt(v, level);
    markChanged(v);
  }

  /// Sends v to rest; a face it leaves below the degenerate angle sends its
  /// other moved vertices to rest too (cleanup's guarantee: no such face
  /// holds a moved vertex, input slivers' children aside).
  void sendToRest(std::size_t first) {
    std::vector<std::size_t> stack{first};
    while (!stack.empty()) {
      const std::size_t v = stack.back();
      stack.pop_back();
      if (!away_[v]) continue;
      countRetreat(v);
      if (v < n0_) ++stats_.zoneReverted;
      moves_.sendBack(v, Placement::IntersectionRevert);
      away_[v] = 0;
      level_[v] = 0;
      markChanged(v);
      for (std::uint32_t j = offset_[v]; j < offset_[v + 1]; ++j) {
        if (minAngleOf(incident_[j]) >= degenerateAngleRad_) continue;
        for (int k = 0; k < 3; ++k) {
          const std::size_t u = vcg::tri::Index(m_, m_.face[incident_[j]].cV(k));
          if (away_[u]) stack.push_back(u);
        }
      }
    }
  }

  /// An inserted vertex that retreats (part way or to rest) is labelled
  /// Placement::IntersectionRevert and counted once; zone vertices are
  /// counted when back at rest (sendToRest()).
  void countRetreat(std::size_t v) {
    if (v < n0_) return;
    if (moves_.labels().placement[&m_.vert[v]] == Placement::Moved) ++stats_.reverted;
    moves_.labels().placement[&m_.vert[v]] = Placement::IntersectionRevert;
  }

  void markChanged(std::size_t v) {
    if (!justChanged_[v]) changed_.push_back(std::uint32_t(v)), justChanged_[v] = 1;
  }

  /// The next round's faces: those of the vertices moved in this one.
  std::vector<std::uint32_t> facesOfChangedVertices() {
    std::vector<std::uint32_t> faces;
    for (const std::uint32_t v : changed_) {
      faces.insert(faces.end(), incident_.begin() + offset_[v], incident_.begin() + offset_[v + 1]);
      justChanged_[v] = 0;
    }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    return faces;
  }

  // --- Geometry ------------------------------------------------------------

  /// v's position `level` steps of 1/kFull of its displacement out from rest.
  Coord positionAt(std::size_t v, int level) const {
    if (level == kFull) return placed_[v];
    const Coord rest = moves_.storedRest(v);
    const Vec3 r = Vec3::Construct(rest);
    return level == 0
               ? rest
               : Coord::Construct(r + (Vec3::Construct(placed_[v]) - r) * (level / double(kFull)));
  }
  double minAngleOf(std::uint32_t fi) const {
    const auto &f = m_.face[fi];
    return minTriangleAngle(positionOf(f.cV(0)), positionOf(f.cV(1)), positionOf(f.cV(2)));
  }
  Vec3 normalOf(std::uint32_t fi) const {
    const auto &f = m_.face[fi];
    const Vec3 a = positionOf(f.cV(0));
    return (positionOf(f.cV(1)) - a) ^ (positionOf(f.cV(2)) - a);
  }

  MeshType &m_;
  VertexMoves<MeshType> &moves_;
  const std::size_t n0_;  // first inserted vertex
  const double degenerateAngleRad_;
  double stillExtent_;  // bound on a still face's extent along an axis
  const std::vector<char> *retreatFirst_ = nullptr;
  const std::vector<char> *onlyThese_ = nullptr;  // the only vertices that may move (else: moved)
  IntersectionStats stats_;
  std::vector<char> away_;                        // still away from rest, free to retreat further
  std::vector<std::uint32_t> query_;              // faces of this round
  std::vector<std::uint32_t> offset_, incident_;  // each moved vertex's faces
  NearLists near_;                   // per query slot: the faces its swept box overlaps
  std::vector<std::uint32_t> slot_;  // query slot of each face of a moved vertex
  std::vector<Coord> placed_;
  std::vector<std::uint8_t> level_;
  std::vector<char> inRound_, justChanged_;
  std::vector<std::uint32_t> changed_;  // vertices moved this round
  std::vector<std::uint32_t> score_;    // in how many of this round's pairs
  std::vector<FacePair> atRest_;        // pairs in a contact there at rest too
};

}  // namespace detail

/// Stage 6b: moves vertices back towards rest until no face incident to a
/// moved vertex intersects another face (facesIntersect(): vcglib's test for
/// faces sharing a vertex, a contact-tolerant Moeller test otherwise). A
/// moved vertex is an inserted vertex placed by placeInsertedVertices()
/// (Placement::Moved), or an original vertex away from its rest position
/// (extended method: a projected zone vertex); VertexMoves::isMoved().
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
/// vertex, input slivers' children aside) is kept. Inserted vertices that retreat are labelled
/// Placement::IntersectionRevert; those back at rest went through
/// VertexMoves::sendBack(). Deterministic (serial, index order).
/// `longestInputEdge`: the input's longest edge (SharpenReport), which bounds
/// the faces the split did not make.
/// `retreatFirst` (by vertex index, optional): moves on weaker evidence,
/// sent back first where more than one vertex can part a pair as far out.
/// `onlyThese` (by vertex index, optional): the only vertices that may
/// retreat (those of them away from rest); every other vertex stays where it
/// stands and counts as at rest there.
/// \pre removeDegenerateTriangles() ran (deleted elements not yet compacted).
template <class MeshType>
IntersectionStats revertSelfIntersections(MeshType &m, VertexMoves<MeshType> &moves,
                                          double degenerateAngleRad, double longestInputEdge,
                                          const std::vector<char> *retreatFirst = nullptr,
                                          const std::vector<char> *onlyThese = nullptr) {
  return detail::IntersectionGuard<MeshType>(m, moves, degenerateAngleRad, longestInputEdge,
                                             retreatFirst, onlyThese)
      .run();
}

}  // namespace edge_sharpener
