// Optional final step, for inspection only: paints either each feature's
// faces by the auto method's verdict on it (verdictColor), or the labels
// with the paper's palette, to see what was detected and what happened to
// each inserted vertex. Paper's faces: smooth region red, chamfer (and its
// children) blue, corner green, others grey. Vertices: red-region vertices
// red, others grey; inserted vertices by outcome (see placementColor()).
#pragma once

#include <vcg/space/color4.h>

#include <cstdint>
#include <vector>

#include "extended/zones.h"
#include "report.h"
#include "util/mesh_labels.h"
#include "util/non_manifold.h"

namespace edge_sharpener {

inline vcg::Color4b faceLabelColor(FaceLabel label) {
  switch (label) {
    case FaceLabel::Red: return vcg::Color4b(220, 50, 40, 255);
    case FaceLabel::Chamfer: return vcg::Color4b(40, 90, 230, 255);
    case FaceLabel::Corner: return vcg::Color4b(30, 190, 60, 255);
    case FaceLabel::Gray: break;
  }
  return vcg::Color4b(160, 160, 160, 255);
}

/// Moved: yellow; kept at rest: parallel planes magenta, coplanar normals
/// cyan, no support plane black, edge too long orange, mixed convexity
/// purple, reverted by cleanup white, far from the chamfer brown, curved support teal,
/// reverted by the self-intersection guard pink, weak evidence (auto method)
/// olive.
inline vcg::Color4b placementColor(Placement p, VertexLabel label) {
  switch (p) {
    case Placement::Original:
      return label == VertexLabel::Red ? vcg::Color4b(220, 50, 40, 255)
                                       : vcg::Color4b(160, 160, 160, 255);
    case Placement::Moved: return vcg::Color4b(255, 220, 0, 255);
    case Placement::ParallelPlanes: return vcg::Color4b(230, 0, 230, 255);
    case Placement::CoplanarNormals: return vcg::Color4b(0, 220, 230, 255);
    case Placement::NoSupportPlane: return vcg::Color4b(0, 0, 0, 255);
    case Placement::EdgeTooLong: return vcg::Color4b(255, 140, 0, 255);
    case Placement::MixedConvexity: return vcg::Color4b(120, 40, 160, 255);
    case Placement::DegenerateRevert: return vcg::Color4b(255, 255, 255, 255);
    case Placement::FarFromChamfer: return vcg::Color4b(140, 80, 20, 255);
    case Placement::CurvedSupport: return vcg::Color4b(0, 120, 120, 255);
    case Placement::IntersectionRevert: return vcg::Color4b(255, 150, 200, 255);
    case Placement::WeakEvidence: return vcg::Color4b(128, 128, 0, 255);
  }
  return vcg::Color4b(160, 160, 160, 255);
}

/// The verdict scheme (ColorScheme::Verdict): a feature's faces in the
/// colour of the auto method's verdict on it. Restored green, left already
/// sharp blue, outside the user's selection white; each reason for leaving
/// a feature weak its own warm or muted colour.
inline vcg::Color4b verdictColor(Verdict v) {
  switch (v) {
    case Verdict::Restored: return vcg::Color4b(40, 170, 70, 255);
    case Verdict::MeshEvidenceWeak: return vcg::Color4b(150, 110, 60, 255);
    case Verdict::OnTheSurface: return vcg::Color4b(235, 150, 30, 255);
    case Verdict::TooShort: return vcg::Color4b(245, 215, 60, 255);
    case Verdict::ShallowAngle: return vcg::Color4b(120, 200, 235, 255);
    case Verdict::LineAcrossChamfer: return vcg::Color4b(150, 90, 200, 255);
    case Verdict::OffItsPlanes: return vcg::Color4b(220, 55, 45, 255);
    case Verdict::MostlyRefused: return vcg::Color4b(230, 95, 170, 255);
    case Verdict::CornerOfWeakEdge: return vcg::Color4b(245, 180, 140, 255);
    case Verdict::AlreadySharp: return vcg::Color4b(40, 90, 220, 255);
    case Verdict::AtNonManifoldSpot: return vcg::Color4b(50, 50, 50, 255);
    case Verdict::OutsideSelection: return vcg::Color4b(250, 250, 250, 255);
  }
  return vcg::Color4b(160, 160, 160, 255);
}

/// The verdict scheme's colour of a face no feature judged.
inline vcg::Color4b noFeatureColor() {
  return vcg::Color4b(170, 170, 170, 255);
}

/// Paints faces by `faceVerdict` (by face index) and each vertex in the
/// colour of its faces' first verdict (verdictRank), where the mesh has
/// those colours.
template <class MeshType>
void paintVerdicts(MeshType &m, const FaceVerdicts &faceVerdict) {
  const auto color = [](std::int8_t v) {
    return v == kNoVerdict ? noFeatureColor() : verdictColor(Verdict(v));
  };
  FaceVerdicts vertexVerdict(m.vert.size(), kNoVerdict);
  for (std::size_t f = 0; f < m.face.size() && f < faceVerdict.size(); ++f) {
    auto &face = m.face[f];
    if (face.IsD()) continue;
    if (vcg::tri::HasPerFaceColor(m)) face.C() = color(faceVerdict[f]);
    for (int k = 0; k < 3; ++k) {
      std::int8_t &v = vertexVerdict[vcg::tri::Index(m, face.V(k))];
      v = firstVerdict(v, faceVerdict[f]);
    }
  }
  if (vcg::tri::HasPerVertexColor(m))
    for (std::size_t v = 0; v < m.vert.size(); ++v)
      if (!m.vert[v].IsD()) m.vert[v].C() = color(vertexVerdict[v]);
}

/// Paints face colours (if the mesh has them) and vertex colours (likewise).
template <class MeshType>
void colorize(MeshType &m, MeshLabels<MeshType> &labels) {
  if (vcg::tri::HasPerFaceColor(m))
    for (auto &f : m.face)
      if (!f.IsD()) f.C() = faceLabelColor(labels.face[&f]);
  if (vcg::tri::HasPerVertexColor(m))
    for (auto &v : m.vert)
      if (!v.IsD()) v.C() = placementColor(labels.placement[&v], labels.vertex[&v]);
}

/// Selects the chamfer and corner faces (and their children) and deselects
/// every other face, so MeshLab users can feed the detection to other filters.
template <class MeshType>
std::size_t selectChamferFaces(MeshType &m, MeshLabels<MeshType> &labels) {
  std::size_t n = 0;
  for (auto &f : m.face) {
    if (f.IsD()) continue;
    const FaceLabel l = labels.face[&f];
    if (l == FaceLabel::Chamfer || l == FaceLabel::Corner) {
      f.SetS();
      ++n;
    } else {
      f.ClearS();
    }
  }
  return n;
}

/// The zone methods' selection: every face of a feature zone (`faceRegion`
/// kZone), the faces whose vertices Sharpen may move or split (a smooth
/// region's vertices never move), but the faces held as they came; every
/// other face deselected. What Sharpen with "Affect only selected faces"
/// takes as it is. \return the number selected.
template <class MeshType>
std::size_t selectZoneFaces(MeshType &m, const std::vector<int> &faceRegion,
                            const HeldFaces &held) {
  std::size_t n = 0;
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    const bool zone = f < faceRegion.size() && faceRegion[f] == kZone && !held.holds(f);
    zone ? m.face[f].SetS() : m.face[f].ClearS();
    n += zone;
  }
  return n;
}

}  // namespace edge_sharpener
