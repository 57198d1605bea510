// MeshLab 2022.02+ adapter of Edge-Sharpener: the FilterPlugin glue only.
// Filters, parameters and the run come from filter_common.h.
#include "filter_edge_sharpener_modern.h"

#include "../filter_common.h"

namespace esm = edge_sharpener::meshlab;

FilterEdgeSharpenerPlugin::FilterEdgeSharpenerPlugin() {
  for (int id = 0; id < int(esm::filterTable().size()); ++id) {
    typeList.push_back(id);
    actionList.push_back(new QAction(filterName(id), this));
  }
}

QString FilterEdgeSharpenerPlugin::pluginName() const {
  return "FilterEdgeSharpener";
}

QString FilterEdgeSharpenerPlugin::vendor() const {
  return "Edge-Sharpener project";  // not the stock plugins' vendor (CNR-ISTI VCLab)
}

QString FilterEdgeSharpenerPlugin::filterName(ActionIDType id) const {
  return esm::filterSpec(id).name;
}

QString FilterEdgeSharpenerPlugin::pythonFilterName(ActionIDType id) const {
  return esm::filterSpec(id).pythonName;
}

QString FilterEdgeSharpenerPlugin::filterInfo(ActionIDType id) const {
  return QString(esm::filterSpec(id).info) + esm::citation();
}

FilterPlugin::FilterClass FilterEdgeSharpenerPlugin::getClass(const QAction *) const {
  return FilterPlugin::Smoothing;  // the menu 2020.09 users find it in
}

FilterPlugin::FilterArity FilterEdgeSharpenerPlugin::filterArity(const QAction *) const {
  return SINGLE_MESH;
}

int FilterEdgeSharpenerPlugin::getPreConditions(const QAction *) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterEdgeSharpenerPlugin::postCondition(const QAction *action) const {
  return esm::filterSpec(ID(action)).postCondition;
}

RichParameterList FilterEdgeSharpenerPlugin::initParameterList(const QAction *action,
                                                               const MeshModel &) {
  RichParameterList par;
  // The ordinary options, as in 2020.09, then (Sharpen) each method's tuning
  // as advanced parameters: the dialog shows them under its ▼ toggle ("Show
  // advanced parameters"); scripts and PyMeshLab set them by name. The
  // constructor argument after the tooltip is RichParameter's isAdvanced
  // (RichBool etc. call it `hidden`); no category (a category's title would
  // stay in sight with its parameters hidden).
  const esm::FilterSpec &filter = esm::filterSpec(ID(action));
  for (const auto *spec : esm::parametersOf(filter, /*withTuning=*/true))
    esm::addParameter(par, *spec, /*isAdvanced=*/!spec->ordinary());
  esm::addSelectionParameter(par, filter, /*isAdvanced=*/false);
  return par;
}

std::map<std::string, QVariant> FilterEdgeSharpenerPlugin::applyFilter(
    const QAction *action, const RichParameterList &par, MeshDocument &md,
    unsigned int & /*postConditionMask: postCondition() is right for every run*/,
    vcg::CallBackPos *cb) {
  const esm::FilterOutcome outcome = esm::runFilter(esm::filterSpec(ID(action)), *md.mm(), par, cb);
  if (!outcome.failure.empty()) throw MLException(QString::fromStdString(outcome.failure));
  // "%s": the report's lines are text, not printf formats.
  for (const std::string &line : outcome.log) log("%s", line.c_str());
  return {};
}
