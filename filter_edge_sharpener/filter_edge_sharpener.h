// MeshLab 2020.09 filter plugin for Edge-Sharpener (Attene, Falcidieno,
// Rossignac, Spagnuolo, SGP 2003). A thin adapter: the MeshFilterInterface
// glue around filter_common.h, which reads the parameters, prepares the
// CMeshO, makes one call into vcg_ext/edge_sharpener and logs the report.
#pragma once

#include <common/interfaces.h>

class FilterEdgeSharpenerPlugin : public QObject, public MeshFilterInterface {
  Q_OBJECT
  MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
  Q_INTERFACES(MeshFilterInterface)

 public:
  /// Filter ids; also indices into the filter table of the .cpp.
  enum { FP_SHARPEN, FP_DETECT };

  FilterEdgeSharpenerPlugin();

  using MeshFilterInterface::filterInfo;
  using MeshFilterInterface::filterName;
  using MeshFilterInterface::initParameterSet;

  QString pluginName() const override;
  QString filterName(FilterIDType id) const override;
  QString filterInfo(FilterIDType id) const override;
  FilterClass getClass(QAction *) override;
  FILTER_ARITY filterArity(QAction *) const override;
  int getPreConditions(QAction *) const override;
  int postCondition(QAction *action) const override;
  void initParameterSet(QAction *action, MeshModel &m, RichParameterList &par) override;
  bool applyFilter(QAction *action, MeshDocument &md, const RichParameterList &par,
                   vcg::CallBackPos *cb) override;
};
