// Stage 6d, auto method: a vertex the degenerate cleanup sent back to rest
// leaves a notch as deep as its move where its placement was right (its cap
// could not be cured by a collapse or a flip). After the other guards, each
// such vertex goes out again towards where it was placed, as far as its faces
// keep their orientation and angles, and the intersection guard then runs on
// these vertices alone: a face of theirs that meets another takes them back,
// never a vertex the guards kept. Their placement stays refused.
#pragma once

#include <vcg/complex/complex.h>

#include <cstdint>
#include <vector>

#include "../cleanup.h"
#include "../util/vertex_faces.h"
#include "intersection_guard.h"
#include "vertex_moves.h"

namespace edge_sharpener {

/// Stage 6d: takes each vertex of `refused` still at rest (with its label
/// Placement::DegenerateRevert) out towards where it was placed, to the
/// farthest of 15, 14, ... 1 sixteenths of the way at which no face of it
/// turns over or gets a new angle below `degenerateAngleRad`
/// (detail::moveKeepsFaces), in the order the cleanup sent them back; then
/// revertSelfIntersections() with only those vertices free to move.
/// \return how many stand away from rest afterwards.
template <class MeshType>
std::size_t takeRefusedPartWay(MeshType &m, VertexMoves<MeshType> &moves,
                               const std::vector<RefusedPlacement> &refused,
                               double degenerateAngleRad, double longestInputEdge) {
  constexpr int kSteps = 16;
  if (refused.empty()) return 0;
  std::vector<char> candidate(m.vert.size(), 0);
  for (const RefusedPlacement &r : refused) {
    const std::size_t v = r.vertex;
    candidate[v] = !m.vert[v].IsD() && moves.isAtRest(v) &&
                   moves.labels().placement[&m.vert[v]] == Placement::DegenerateRevert;
  }
  const VertexFaceTable vf(m, candidate);
  std::vector<char> out(m.vert.size(), 0);
  std::size_t moved = 0;
  for (const RefusedPlacement &r : refused) {
    const std::size_t v = r.vertex;
    if (!candidate[v] || out[v]) continue;
    const std::vector<std::uint32_t> faces(vf.begin(v), vf.end(v));
    const Vec3 rest = Vec3::Construct(moves.storedRest(v));
    for (int level = kSteps - 1; level > 0; --level) {
      const Vec3 p = rest + (r.placed - rest) * (double(level) / kSteps);
      if (!detail::moveKeepsFaces(m, faces, v, p, degenerateAngleRad)) continue;
      m.vert[v].P() = vcg::Point3<typename MeshType::ScalarType>::Construct(p);
      out[v] = 1;
      ++moved;
      break;
    }
  }
  if (moved == 0) return 0;
  revertSelfIntersections(m, moves, degenerateAngleRad, longestInputEdge, nullptr, &out);
  std::size_t away = 0;
  for (std::size_t v = 0; v < out.size(); ++v) away += out[v] && !moves.isAtRest(v);
  return away;
}

}  // namespace edge_sharpener
