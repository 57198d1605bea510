// What the MeshLab adapters share, whatever MeshLab's plugin API: the filter
// table (names, descriptions, core entry points), the parameters (from the
// option table of vcg_ext/edge_sharpener/option_table.h: labels and help are
// the table's), and one filter run that prepares the CMeshO, calls the core
// and leaves a refused mesh as it was. The includer includes its MeshLab's
// plugin interface header first (RichParameterList, MeshModel and MeshDocument
// are the same in 2020.09 and 2022.02+).
#pragma once

#include <edge_sharpener/edge_sharpener.h>
#include <edge_sharpener/option_table.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/selection.h>
#include <vcg/complex/allocate.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

namespace edge_sharpener::meshlab {

/// One filter of the plugin.
struct FilterSpec {
  const char *name;
  const char *pythonName;  ///< PyMeshLab's name of the filter (2022.02+)
  const char *info;        ///< HTML, without the bibliography
  unsigned parameterMask;  ///< which rows of the option table it shows (MeshLabFilterMask)
  /// Also shows each method's tuning, as advanced parameters, where MeshLab
  /// has them (2022.02+: RichParameter's isAdvanced, behind the dialog's ▼).
  bool tuning;
  SharpenReport (*run)(CMeshO &, const SharpenOptions &);
  bool alwaysColorize;  ///< paints colours whatever the parameters say
  /// Takes "Affect only selected faces" (SharpenOptions::selectedFacesOnly).
  bool affectsSelection;
  int postCondition;
};

inline const char *citation() {
  return "<br><br>See:<br>"
         "<i>Marco Attene, Bianca Falcidieno, Jarek Rossignac, Michela Spagnuolo</i><br>"
         "<b>\"Edge-Sharpener: Recovering sharp features in triangulations of non-adaptively "
         "re-meshed surfaces\"</b><br>"
         "Eurographics Symposium on Geometry Processing (SGP), 2003.";
}

/// The filters, in the order of their ids.
inline const std::vector<FilterSpec> &filterTable() {
  static const std::vector<FilterSpec> table{
      {"Edge-Sharpener: Sharpen Chamfered Edges", "sharpen_chamfered_edges",
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
       "Needs a triangle mesh (a point cloud is refused and left untouched). Faces at a "
       "non-manifold vertex or edge are left as they came, with the features that reach "
       "them. With <i>Affect only selected faces</i>, the faces outside the selection are "
       "left as they came: a feature wholly outside it is left, one it cuts is sharpened up "
       "to its border (deselect a designed bevel after <i>Detect Chamfers</i>). The report "
       "of every stage is written to the log.",
       kInSharpen, true, &sharpen<CMeshO>, false, true,
       MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE | MeshModel::MM_VERTCOLOR |
           MeshModel::MM_FACECOLOR | MeshModel::MM_FACEFLAGSELECT},
      {"Edge-Sharpener: Detect Chamfers", "detect_chamfers",
       "Runs the detection stages of Edge-Sharpener only (the smooth-edge test and the six "
       "filters of the paper), without changing the geometry: paints the labels into "
       "per-face colour (smooth regions red, chamfer triangles blue, corner triangles green, "
       "others grey) and selects the faces that <i>Sharpen Chamfered Edges</i> may change "
       "(the paper's method: the chamfer and corner triangles it subdivides; the others: "
       "every face of a feature zone).<br>"
       "Useful to tune the smooth-edge multiplier before sharpening, and to choose what to "
       "sharpen: deselect a designed bevel, then sharpen with <i>Affect only selected "
       "faces</i>.",
       kInDetect, false, &detectChamfers<CMeshO>, true, false,
       MeshModel::MM_VERTCOLOR | MeshModel::MM_FACECOLOR | MeshModel::MM_FACEFLAGSELECT},
  };
  return table;
}

inline const FilterSpec &filterSpec(int id) {
  return filterTable().at(std::size_t(id));
}

/// The rows of the option table that filter `f` shows, in table order: its
/// ordinary options, and with `withTuning` (MeshLab 2022.02+) each method's
/// tuning too when the filter takes it.
inline std::vector<const OptionSpec *> parametersOf(const FilterSpec &f, bool withTuning) {
  std::vector<const OptionSpec *> out;
  for (const OptionSpec &spec : optionTable())
    if ((spec.meshlabFilters & f.parameterMask) || (withTuning && f.tuning && !spec.ordinary()))
      out.push_back(&spec);
  return out;
}

/// An option's parameter name in MeshLab and its .mlx scripts: the table's,
/// else (the tuning options) its key in camelCase, as the ordinary ones are
/// named (max_label_hops: maxLabelHops).
inline QString parameterName(const OptionSpec &spec) {
  if (!spec.meshlabName.empty())
    return QString::fromUtf8(spec.meshlabName.data(), int(spec.meshlabName.size()));
  std::string name;
  bool upper = false;
  for (const char c : spec.key) {
    if (c == '_') {
      upper = true;
      continue;
    }
    name += upper ? char(std::toupper(static_cast<unsigned char>(c))) : c;
    upper = false;
  }
  return QString::fromStdString(name);
}

/// A MeshLab parameter of one option row, at the option's default: the
/// table's label, its help as the tooltip (a tuning option's with its group
/// and unit). `extra` forwards the 2022.02+ constructor arguments (isAdvanced,
/// category), if any.
template <class... Extra>
void addParameter(RichParameterList &par, const OptionSpec &spec, Extra... extra) {
  const QString name = parameterName(spec);
  const QString label = QString::fromUtf8(spec.label.data(), int(spec.label.size()));
  QString help = QString::fromUtf8(spec.help.data(), int(spec.help.size()));
  if (!spec.ordinary()) {
    help = QString(toString(spec.group)) + ". " + help;
    if (!spec.unit.empty())
      help += " [" + QString::fromUtf8(spec.unit.data(), int(spec.unit.size())) + "]";
  }
  const double value = spec.defaultValue();
  switch (spec.type) {
    case OptionType::Flag: par.addParam(RichBool(name, value != 0, label, help, extra...)); break;
    case OptionType::Integer: par.addParam(RichInt(name, int(value), label, help, extra...)); break;
    case OptionType::Real:
      par.addParam(RichFloat(name, float(value), label, help, extra...));
      break;
    case OptionType::Choice: {
      QStringList labels;
      for (std::string_view l : spec.choiceLabels)
        labels << QString::fromUtf8(l.data(), int(l.size()));
      par.addParam(RichEnum(name, int(value), labels, label, help, extra...));
      break;
    }
  }
}

/// MeshLab's name of "Affect only selected faces", as its own filters call it.
inline QString selectionParameterName() {
  return "Selected";
}

/// "Affect only selected faces", for the filters that take it, off by
/// default; `extra` as addParameter's.
template <class... Extra>
void addSelectionParameter(RichParameterList &par, const FilterSpec &f, Extra... extra) {
  if (!f.affectsSelection) return;
  par.addParam(RichBool(selectionParameterName(), false, "Affect only selected faces",
                        "Sharpen only within the selected faces: a feature wholly outside the "
                        "selection is left as it came, one it cuts is sharpened up to its "
                        "border; no face outside it moves or is split. Nothing selected: the "
                        "mesh is left as it is.",
                        extra...));
}

/// The number a person entered, from the float MeshLab keeps it as: the
/// shortest decimal that reads back as that float (0.3f gives 0.3, not
/// 0.30000001192), so a value means what it means on the command line.
inline double enteredValue(float value) {
  char text[32];
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, double(value));
    if (std::strtof(text, nullptr) == value) break;
  }
  return std::strtod(text, nullptr);
}

