// meshlab-filter-runner: applies MeshLab filters without the GUI, for MeshLab
// 2022.02+ (which has no meshlabserver). Linked only against the installed
// MeshLab's libmeshlab-common.so: loads the stock plugins (I/O included) and
// any extra plugin file, opens a mesh, applies one filter by name or every
// filter of an .mlx script, saves the current mesh and prints MeshLab's log.
// Exit status: 0 done, 1 a filter failed (MLException; the mesh is not saved
// unless --save-on-error), 2 usage, plugin or I/O error.
#include <common/filterscript.h>
#include <common/globals.h>
#include <common/ml_document/mesh_document.h>
#include <common/plugins/plugin_manager.h>
#include <common/utilities/load_save.h>

#include <QApplication>
#include <QDir>
#include <QDomDocument>
#include <QFileInfo>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace {

const char *kUsage =
    "usage: meshlab-filter-runner [--plugins DIR] [--add-plugin FILE]... --list\n"
    "       meshlab-filter-runner [--plugins DIR] [--add-plugin FILE]... -i IN --params 'FILTER'\n"
    "       meshlab-filter-runner [--plugins DIR] [--add-plugin FILE]... -i IN [-o OUT]\n"
    "           [--mask vc,fc,vf,ff,vq,fq,vn,wt] [-l LOG] [--save-on-error]\n"
    "           (-s SCRIPT.mlx | -f 'FILTER NAME' [-p name=value]...)\n"
    "  --plugins DIR   the stock plugins (default: MeshLab's plugin folder, found like\n"
    "                  meshlab does, then /usr/lib/x86_64-linux-gnu/meshlab/plugins)\n"
    "  --add-plugin FILE  one more plugin file to load (e.g. a build of "
    "libfilter_edge_sharpener.so)\n"
    "  --list          print every filter: name, PyMeshLab name, class bits (tab-separated)\n"
    "  --params NAME   print the filter's parameters for the mesh IN: name, type, 'advanced'\n"
    "                  (behind the dialog's toggle) or 'shown', label (tab-separated)\n"
    "  -s SCRIPT       apply the filters of a MeshLab .mlx script in order; parameters the\n"
    "                  script omits keep their defaults\n"
    "  -f NAME -p k=v  apply one filter; parameters not given keep their defaults\n"
    "  --mask LIST     per-element data written besides the geometry (as meshlabserver -m)\n"
    "  -l LOG          also write MeshLab's log there\n"
    "  --save-on-error save the mesh also when a filter fails (what the failure left)\n";

struct Options {
  QString pluginsDir, input, output, script, filter, logFile, paramsOf;
  QStringList extraPlugins, params, mask;
  bool list = false, saveOnError = false;
};

int usageError(const std::string &why) {
  std::cerr << "meshlab-filter-runner: " << why << "\n" << kUsage;
  return 2;
}

// The log lines MeshLab collected since `from`, printed (and appended to LOG).
void flushLog(const GLLogStream &log, int &from, const QString &logFile) {
  const auto &lines = log.logStringList();
  FILE *file = logFile.isEmpty() ? nullptr : std::fopen(logFile.toLocal8Bit().constData(), "a");
  for (; from < lines.size(); ++from) {
    const QByteArray text = lines[from].second.toUtf8();
    std::printf("LOG: %d %s\n", lines[from].first, text.constData());
    if (file) std::fprintf(file, "%s\n", text.constData());
  }
  std::fflush(stdout);
  if (file) std::fclose(file);
}

// Where meshlab looks (beside its executable, Debian layout), else the system's.
// Not meshlab::defaultPluginPath(): it complains on stderr when the folder is missing.
QString defaultPluginsDir() {
  const QString besideMe =
      QCoreApplication::applicationDirPath() + "/../lib/x86_64-linux-gnu/meshlab/plugins";
  if (QFileInfo(besideMe).isDir()) return QDir(besideMe).canonicalPath();
  return "/usr/lib/x86_64-linux-gnu/meshlab/plugins";
}

// `value` parsed as the type of the filter's own parameter `name`, the way
// MeshLab reads a <Param> of an .mlx script.
void setParameterFromText(RichParameterList &params, const QString &name, const QString &value) {
  if (!params.hasParameter(name)) throw MLException("the filter has no parameter '" + name + "'");
  QDomDocument doc;
  QDomElement element = doc.createElement("Param");
  element.setAttribute("name", name);
  element.setAttribute("type", params.getParameterByName(name).stringType());
  element.setAttribute("value", value);
  RichParameterList parsed;
  parsed.pushFromQDomElement(element);
  params.setValue(name, parsed.getParameterByName(name).value());
}

