// MeshLab adapter of Edge-Sharpener. Everything a filter needs is one row of
// the table below (name, description, parameters, core entry point); the
// MeshFilterInterface methods only look rows up, so there is no switch.
#include "filter_edge_sharpener.h"

#include <edge_sharpener/edge_sharpener.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/selection.h>
#include <vcg/complex/allocate.h>

#include <cmath>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

namespace es = edge_sharpener;

namespace {

constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------
// Parameters: each MeshLab parameter is declared once, next to the
// SharpenOptions field it fills. Its name is part of the .mlx interface. A new
// option (e.g. a RichEnum "method" for SharpenOptions::method) is one more
// OptionParam here plus its address in the `params` list of the filters below.

struct OptionParam {
  void (*add)(RichParameterList &par, const es::SharpenOptions &defaults);
  void (*read)(const RichParameterList &par, es::SharpenOptions &opt);
};

const OptionParam kSmoothMultiplier{
    [](RichParameterList &par, const es::SharpenOptions &d) {
      par.addParam(RichFloat(
          "smoothMultiplier", float(d.smoothMultiplier), "Smooth-edge multiplier",
          "An edge is smooth when the angle between the normals of its two faces is below this "
          "multiple of the mean of that angle over the whole mesh (paper: 2). Smaller values "
          "find fewer smooth regions; larger values may take curved chamfers for smooth "
          "surface."));
    },
    [](const RichParameterList &par, es::SharpenOptions &o) {
      o.smoothMultiplier = par.getFloat("smoothMultiplier");
    }};

const OptionParam kEdgeLengthCheck{
    [](RichParameterList &par, const es::SharpenOptions &d) {
      par.addParam(RichBool("edgeLengthCheck", d.edgeLengthCheck, "Edge-length check",
                            "Leave an inserted vertex in the middle of its chamfer edge or corner "
                            "triangle when moving it would create an edge longer than the "
                            "longest edge of the input (paper, Figure 7). Keep it on: without "
                            "it, nearly parallel planes can send vertices far away."));
    },
    [](const RichParameterList &par, es::SharpenOptions &o) {
      o.edgeLengthCheck = par.getBool("edgeLengthCheck");
    }};

const OptionParam kColorize{
    [](RichParameterList &par, const es::SharpenOptions &d) {
      par.addParam(RichBool("colorize", d.colorize, "Colorize",
                            "Paint the labels into per-face colour (smooth regions red, chamfer "
                            "triangles blue, corner triangles green, others grey) and per-vertex "
                            "colour (inserted vertices: moved yellow, kept at the midpoint by a "
                            "fallback in another colour)."));
    },
    [](const RichParameterList &par, es::SharpenOptions &o) {
      o.colorize = par.getBool("colorize");
    }};

const OptionParam kDegenerateAngle{
    [](RichParameterList &par, const es::SharpenOptions &d) {
      par.addParam(RichFloat("degenerateAngleDeg", float(d.degenerateAngleRad * 180.0 / kPi),
                             "Degenerate angle (deg)",
                             "After sharpening, new triangles with an angle below this many "
                             "degrees are removed (paper: 1 degree)."));
    },
    [](const RichParameterList &par, es::SharpenOptions &o) {
      o.degenerateAngleRad = par.getFloat("degenerateAngleDeg") * kPi / 180.0;
    }};

const OptionParam kMethod{
    [](RichParameterList &par, const es::SharpenOptions &d) {
      par.addParam(RichEnum(
          "method", d.method == es::Method::Extended ? 1 : 0,
          QStringList() << "Paper (2003)"
                        << "Extended (feature zones)",
          "Method",
          "<b>Paper</b>: the 2003 method exactly as published (chamfers one triangle wide).<br>"
          "<b>Extended</b>: smooth regions are segmented and the feature zone between them may "
          "be of any width (marching-cubes bands and corner patches); zone vertices are moved "
          "onto their region's fitted plane, never the vertices of smooth regions."));
    },
    [](const RichParameterList &par, es::SharpenOptions &o) {
      o.method = par.getEnum("method") == 1 ? es::Method::Extended : es::Method::Paper;
    }};

const OptionParam kStrictPlaneGuard{
    [](RichParameterList &par, const es::SharpenOptions &d) {
      par.addParam(RichBool(
          "strictPlaneGuard", d.maxSourceOffPlaneSpacings > 0, "Strict plane guard (extended)",
          "Extended method only. Region faces next to the feature zone that turn away from "
          "their region's plane return to the zone, the planes are fitted around the flat "
          "faces away from the zone, and an inserted vertex stays at rest when a vertex it "
          "comes from lies more than 0.3 median edge lengths off its plane. Keeps blends and "
          "finely facetted curves rounded (fandisk at 1% cells: max error 0.52% -> 0.39%, RMS "
          "x3.4 -> x4.0), but also leaves the wide bevels of coarse remeshings and the tips of "
          "acute corners chamfered."));
    },
    [](const RichParameterList &par, es::SharpenOptions &o) {
      o.setStrictPlaneGuard(par.getBool("strictPlaneGuard"));
    }};

const OptionParam kSamplingGridGuard{
    [](RichParameterList &par, const es::SharpenOptions &d) {
      par.addParam(RichBool(
          "samplingGridGuard", d.samplingGridGuard, "Sampling-grid guard (extended)",
          "Extended method only. When the input was made by marching cubes (its vertices lie on "
          "the edges of an axis-aligned grid, which is detected), a new vertex goes back to "
          "rest (fallback <i>grid_revert</i>) when sharpening would sweep the surface over a "
          "grid node that the sampler saw on the other side: the edge is a blend or a bevel "
          "hardly larger than a cell, not a sharp edge; when a tenth of the moves between two "
          "regions go back so, the rest of them follow (a blend along its whole length). For "
          "resamplings of exact shapes (Uniform "
          "Mesh Resampling); not for reconstructions (Screened Poisson), whose grid holds a "
          "smoothed surface. Does nothing on inputs without such a grid."));
    },
    [](const RichParameterList &par, es::SharpenOptions &o) {
      o.samplingGridGuard = par.getBool("samplingGridGuard");
    }};

// ---------------------------------------------------------------------------
// Filters.

using CoreCall = es::SharpenReport (*)(CMeshO &, const es::SharpenOptions &);

struct FilterSpec {
  const char *name;
  const char *info;  ///< HTML, without the bibliography
  std::vector<const OptionParam *> params;
  CoreCall run;
  bool alwaysColorize;  ///< paints colours whatever the parameters say
  int postCondition;
};

const char *const kCitation =
    "<br><br>See:<br>"
    "<i>Marco Attene, Bianca Falcidieno, Jarek Rossignac, Michela Spagnuolo</i><br>"
    "<b>\"Edge-Sharpener: Recovering sharp features in triangulations of non-adaptively "
    "re-meshed surfaces\"</b><br>"
    "Eurographics Symposium on Geometry Processing (SGP), 2003.";

const std::vector<FilterSpec> &filterTable() {
  static const std::vector<FilterSpec> table{
      // FP_SHARPEN
      {"Edge-Sharpener: Sharpen Chamfered Edges",
       "Restores the sharp edges and corners that a feature-insensitive, uniform re-meshing "
       "(marching cubes, uniform mesh resampling, regular remeshing) has cut into chamfers.<br>"
       "An edge is <i>smooth</i> when the angle between its face normals is below the "
       "multiplier times the mean of that angle over the mesh. Six filters grow smooth regions "
       "from the vertices whose edges are all smooth and mark as <i>chamfer edges</i> the "
       "edges joining two region-boundary vertices, and as <i>corner triangles</i> those with "
       "three chamfer edges. A new vertex is inserted on each chamfer edge and inside each "
       "corner triangle (chamfer triangles are split in 2, 3 or a fan of 6) and moved onto "
       "the intersection of the planes that extrapolate the adjacent smooth regions. "
       "Original vertices never move. Triangles left with an angle below the degenerate "
       "angle are removed.<br>"
       "Needs a two-manifold triangle mesh (point clouds and non-manifold meshes are "
       "refused and left untouched). The report of every stage is written to the log.",
       {&kMethod, &kSmoothMultiplier, &kEdgeLengthCheck, &kColorize, &kDegenerateAngle,
        &kStrictPlaneGuard, &kSamplingGridGuard},
       &es::sharpen<CMeshO>,
       false,
       MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE | MeshModel::MM_VERTCOLOR |
           MeshModel::MM_FACECOLOR | MeshModel::MM_FACEFLAGSELECT},
      // FP_DETECT
      {"Edge-Sharpener: Detect Chamfers",
       "Runs the detection stages of Edge-Sharpener only (the smooth-edge test and the six "
       "filters of the paper), without changing the geometry: paints the labels into "
       "per-face colour (smooth regions red, chamfer triangles blue, corner triangles green, "
       "others grey) and selects the chamfer and corner triangles, i.e. the faces that "
       "<i>Sharpen Chamfered Edges</i> would subdivide.<br>"
       "Useful to tune the smooth-edge multiplier before sharpening.",
       {&kMethod, &kSmoothMultiplier, &kStrictPlaneGuard},
       &es::detectChamfers<CMeshO>,
       true,
       MeshModel::MM_VERTCOLOR | MeshModel::MM_FACECOLOR | MeshModel::MM_FACEFLAGSELECT},
  };
  return table;
}

const FilterSpec &spec(int id) {
  return filterTable().at(std::size_t(id));
}

es::SharpenOptions readOptions(const FilterSpec &f, const RichParameterList &par) {
  es::SharpenOptions opt;
  for (const OptionParam *p : f.params) p->read(par, opt);
  if (f.alwaysColorize) opt.colorize = true;
  return opt;
}

/// What the filter changes in MeshLab's per-mesh state (its data mask), so
/// that a refused mesh is left as it was.
struct MeshState {
  bool hadFaceFace, hadFaceColor, hadVertColor;
  explicit MeshState(const MeshModel &mm)
      : hadFaceFace(mm.hasDataMask(MeshModel::MM_FACEFACETOPO) ||
                    mm.cm.face.IsFFAdjacencyEnabled()),
        hadFaceColor(mm.hasDataMask(MeshModel::MM_FACECOLOR)),
        hadVertColor(mm.hasDataMask(MeshModel::MM_VERTCOLOR)) {}
};

/// The core's preconditions: compact vectors and the FF adjacency component.
/// Only the component is enabled here (not MeshModel::updateDataMask, which
/// would also run vcglib's UpdateTopology::FaceFace): the core's input check
/// builds the adjacency itself with its linear-time builder (fast_topology.h,
/// the same FF vcglib builds) and keeps it up to date through every change.
void prepareTopology(MeshModel &mm) {
  vcg::tri::Allocator<CMeshO>::CompactEveryVector(mm.cm);
  if (!mm.cm.face.IsFFAdjacencyEnabled()) mm.cm.face.EnableFFAdjacency();
}

/// After the core call: FF adjacency is valid (built and maintained by the
/// core). If the mesh had no FF component before, drop it again, so that
/// MeshLab's mask and the mesh agree (a later filter that needs FF requests
/// it and gets it built).
void restoreTopologyState(MeshModel &mm, const MeshState &before) {
  if (!before.hadFaceFace && mm.cm.face.IsFFAdjacencyEnabled()) mm.cm.face.DisableFFAdjacency();
}

void enableOutputAttributes(MeshModel &mm, const es::SharpenOptions &opt) {
  if (opt.colorize) mm.updateDataMask(MeshModel::MM_FACECOLOR | MeshModel::MM_VERTCOLOR);
}

/// A refused mesh does not keep the colour layers enabled for the run.
void restoreOutputAttributes(MeshModel &mm, const MeshState &before) {
  if (!before.hadFaceColor) mm.clearDataMask(MeshModel::MM_FACECOLOR);
  if (!before.hadVertColor) mm.clearDataMask(MeshModel::MM_VERTCOLOR);
}

std::vector<std::string> lines(const std::string &text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(line);
  return out;
}

}  // namespace

