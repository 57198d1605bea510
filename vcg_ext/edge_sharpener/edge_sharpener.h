// Edge-Sharpener: public entry points.
//
// M. Attene, B. Falcidieno, J. Rossignac, M. Spagnuolo, "Edge-Sharpener:
// Recovering sharp features in triangulations of non-adaptively re-meshed
// surfaces", Eurographics Symposium on Geometry Processing, 2003.
//
// Data flow (one small function per stage, each reading and writing labels):
//   smooth-edge test -> six filters -> split plan -> subdivision
//   -> vertex placement -> degenerate cleanup -> (optional) colouring
#pragma once

#include <stdexcept>
#include <string>

#include "options.h"
#include "report.h"

namespace edge_sharpener {

/// Thrown by sharpen()/detectChamfers() when the input cannot be processed.
/// The mesh is left exactly as it was.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Returns an empty string when `m` can be processed, otherwise a one-line
/// reason (no faces, NaN/Inf coordinates, a face repeating a vertex,
/// inconsistent orientation). Non-manifold vertices and edges are processed:
/// their faces are left as they came (util/non_manifold.h); `nonManifold`,
/// when not null, tells whether there are any.
/// \pre m has face-face adjacency enabled; vectors compact (no deleted elements).
/// Recomputes m's FF topology.
template <class MeshType>
std::string findInputProblem(MeshType &m, bool *nonManifold);
template <class MeshType>
std::string findInputProblem(MeshType &m);

/// Detects chamfers and corners and sharpens them in place.
/// \pre m has FF adjacency (tri::RequireFFAdjacency) and is compact;
///      with opt.colorize also per-face and per-vertex colour.
/// \return counts of every stage. Original vertices keep their index and
///         bit-identical position; inserted vertices are appended after them.
///         Where m has the per-vertex attribute kRestoredVertexAttribute
///         (restored_edges.h), it marks the vertices placed on sharp edges.
/// \throws InputError (mesh untouched) when findInputProblem() reports a problem.
/// Faces at non-manifold vertices and edges, and the features that reach
/// them, are left as they came; the output keeps those vertices and edges
/// (report.nonManifold says how many and where). With opt.selectedFacesOnly
/// only the features within the selected faces are sharpened (options.h);
/// no face selected: the mesh is left as it came.
template <class MeshType>
SharpenReport sharpen(MeshType &m, const SharpenOptions &opt = {});

/// Runs the smooth-edge test and the six filters only: no geometry change.
/// Paints the paper's palette (when the mesh has colours) and sets the
/// selection flag of chamfer and corner faces.
/// \pre as sharpen(). \throws InputError as sharpen().
template <class MeshType>
SharpenReport detectChamfers(MeshType &m, const SharpenOptions &opt = {});

}  // namespace edge_sharpener

#include "detail/sharpen_impl.h"