// Applies one filter with `given` over its defaults (MeshLab 2022.02's
// MainWindow does the same steps, minus the GL context and the rendering).
void applyFilter(PluginManager &pm, MeshDocument &md, const QString &name,
                 const RichParameterList &given) {
  QAction *action = pm.filterAction(name);
  if (action == nullptr) throw MLException("no filter named '" + name + "' is loaded");
  FilterPlugin *plugin = pm.getFilterPluginFromAction(action);
  if (plugin->requiresGLContext(action))
    throw MLException("'" + name + "' needs an OpenGL context, which this runner does not make");
  RichParameterList params = plugin->initParameterList(action, md);
  for (const RichParameter &p : given) {
    if (!params.hasParameter(p.name()))
      throw MLException("'" + name + "' has no parameter '" + p.name() + "'");
    params.setValue(p.name(), p.value());
  }
  if (md.mm() != nullptr) md.mm()->updateDataMask(plugin->getRequirements(action));
  plugin->setLog(&md.Log);
  unsigned int postConditionMask = MeshModel::MM_UNKNOWN;
  plugin->applyFilter(action, params, md, postConditionMask, nullptr);
  for (MeshModel &m : md.meshIterator()) vcg::tri::Allocator<CMeshO>::CompactEveryVector(m.cm);
}

int ioMaskOf(const QStringList &names, const MeshModel &m) {
  namespace io = vcg::tri::io;
  int mask = 0;
  for (const QString &n : names) {
    if (n == "vc" && m.hasDataMask(MeshModel::MM_VERTCOLOR))
      mask |= io::Mask::IOM_VERTCOLOR;
    else if (n == "fc" && m.hasDataMask(MeshModel::MM_FACECOLOR))
      mask |= io::Mask::IOM_FACECOLOR;
    else if (n == "vq" && m.hasDataMask(MeshModel::MM_VERTQUALITY))
      mask |= io::Mask::IOM_VERTQUALITY;
    else if (n == "fq" && m.hasDataMask(MeshModel::MM_FACEQUALITY))
      mask |= io::Mask::IOM_FACEQUALITY;
    else if (n == "vf")
      mask |= io::Mask::IOM_VERTFLAGS;
    else if (n == "ff")
      mask |= io::Mask::IOM_FACEFLAGS;
    else if (n == "vn")
      mask |= io::Mask::IOM_VERTNORMAL;
    else if (n == "wt" && m.hasDataMask(MeshModel::MM_WEDGTEXCOORD))
      mask |= io::Mask::IOM_WEDGTEXCOORD;
  }
  return mask;
}

void saveMesh(PluginManager &pm, MeshModel &m, const QString &file, const QStringList &maskNames,
              GLLogStream &log) {
  const QString ext = QFileInfo(file).suffix().toLower();
  IOPlugin *io = pm.outputMeshPlugin(ext);
  if (io == nullptr) throw MLException("no plugin saves ." + ext + " files");
  io->setLog(&log);
  int capability = 0, defaultBits = 0;
  io->exportMaskCapability(ext, capability, defaultBits);
  const RichParameterList params = io->initSaveParameter(ext, m);
  io->save(ext, file, m, ioMaskOf(maskNames, m) & capability, params, nullptr);
}

bool parseArguments(const QStringList &args, Options &o, std::string &error) {
  for (int i = 1; i < args.size(); ++i) {
    const QString &a = args[i];
    auto next = [&]() -> QString {
      if (i + 1 >= args.size()) {
        error = a.toStdString() + " needs a value";
        return {};
      }
      return args[++i];
    };
    if (a == "--plugins")
      o.pluginsDir = next();
    else if (a == "--add-plugin")
      o.extraPlugins << next();
    else if (a == "--list")
      o.list = true;
    else if (a == "--params")
      o.paramsOf = next();
    else if (a == "-i")
      o.input = next();
    else if (a == "-o")
      o.output = next();
    else if (a == "-s")
      o.script = next();
    else if (a == "-f")
      o.filter = next();
    else if (a == "-p")
      o.params << next();
    else if (a == "-l")
      o.logFile = next();
    else if (a == "--mask")
      o.mask = next().split(',', Qt::SkipEmptyParts);
    else if (a == "--save-on-error")
      o.saveOnError = true;
    else
      error = "unknown argument '" + a.toStdString() + "'";
    if (!error.empty()) return false;
  }
  if (o.list) return true;
  if (o.input.isEmpty())
    error = "no input mesh (-i)";
  else if (!o.paramsOf.isEmpty() && (!o.script.isEmpty() || !o.filter.isEmpty()))
    error = "--params goes without -s and -f";
  else if (!o.paramsOf.isEmpty())
    return true;
  else if (o.script.isEmpty() == o.filter.isEmpty())
    error = "give either -s SCRIPT or -f FILTER";
  else if (!o.params.isEmpty() && o.filter.isEmpty())
    error = "-p goes with -f";
  return error.empty();
}

}  // namespace

int main(int argc, char **argv) {
  // The plugins are Qt GUI plugins; run with QT_QPA_PLATFORM=offscreen. (Qt takes
  // its own options such as -plugin out of argv: hence --add-plugin.)
  QApplication app(argc, argv);
  Options o;
  std::string error;
  if (!parseArguments(app.arguments(), o, error)) return usageError(error);
  if (!o.logFile.isEmpty()) QFile::remove(o.logFile);

  PluginManager &pm = meshlab::pluginManagerInstance();  // the one meshlab::loadMesh uses
  const QString pluginsDir = o.pluginsDir.isEmpty() ? defaultPluginsDir() : o.pluginsDir;
  // The stock plugins one by one, so that an installed copy of a plugin given with
  // --add-plugin (same file name) is left out: the given build replaces it.
  QStringList extraNames;
  for (const QString &file : o.extraPlugins) extraNames << QFileInfo(file).fileName();
  const QDir stock(pluginsDir);
  if (!stock.exists()) return usageError("no plugin folder " + pluginsDir.toStdString());
  for (const QFileInfo &file : stock.entryInfoList(QStringList() << "*.so", QDir::Files)) {
    if (extraNames.contains(file.fileName())) continue;
    try {
      pm.loadPlugin(file.absoluteFilePath());
    } catch (const MLException &e) {  // as meshlab: go on without that stock plugin
      std::cerr << "warning: " << e.what() << "\n";
    }
  }
  for (const QString &file : o.extraPlugins) {
    try {
      pm.loadPlugin(QFileInfo(file).absoluteFilePath());
    } catch (const MLException &e) {
      std::cerr << "meshlab-filter-runner: cannot load plugin " << file.toStdString() << ": "
                << e.what() << "\n";
      return 2;
    }
  }
  std::printf("Loaded %u plugins from %s\n", pm.size(), qUtf8Printable(pluginsDir));

  if (o.list) {
    for (FilterPlugin *plugin : pm.filterPluginIterator())
      for (QAction *action : plugin->actions())
        std::printf("%s\t%s\t0x%x\n", qUtf8Printable(plugin->filterName(action)),
                    qUtf8Printable(plugin->pythonFilterName(action)),
                    unsigned(plugin->getClass(action)));
    return 0;
  }

  std::vector<std::pair<QString, RichParameterList>> steps;
  if (!o.script.isEmpty()) {
    FilterScript script;
    if (!script.open(o.script))
      return usageError("cannot read the script " + o.script.toStdString());
    for (const FilterNameParameterValuesPair &step : script)
      steps.emplace_back(step.first, step.second);
  }

  MeshDocument md;
  int logged = 0;
  try {
    meshlab::loadMeshWithStandardParameters(o.input, md);
    if (!o.paramsOf.isEmpty()) {
      QAction *action = pm.filterAction(o.paramsOf);
      if (action == nullptr) throw MLException("no filter named '" + o.paramsOf + "' is loaded");
      for (const RichParameter &p :
           pm.getFilterPluginFromAction(action)->initParameterList(action, md))
        std::printf("%s\t%s\t%s\t%s\n", qUtf8Printable(p.name()), qUtf8Printable(p.stringType()),
                    p.isAdvanced() ? "advanced" : "shown", qUtf8Printable(p.fieldDescription()));
      return 0;
    }
    if (!o.filter.isEmpty()) {
      QAction *action = pm.filterAction(o.filter);
      if (action == nullptr) throw MLException("no filter named '" + o.filter + "' is loaded");
      RichParameterList given = pm.getFilterPluginFromAction(action)->initParameterList(action, md);
      for (const QString &p : o.params) {
        const int eq = p.indexOf('=');
        if (eq <= 0) return usageError("-p wants name=value, not '" + p.toStdString() + "'");
        setParameterFromText(given, p.left(eq), p.mid(eq + 1));
      }
      steps.emplace_back(o.filter, given);
    }
  } catch (const MLException &e) {
    flushLog(md.Log, logged, o.logFile);
    std::cerr << "meshlab-filter-runner: " << e.what() << "\n";
    return 2;
  }

  int status = 0;
  for (const auto &[name, params] : steps) {
    try {
      applyFilter(pm, md, name, params);
      flushLog(md.Log, logged, o.logFile);
    } catch (const MLException &e) {
      md.Log.log(GLLogStream::WARNING, "Filter '" + name + "' failed: " + QString(e.what()));
      flushLog(md.Log, logged, o.logFile);
      std::cerr << "meshlab-filter-runner: filter '" << name.toStdString()
                << "' failed: " << e.what() << "\n";
      status = 1;
      break;
    }
  }

  if (!o.output.isEmpty() && (status == 0 || o.saveOnError)) {
    try {
      saveMesh(pm, *md.mm(), o.output, o.mask, md.Log);
      flushLog(md.Log, logged, o.logFile);
    } catch (const MLException &e) {
      std::cerr << "meshlab-filter-runner: cannot save " << o.output.toStdString() << ": "
                << e.what() << "\n";
      return 2;
    }
  }
  return status;
}
