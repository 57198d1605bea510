// Parameters of Edge-Sharpener (Attene, Falcidieno, Rossignac, Spagnuolo 2003):
// the few ordinary options, then each method's tuning as nested settings
// (rulebook.h), as vcglib's algorithms take their Params.
#pragma once

#include <cmath>
// clang-format off
#include <cstring>  // wrap/callback.h uses strcpy without including it: keep it first
#include <wrap/callback.h>
// clang-format on

#include "rulebook.h"

namespace edge_sharpener {

/// Which placement/detection method runs.
enum class Method {
  Paper,     ///< the 2003 filter approach, exactly as published (section 3)
  Extended,  ///< feature zones of any width between segmented smooth regions (feature_zones.h)
  Auto,      ///< the extended method, each feature kept only on strong evidence
             ///< (feature_evidence.h); the default
};

/// What SharpenOptions::colorize and detectChamfers() paint.
enum class ColorScheme {
  Verdict,  ///< each feature's faces by the auto method's verdict on it (colorize.h: verdictColor)
  Paper,    ///< the paper's labels: smooth region, chamfer, corner (colorize.h: faceLabelColor)
};

/// Options of sharpen() and detectChamfers(). Angles are in radians.
struct SharpenOptions {
  Method method = Method::Auto;

  /// An edge is smooth when the angle between its two face normals is below
  /// `smoothMultiplier` x the mesh-wide mean of that angle. Paper: 2.
  double smoothMultiplier = 2.0;

  /// Reject a placement that would create an edge longer than the longest
  /// edge of the input (paper, Figure 7). Off only for experiments.
  bool edgeLengthCheck = true;

  /// Paint face/vertex colours for inspection (needs per-face and per-vertex
  /// colour on the mesh), in the scheme `colors` names.
  bool colorize = false;
  /// The auto method paints by verdict unless the paper's labels are asked
  /// for; the paper and extended methods judge no feature and always paint
  /// the paper's labels.
  ColorScheme colors = ColorScheme::Verdict;

  /// Triangles with an angle below this are degenerate and removed after
  /// sharpening (paper: 1 degree).
  double degenerateAngleRad = 1.0 * M_PI / 180.0;

  /// Sharpen only within the faces selected on the mesh (vcglib's face
  /// selection flag, as MeshLab's "Affect only selected faces"). The auto
  /// method judges every feature on the whole mesh, as without a selection;
  /// then a new vertex on a face outside the selection stays at rest (with
  /// the vertices it was made between), and so does every vertex of such a
  /// face (a smooth region's never moves anyway), so a feature it cuts is
  /// sharpened up to its border, a feature wholly outside is left (verdict
  /// outside_selection) and so are the corners it runs into. The paper and
  /// extended methods split only selected faces and move no vertex of an
  /// unselected one. Not in the option table: the
  /// faces come with the mesh, each front end has its own way to give them
  /// (MeshLab's selection, Python's face_mask, the CLI's --only-faces).
  bool selectedFacesOnly = false;

  /// Tuning, by method (rulebook.h).
  PaperSettings paper;
  ExtendedSettings extended;  ///< the extended and auto methods
  AutoRules rules;            ///< the auto method

  /// The 2003 method exactly as published, every other option at its default.
  static SharpenOptions paperMethod() {
    SharpenOptions o;
    o.method = Method::Paper;
    return o;
  }

  /// Optional progress callback (percent, stage name); may be null.
  vcg::CallBackPos *progress = nullptr;
};

}  // namespace edge_sharpener
