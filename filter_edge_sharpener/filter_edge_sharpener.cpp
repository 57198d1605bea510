// MeshLab 2020.09 adapter of Edge-Sharpener: the MeshFilterInterface glue
// only. Filters, parameters and the run are shared with the 2022.02+ adapter
// (filter_common.h); every parameter is a row of the option table.
#include "filter_edge_sharpener.h"

#include "filter_common.h"

namespace esm = edge_sharpener::meshlab;

FilterEdgeSharpenerPlugin::FilterEdgeSharpenerPlugin() {
  for (int id = 0; id < int(esm::filterTable().size()); ++id) {
    typeList << id;
    actionList << new QAction(filterName(id), this);
  }
}

QString FilterEdgeSharpenerPlugin::pluginName() const {
  return "FilterEdgeSharpener";
}

QString FilterEdgeSharpenerPlugin::filterName(FilterIDType id) const {
  return esm::filterSpec(id).name;
}

QString FilterEdgeSharpenerPlugin::filterInfo(FilterIDType id) const {
  return QString(esm::filterSpec(id).info) + esm::citation();
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
  return esm::filterSpec(ID(action)).postCondition;
}

void FilterEdgeSharpenerPlugin::initParameterSet(QAction *action, MeshModel &,
                                                 RichParameterList &par) {
  // The ordinary options only: 2020.09's dialog has no advanced section for
  // each method's tuning (the CLI and Python have it).
  const esm::FilterSpec &filter = esm::filterSpec(ID(action));
  for (const auto *spec : esm::parametersOf(filter, /*withTuning=*/false))
    esm::addParameter(par, *spec);
  esm::addSelectionParameter(par, filter);
}

bool FilterEdgeSharpenerPlugin::applyFilter(QAction *action, MeshDocument &md,
                                            const RichParameterList &par, vcg::CallBackPos *cb) {
  const esm::FilterOutcome outcome = esm::runFilter(esm::filterSpec(ID(action)), *md.mm(), par, cb);
  if (!outcome.failure.empty()) {
    errorMessage = QString::fromStdString(outcome.failure);  // shown by the GUI
    Log(GLLogStream::WARNING, outcome.failure);              // meshlabserver only prints the log
    return false;
  }
  for (const std::string &line : outcome.log) Log(line);
  return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterEdgeSharpenerPlugin)
