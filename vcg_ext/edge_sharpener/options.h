// Parameters of Edge-Sharpener (Attene, Falcidieno, Rossignac, Spagnuolo 2003).
#pragma once

#include <cmath>
// clang-format off
#include <cstring>  // wrap/callback.h uses strcpy without including it: keep it first
#include <wrap/callback.h>
// clang-format on

namespace edge_sharpener {

/// Which placement/detection method runs.
enum class Method {
  Paper,     ///< the 2003 filter approach, exactly as published (section 3)
  Extended,  ///< feature zones of any width between segmented smooth regions (feature_zones.h)
  Auto,      ///< the extended method, each feature kept only on strong evidence
             ///< (feature_evidence.h); the default
};

/// Whether `method` detects by feature zones (extended_method.h).
inline bool usesFeatureZones(Method method) {
  return method != Method::Paper;
}

/// Options of sharpen() and detectChamfers(). Angles are in radians.
struct SharpenOptions {
  /// An edge is smooth when the angle between its two face normals is below
  /// `smoothMultiplier` x the mesh-wide mean of that angle. Paper: 2.
  double smoothMultiplier = 2.0;

  /// Reject a placement that would create an edge longer than the longest
  /// edge of the input (paper, Figure 7). Off only for experiments.
  bool edgeLengthCheck = true;

  /// Keep a new vertex unmoved when its chamfer is bordered by a concave edge
  /// on one side and a convex edge on the other (paper, section 3). The paper
  /// and extended methods; auto judges such moves by its own tests
  /// (appliesConvexityCheck).
  bool convexityCheck = true;

  /// Two planes whose normals are closer than this angle count as parallel;
  /// three normals whose triple product is below sin(this) count as coplanar.
  double parallelAngleRad = 1.0 * M_PI / 180.0;

  /// Triangles with an angle below this are degenerate and removed after
  /// sharpening (paper: 1 degree).
  double degenerateAngleRad = 1.0 * M_PI / 180.0;

  /// Paint the paper's palette into face/vertex colours (needs per-face and
  /// per-vertex colour on the mesh).
  bool colorize = false;

  Method method = Method::Auto;

  // --- Extended method only (feature_zones.h) ---