FilterEdgeSharpenerPlugin::FilterEdgeSharpenerPlugin() {
  for (int id = 0; id < int(filterTable().size()); ++id) {
    typeList << id;
    actionList << new QAction(filterName(id), this);
  }
}

QString FilterEdgeSharpenerPlugin::pluginName() const {
  return "FilterEdgeSharpener";
}

QString FilterEdgeSharpenerPlugin::filterName(FilterIDType id) const {
  return spec(id).name;
}

QString FilterEdgeSharpenerPlugin::filterInfo(FilterIDType id) const {
  return QString(spec(id).info) + kCitation;
}

MeshFilterInterface::FilterClass FilterEdgeSharpenerPlugin::getClass(QAction *) {
  return MeshFilterInterface::Smoothing;
}

MeshFilterInterface::FILTER_ARITY FilterEdgeSharpenerPlugin::filterArity(QAction *) const {
  return SINGLE_MESH;
}

int FilterEdgeSharpenerPlugin::getPreConditions(QAction *) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterEdgeSharpenerPlugin::postCondition(QAction *action) const {
  return spec(ID(action)).postCondition;
}

void FilterEdgeSharpenerPlugin::initParameterSet(QAction *action, MeshModel &,
                                                 RichParameterList &par) {
  const es::SharpenOptions defaults;
  for (const OptionParam *p : spec(ID(action)).params) p->add(par, defaults);
}

