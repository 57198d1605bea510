// Prints the entries of one submenu of MeshLab's Filters menu, in the order the
// MeshLab 2020.09 GUI shows them, so that the GUI test can reach a filter with
// the keyboard whatever the set of installed plugins.
//   list_filter_menu PLUGIN_DIR CLASS_MASK   (e.g. 0x80 = Smoothing, Fairing and Deformation)
// The GUI fills each submenu with the filters whose class has the submenu's bit,
// walking a QMap keyed by filter name (mainwindow_Init.cpp, fillFilterMenu): the
// order is QString's, which this program reproduces by using the same QMap.
#include <common/interfaces.h>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QMap>
#include <QPluginLoader>
#include <cstdio>

int main(int argc, char **argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: list_filter_menu PLUGIN_DIR CLASS_MASK\n");
    return 2;
  }
  QApplication app(argc, argv);
  const QDir dir(QString::fromLocal8Bit(argv[1]));
  bool ok = false;
  const int mask = QString(argv[2]).toInt(&ok, 0);
  if (!ok || !dir.exists()) {
    std::fprintf(stderr, "bad plugin dir or class mask\n");
    return 2;
  }
  QMap<QString, int> classByName;
  for (const QString &file : dir.entryList({"*.so"}, QDir::Files)) {
    QPluginLoader loader(dir.absoluteFilePath(file));
    auto *filters = qobject_cast<MeshFilterInterface *>(loader.instance());
    if (!filters) continue;
    for (QAction *action : filters->actions())
      classByName.insert(action->text(), int(filters->getClass(action)));
  }
  for (auto it = classByName.cbegin(); it != classByName.cend(); ++it)
    if (it.value() & mask) std::printf("%s\n", qUtf8Printable(it.key()));
  std::fflush(stdout);
  std::_Exit(0);  // skip the plugins' static destructors: some assume a MeshLab main window
}