  /// A smooth region whose vertices are all fewer than this many hops from
  /// its border is a corridor (e.g. a regular chamfer band) and joins the zone.
  int minRegionDepth = 1;
  /// Return to the zone the region faces around vertices where two regions
  /// touch (feature_zones.h: openRegionContacts).
  bool openRegionContacts = true;
  /// ...except the faces of a region that opening would leave without an
  /// interior vertex and that spans at least this many sample spacings (a
  /// narrow facet of a coarse cylinder). 0: such regions open too.
  double minFacetLengthSpacings = 10.0;
  /// Place a feature's new vertices on its flanks' regions' own planes where
  /// those regions are planes away from their features and no other region
  /// is near (planar_regions.h; placement.h: detail::onRegionPlanes).
  bool regionPlanes = true;
  /// Return to the zone the region faces around internal creases (a
  /// non-smooth edge inside one region: feature_zones.h: openInternalCreases).
  bool openInternalCreases = true;
  /// ...whose face normals turn by more than this angle (radians): below
  /// it, a non-smooth edge inside a region is marching-cubes noise.
  double internalCreaseAngleRad = 20.0 * M_PI / 180.0;
  /// ...and by more than this multiple of the smooth-edge threshold (a
  /// coarse sampling of a curved surface has large angles everywhere).
  double internalCreaseThresholdFactor = 3.0;
  /// Two vertices of one region whose planes turn by more than this angle
  /// (radians) lie on different surfaces: a chamfer edge may join them. 0:
  /// one region is one surface.
  double sameRegionFeatureAngleRad = 45.0 * M_PI / 180.0;
  /// Face rings around a region's border vertex used to fit its plane.
  int supportRings = 2;
  /// A zone vertex considers the regions reaching it within this many hops
  /// of the closest one...
  int labelSlackHops = 2;
  /// ...and none farther than this: a region's plane extrapolated farther
  /// misses a curved surface (a marching-cubes sphere at multiplier 1.5: max
  /// 4.6% of the diagonal at 8 hops, 1.5% at 3), while a chamfer band of
  /// marching cubes is at most about 3 hops wide (UMR factors unchanged).
  int maxLabelHops = 3;
  /// A zone vertex moves onto its region's plane only if the move is at
  /// most this fraction of its mean edge length.
  double maxProjectionFactor = 0.75;
  /// The edge-length check allows edges up to this multiple of the input's
  /// longest edge: the tip of an acute edge (a 35-degree wedge) lies well
  /// beyond its chamfer, and the apex test below guards against far planes.
  double extendedEdgeLengthFactor = 2.0;
  /// An inserted vertex stays at rest when the planes meet farther from it
  /// than this many sample spacings (the input's median edge length): a
  /// remesher's chamfer cuts a sample or two off a sharp edge (99.9% of the
  /// benchmark's moves stay below 2), while the global edge-length check
  /// lets a CAD mesh's long slivers throw vertices far away (twirl as is:
  /// 31% of the diagonal without this bound). 0 disables.
  double maxDisplacementSpacings = 2.5;
  /// An inserted vertex stays at rest when the planes meet more than this
  /// factor above its chamfer than their angle allows
  /// (geometry.h: chamferApexHeightRatio); 0 disables the test.
  double apexHeightFactor = 1.5;
  /// An inserted vertex stays at rest when the region next to it turns, over
  /// the fitted neighbourhood, by more than this fraction of the angle
  /// between the two planes: a finely sampled blend, not a sharp edge.
  /// 0 disables the test.
  double maxSupportSpreadRatio = 0.35;
  /// An inserted vertex stays at rest when it would pass through the plane of
  /// a third region nearby whose normal lies between the two flanks' (within
  /// `intermediateSlackRad`) by more than this fraction of its displacement:
  /// the surface turns through facets or a blend, not at one sharp edge.
  /// Negative disables the test.
  double intermediatePlaneTolerance = 0.3;
  /// An inserted vertex stays at rest when a flank's region, bending across
  /// the feature as measured where its plane was fitted, would leave that
  /// plane by more than this fraction of the vertex's displacement before
  /// reaching the sharp edge (geometry.h: extrapolationBend); at a corner,
  /// also for each pair of its planes toward their own line. Negative
  /// disables the test.
  double maxBendFraction = 0.45;
  /// Auto method: a vertex the bend test would keep at rest moves instead
  /// when its move is at most this many sample spacings and nothing else
  /// refuses it; it stays moved only with a feature whose evidence is
  /// strong, and counts as refused in that evidence (its feature's and the
  /// whole mesh's). A sampler rounds a sharp edge most near its corners,
  /// where the fitted faces bend like a blend's, by about one sample
  /// spacing; a longer move across a bend extrapolates a curved flank.
  /// 0: the bend keeps every vertex at rest (the extended method always does).
  double maxBentMoveSpacings = 1.0;
  /// ...tested where the fitted faces spread by at least this angle
  /// (radians): below it, marching cubes' staircase dominates the estimate...
  double minBendSpreadRad = 5.0 * M_PI / 180.0;
  /// ...or where the fitted faces' normals follow their position this well
  /// (geometry.h: curveFitQuality, in [0, 1]): a finely sampled curve (a
  /// sphere remeshed isotropically) spreads little over the fitted rings.
  double minBendFitQuality = 0.9;
  /// How far (radians) a third region's normal may lie off the arc between
  /// the flanks' normals and still count as between them.
  double intermediateSlackRad = 10.0 * M_PI / 180.0;
  /// A region's plane is refitted without its faces turned more than this
  /// (radians) from the first fit: a region's border often holds a few
  /// faces of the chamfer. 0: no refit.
  double fitTrimAngleRad = 15.0 * M_PI / 180.0;

  // --- Auto method: the evidence guard (feature_evidence.h) ---

  /// Nothing is sharpened when the tests refused more than this fraction of
  /// the inserted vertices of the features placement moved at all
  /// (feature_evidence.h: refusedFraction).
  double maxRefusedFraction = 0.4;
  /// ...or this fraction on a smooth part made of planes: an input whose
  /// noise is at most `maxSmoothNoiseSpacings` sample spacings and whose
  /// planar share is at least `minPlanarAreaFraction` (surface_measures.h).
  /// There the refusals come from the shape (a rounded blend, a thin part),
  /// which the per-feature evidence sorts out; on a rough surface (a scan)
  /// they come from the noise, on a freeform part from curved faces.
  double maxRefusedFractionSmooth = 0.6;
  /// 0: no input counts as smooth.
  double maxSmoothNoiseSpacings = 0.018;
  double minPlanarAreaFraction = 0.3;
  /// On a rough input (noise above `maxSmoothNoiseSpacings`: a fused scan)
  /// that the evidence guard leaves whole, the vertices labelled with a
  /// region that is a plane in its core (its own and its zone's) that lie
  /// outside that plane, by at most kFlattenMaxSpacings, move onto it where
  /// that place is on the region's face (planar_regions.h:
  /// flattenPlanarRegions): a scan's fusion bulges its planes outwards for a
  /// few samples beside each edge. Beside a convex edge or corner, a vertex
  /// that bulges beyond the other face's plane too, or belongs to no planar
  /// region, moves to the nearest point behind the planes of the planar
  /// regions around it. Where that moved a share of the vertices (the
  /// planes bulge as a fused scan's do), the same again on planes grown face
  /// by face (plane_patches.h: growPlanePatches), which the segmentation may
  /// have merged across a rounded edge. Uses the planar regions' planes
  /// (`regionPlanes`: off with it).
  bool flattenRoughPlanes = true;
  /// A feature goes back to rest whole when more than this fraction of its
  /// inserted vertices were refused by the other tests or moved across to
  /// another sheet of the input (feature_evidence.h: crossesSheet): when
  /// most of it was refused. Below that, each refusal stays a vertex's own...
  double maxFeatureFallbackFraction = 0.5;
  /// ...or when one of its source vertices lies off its plane by more than
  /// this many sample spacings...
  double maxFeatureOffPlaneSpacings = 0.6;
  /// ...unless nine in ten of its source vertices lie within this many
  /// sample spacings of their planes: a feature sampled exactly (a remesher
  /// that reprojects onto the surface) whose few far samples lie where it
  /// meets another part, not on a blend along it. The new vertices those
  /// far samples source stay at rest. 0: every far sample counts.
  double onPlaneSpacings = 0.05;
  /// A mesh counts as sampled exactly on its surface when its median edge
  /// feature (weighted by its new vertices) has nine in ten of its source
  /// vertices within this many sample spacings of their planes: a remesher
  /// that casts or reprojects its vertices onto the input (Blender's voxel
  /// remesh with Preserve Volume, isotropic remeshing with reprojection).
  /// There a source vertex farther than `onPlaneSpacings` from its plane is
  /// a point of the surface, not the sampler's cut: a designed bevel or
  /// blend. A feature half of whose sources lie that far stays as it was,
  /// and the new vertices such a source serves stay at rest. 0: off.
  double exactSamplingSpacings = 0.001;
  /// ...or unless half of its source vertices lie within this many sample
  /// spacings of their planes and none farther than
  /// `maxMedianOnPlaneOffSpacings`: a sampler that rounds a few samples
  /// near the edge (a reconstruction, a voxel remesher's corner cells) but
  /// puts most on the surface, where a blend or a bevel along the feature
  /// moves most of them off it. For an edge, both bounds are multiplied by
  /// the sine of the angle its flanks' planes meet at: the line they meet
  /// on moves by their errors over that sine. As above, only the far
  /// samples' new vertices stay at rest. 0: off.
  double medianOnPlaneSpacings = 0.1;
  double maxMedianOnPlaneOffSpacings = 1.0;
  /// ...or when it has fewer than this many inserted vertices...
  int minFeatureVertices = 3;
  /// ...or, for an edge, when its flanks' planes meet at less than this
  /// angle (radians; feature_evidence.h: planeMeetingAngle): the line they
  /// meet on moves by the planes' errors over the angle's sine, at a shallow
  /// crease (whose chamfer is shallow too) as at a knife edge (a wall's two
  /// sides taken for the flanks of one edge). 0: off.
  double minFeatureAngleRad = 20.0 * M_PI / 180.0;
  /// ...or when the lines its vertices' planes meet on turn out of its
  /// chamfer by a median angle (radians) above this: a sharp edge runs along
  /// its chamfer, while planes that meet across it (the two walls beside a
  /// thin wall's cap) make no edge there. 0 disables.
  double maxFeatureLineChamferAngleRad = 45.0 * M_PI / 180.0;
  /// In a feature kept, a new edge vertex moved farther than this many sample
  /// spacings from its chamfer stays at rest when one of its source vertices
  /// lies more than `maxLongMoveOffPlaneSpacings` off its plane: a long
  /// extrapolation magnifies the misfit such a sample shows (a curved petal
  /// whose planes meet beyond the tip a reconstruction rounded). 0: off.
  double longMoveSpacings = 2.0;
  double maxLongMoveOffPlaneSpacings = 0.3;
  /// Nothing is sharpened either when the moves mostly slide along the
  /// input's surface: the median distance of their targets from the input
  /// faces around them is below this fraction of their length (a model
  /// already sharp). On a mesh sampled exactly, only the features whose own
  /// moves slide so (weakFeatures).
  double minMedianLift = 0.07;

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