/// The core's options from filter `f`'s parameters; its defaults for those
/// the list lacks (a script written before they existed, which MeshLab
/// 2022.02's GUI passes as it is).
inline SharpenOptions readOptions(const FilterSpec &f, const RichParameterList &par) {
  SharpenOptions opt;
  for (const OptionSpec *spec : parametersOf(f, /*withTuning=*/true)) {
    const QString name = parameterName(*spec);
    if (!par.hasParameter(name)) continue;
    switch (spec->type) {
      case OptionType::Flag: spec->set(opt, par.getBool(name) ? 1.0 : 0.0); break;
      case OptionType::Integer: spec->set(opt, par.getInt(name)); break;
      case OptionType::Real: spec->set(opt, enteredValue(float(par.getFloat(name)))); break;
      case OptionType::Choice: spec->set(opt, par.getEnum(name)); break;
    }
  }
  if (f.alwaysColorize) opt.colorize = true;
  if (f.affectsSelection && par.hasParameter(selectionParameterName()))
    opt.selectedFacesOnly = par.getBool(selectionParameterName());
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
inline void prepareTopology(MeshModel &mm) {
  vcg::tri::Allocator<CMeshO>::CompactEveryVector(mm.cm);
  if (!mm.cm.face.IsFFAdjacencyEnabled()) mm.cm.face.EnableFFAdjacency();
}

/// After the core call: FF adjacency is valid (built and maintained by the
/// core). If the mesh had no FF component before, drop it again, so that
/// MeshLab's mask and the mesh agree (a later filter that needs FF requests
/// it and gets it built).
inline void restoreTopologyState(MeshModel &mm, const MeshState &before) {
  if (!before.hadFaceFace && mm.cm.face.IsFFAdjacencyEnabled()) mm.cm.face.DisableFFAdjacency();
}

/// A refused mesh does not keep the colour layers enabled for the run.
inline void restoreOutputAttributes(MeshModel &mm, const MeshState &before) {
  if (!before.hadFaceColor) mm.clearDataMask(MeshModel::MM_FACECOLOR);
  if (!before.hadVertColor) mm.clearDataMask(MeshModel::MM_VERTCOLOR);
}

inline std::vector<std::string> lines(const std::string &text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(line);
  return out;
}

/// What one filter run did: the report's lines to log, or why it refused.
struct FilterOutcome {
  std::string failure;  ///< empty when the filter ran
  std::vector<std::string> log;
};

/// Runs filter `f` on the current mesh: one core call. A refused mesh (bad
/// mesh or parameter values: the core throws before changing anything) keeps
/// its geometry and its MeshLab state.
inline FilterOutcome runFilter(const FilterSpec &f, MeshModel &mm, const RichParameterList &par,
                               vcg::CallBackPos *cb) {
  SharpenOptions opt = readOptions(f, par);
  opt.progress = cb;  // the core reports (percent, stage) straight to MeshLab
  const MeshState before(mm);
  prepareTopology(mm);
  if (opt.colorize) mm.updateDataMask(MeshModel::MM_FACECOLOR | MeshModel::MM_VERTCOLOR);
  SharpenReport report;
  FilterOutcome outcome;
  try {
    report = f.run(mm.cm, opt);
  } catch (const InputError &e) {
    const std::string problem = findInputProblem(mm.cm);
    outcome.failure = problem.empty() ? std::string("Edge-Sharpener cannot run: ") + e.what()
                                      : "Edge-Sharpener cannot process this mesh: " + problem;
  } catch (const std::exception &e) {
    outcome.failure = std::string("Edge-Sharpener failed: ") + e.what();
  }
  if (!outcome.failure.empty()) {
    restoreOutputAttributes(mm, before);
    restoreTopologyState(mm, before);
    return outcome;
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
  outcome.log.push_back(f.name);
  outcome.log.push_back("  " + formatVerdictSummary(report));
  if (const std::string notes = formatInputNotes(report); !notes.empty())
    outcome.log.push_back("  " + notes);
  for (const std::string &line : lines(formatReport(report))) outcome.log.push_back("  " + line);
  // New vertices take their sources' mean colour (subdivide()); per-wedge
  // texture coordinates are face data, copied from the split face.
  if (report.geometryChanged && report.outputVertices > report.inputVertices &&
      vcg::tri::HasPerWedgeTexCoord(mm.cm))
    outcome.log.push_back(
        "  note: the new faces copy their parent face's per-wedge texture coordinates (not "
        "interpolated): the texture may look stretched along the restored edges");
  return outcome;
}

}  // namespace edge_sharpener::meshlab