bool FilterEdgeSharpenerPlugin::applyFilter(QAction *action, MeshDocument &md,
                                            const RichParameterList &par, vcg::CallBackPos *cb) {
  const FilterSpec &f = spec(ID(action));
  MeshModel &mm = *md.mm();
  es::SharpenOptions opt = readOptions(f, par);
  opt.progress = cb;  // the core reports (percent, stage) straight to MeshLab

  // One input check, the core's own (it throws InputError before changing
  // anything); colour layers are enabled first and dropped again on refusal.
  const MeshState before(mm);
  prepareTopology(mm);
  enableOutputAttributes(mm, opt);
  es::SharpenReport report;
  std::string failure;
  try {
    report = f.run(mm.cm, opt);
  } catch (const es::InputError &e) {  // bad mesh or parameter values; thrown before any change
    const std::string problem = es::findInputProblem(mm.cm);
    failure = problem.empty() ? std::string("Edge-Sharpener cannot run: ") + e.what()
                              : "Edge-Sharpener cannot process this mesh: " + problem;
  } catch (const std::exception &e) {
    failure = std::string("Edge-Sharpener failed: ") + e.what();
  }
  if (!failure.empty()) {
    restoreOutputAttributes(mm, before);
    restoreTopologyState(mm, before);
    return refuse(failure);
  }
  restoreTopologyState(mm, before);

  if (report.geometryChanged) {
    // MeshModel::UpdateBoxAndNormals() minus the face normals, which the core
    // has just computed the same way (UpdateNormal::PerFaceNormalized).
    vcg::tri::UpdateBounding<CMeshO>::Box(mm.cm);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexAngleWeighted(mm.cm);
  }
  mm.cm.svn = int(vcg::tri::UpdateSelection<CMeshO>::VertexCount(mm.cm));
  mm.cm.sfn = int(vcg::tri::UpdateSelection<CMeshO>::FaceCount(mm.cm));

  Log(std::string(f.name));
  for (const std::string &line : lines(es::formatReport(report))) Log("  " + line);
  return true;
}

bool FilterEdgeSharpenerPlugin::refuse(const std::string &why) {
  errorMessage = QString::fromStdString(why);  // shown by the GUI
  Log(GLLogStream::WARNING, why);              // meshlabserver only prints the log
  return false;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterEdgeSharpenerPlugin)
