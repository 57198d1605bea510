// MeshLab 2022.02+ filter plugin for Edge-Sharpener (Attene, Falcidieno,
// Rossignac, Spagnuolo, SGP 2003): the FilterPlugin glue around
// filter_common.h, which it shares with the 2020.09 adapter (same filter
// names, parameter names and .mlx interface). The same source builds for
// MeshLab 2022.02, 2023.12 and 2025.07 (their plugin API did not change);
// the binary fits only the release whose headers it was built against
// (MeshLab checks MESHLAB_VERSION when it loads a plugin).
#pragma once

#include <common/plugins/interfaces/filter_plugin.h>

class FilterEdgeSharpenerPlugin : public QObject, public FilterPlugin {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(FILTER_PLUGIN_IID)
  Q_INTERFACES(FilterPlugin)

 public:
  FilterEdgeSharpenerPlugin();

  QString pluginName() const override;
  QString vendor() const override;
  QString filterName(ActionIDType id) const override;
  QString pythonFilterName(ActionIDType id) const override;
  QString filterInfo(ActionIDType id) const override;
  FilterClass getClass(const QAction *) const override;
  FilterArity filterArity(const QAction *) const override;
  int getPreConditions(const QAction *) const override;
  int postCondition(const QAction *action) const override;
  RichParameterList initParameterList(const QAction *action, const MeshModel &m) override;
  std::map<std::string, QVariant> applyFilter(const QAction *action, const RichParameterList &par,
                                              MeshDocument &md, unsigned int &postConditionMask,
                                              vcg::CallBackPos *cb) override;
};
