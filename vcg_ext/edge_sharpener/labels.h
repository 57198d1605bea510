// Labels written by the stages of Edge-Sharpener. Algorithm state lives in
// these enums (in scoped vcglib attributes), never in colours: colouring is a
// separate, final, optional step (colorize.h).
#pragma once

#include <cstdint>

namespace edge_sharpener {

/// Per face-edge label (kept equal on both sides of a shared edge).
enum class EdgeLabel : std::uint8_t {
  Gray,     ///< none of the below
  Smooth,   ///< "brown": dihedral normal angle below the threshold
  Red,      ///< bounds or lies inside a smooth region (filter 4)
  Chamfer,  ///< "blue": non-red edge joining two red vertices (filter 5)
};

/// Per face label.
enum class FaceLabel : std::uint8_t {
  Gray,     ///< neither smooth-region, chamfer nor corner
  Red,      ///< part of a smooth region (filters 2 and 3)
  Chamfer,  ///< has one or two chamfer edges (split into 2 or 3 faces)
  Corner,   ///< "green": three chamfer edges (filter 6, split into a fan of 6)
};

/// Per vertex label.
enum class VertexLabel : std::uint8_t {
  Gray,
  Red,  ///< interior (filter 1) or boundary (filter 4) vertex of a smooth region
};

/// Where an inserted vertex ended up, and why (the fallback reasons are the
/// paper's degenerate cases, each counted in the report).
enum class Placement : std::uint8_t {
  Original,            ///< not an inserted vertex: never moved
  Moved,               ///< moved onto the plane intersection
  ParallelPlanes,      ///< chamfer edge: the two planes are (nearly) parallel
  CoplanarNormals,     ///< corner: the three plane normals are (nearly) coplanar
  NoSupportPlane,      ///< an endpoint's red-triangle normal sum vanishes
  EdgeTooLong,         ///< moving would create an edge longer than the input's longest
  MixedConvexity,      ///< chamfer bordered by a concave and a convex side
  DegenerateRevert,    ///< moved back by the degenerate-triangle cleanup
  FarFromChamfer,      ///< extended method: the planes meet farther off than their angle
                       ///< allows, or than maxDisplacementSpacings sample spacings
  CurvedSupport,       ///< extended method: the regions curve like a blend, not a sharp edge
  IntersectionRevert,  ///< moved back: a face of it intersected another face
  WeakEvidence,        ///< auto method: moved back with its whole feature, too many of whose
                       ///< vertices the other tests refused (feature_evidence.h)
};
constexpr int kPlacementCount = 12;

const char *toString(Placement p);

inline const char *toString(Placement p) {
  switch (p) {
    case Placement::Original: return "original";
    case Placement::Moved: return "moved";
    case Placement::ParallelPlanes: return "parallel_planes";
    case Placement::CoplanarNormals: return "coplanar_normals";
    case Placement::NoSupportPlane: return "no_support_plane";
    case Placement::EdgeTooLong: return "edge_too_long";
    case Placement::MixedConvexity: return "mixed_convexity";
    case Placement::DegenerateRevert: return "degenerate_revert";
    case Placement::FarFromChamfer: return "far_from_chamfer";
    case Placement::CurvedSupport: return "curved_support";
    case Placement::IntersectionRevert: return "intersection_revert";
    case Placement::WeakEvidence: return "weak_evidence";
  }
  return "unknown";
}

/// The auto method's judgement of one feature (a chamfer strip between two
/// regions, or a cluster of corner vertices): restored, or left as it came
/// and why (auto_rules.h names the rule behind each; feature_evidence.h:
/// judgeFeature).
enum class Verdict : std::uint8_t {
  Restored,           ///< sharpened
  MeshEvidenceWeak,   ///< the whole mesh was left: too many moves refused, or already sharp
  OnTheSurface,       ///< its samples lie on the surface there: a designed bevel or fillet
  TooShort,           ///< fewer new vertices than a feature has
  ShallowAngle,       ///< its flanks meet at a shallow crease or a knife edge
  LineAcrossChamfer,  ///< its flanks' planes meet on a line across the chamfer, not along it
  OffItsPlanes,       ///< a sample beside it lies far off the plane of its flank
  MostlyRefused,      ///< placement's tests refused most of its new vertices
  CornerOfWeakEdge,   ///< a corner one of whose edges was left
  AlreadySharp,       ///< its moves slide along the input: sharp there already
  AtNonManifoldSpot,  ///< it reaches a face held at a non-manifold spot
  OutsideSelection,   ///< all its new vertices lie on faces outside the user's selection
};
constexpr int kVerdictCount = 12;

/// Whether a feature of this verdict is left as it came.
inline bool isLeft(Verdict v) {
  return v != Verdict::Restored;
}

/// snake_case name (JSON keys, Python).
inline const char *toString(Verdict v) {
  switch (v) {
    case Verdict::Restored: return "restored";
    case Verdict::MeshEvidenceWeak: return "mesh_evidence_weak";
    case Verdict::OnTheSurface: return "on_the_surface";
    case Verdict::TooShort: return "too_short";
    case Verdict::ShallowAngle: return "shallow_angle";
    case Verdict::LineAcrossChamfer: return "line_across_chamfer";
    case Verdict::OffItsPlanes: return "off_its_planes";
    case Verdict::MostlyRefused: return "mostly_refused";
    case Verdict::CornerOfWeakEdge: return "corner_of_weak_edge";
    case Verdict::AlreadySharp: return "already_sharp";
    case Verdict::AtNonManifoldSpot: return "at_non_manifold_spot";
    case Verdict::OutsideSelection: return "outside_selection";
  }
  return "unknown";
}

/// A few words for people (CLI, MeshLab log).
inline const char *describe(Verdict v) {
  switch (v) {
    case Verdict::Restored: return "restored";
    case Verdict::MeshEvidenceWeak: return "weak evidence over the whole mesh";
    case Verdict::OnTheSurface: return "on the surface (designed bevel or fillet)";
    case Verdict::TooShort: return "too short";
    case Verdict::ShallowAngle: return "shallow angle";
    case Verdict::LineAcrossChamfer: return "planes meet across it";
    case Verdict::OffItsPlanes: return "off its planes";
    case Verdict::MostlyRefused: return "mostly refused";
    case Verdict::CornerOfWeakEdge: return "at a corner of a weak edge";
    case Verdict::AlreadySharp: return "already sharp";
    case Verdict::AtNonManifoldSpot: return "at a non-manifold spot";
    case Verdict::OutsideSelection: return "outside the selection";
  }
  return "unknown";
}

}  // namespace edge_sharpener
