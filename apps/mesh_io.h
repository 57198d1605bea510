// Mesh reading and writing for the command-line programs, on vcglib's
// importers/exporters (PLY, OFF, OBJ, STL), with one-line error messages.
#pragma once

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/clean.h>
#include <wrap/io_trimesh/export.h>
#include <wrap/io_trimesh/import.h>

namespace edge_sharpener::io {

inline std::string lowerExtension(const std::string &path) {
  const std::string name = path.substr(path.find_last_of('/') + 1);  // npos + 1 == 0
  const auto dot = name.find_last_of('.');
  if (dot == std::string::npos) return "";
  std::string ext = name.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

inline bool isSupportedExtension(const std::string &ext) {
  return ext == "ply" || ext == "off" || ext == "obj" || ext == "stl";
}

/// Loads `path` into `m` (cleared first). STL stores a triangle soup, so its
/// coincident vertices are merged; other formats are taken as they are
/// (polygons are triangulated by vcglib's importers).
/// \throws std::runtime_error with a one-line message.
template <class MeshType>
void loadMesh(const std::string &path, MeshType &m) {
  const std::string ext = lowerExtension(path);
  if (!isSupportedExtension(ext))
    throw std::runtime_error(path + ": unsupported format (use .ply, .off, .obj or .stl)");
  if (!std::ifstream(path).good()) throw std::runtime_error(path + ": cannot open file");
  m.Clear();
  int mask = 0;
  using Importer = vcg::tri::io::Importer<MeshType>;
  const int err = Importer::Open(m, path.c_str(), mask);
  if (err != 0 && Importer::ErrorCritical(err))
    throw std::runtime_error(path + ": cannot read mesh (" + Importer::ErrorMsg(err) + ")");
  if (ext == "stl") vcg::tri::Clean<MeshType>::RemoveDuplicateVertex(m, false);
  vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
}

/// Writes `m` to `path` through a temporary file renamed into place, so a
/// failed write never leaves a truncated output.
/// `mask` is a vcg::tri::io::Mask combination (colours, flags...).
/// \throws std::runtime_error with a one-line message.
template <class MeshType>
void saveMesh(MeshType &m, const std::string &path, int mask) {
  const std::string ext = lowerExtension(path);
  if (!isSupportedExtension(ext))
    throw std::runtime_error(path + ": unsupported output format (use .ply, .off, .obj or .stl)");
  const std::string tmp = path + ".tmp-edge-sharpener." + ext;
  using Exporter = vcg::tri::io::Exporter<MeshType>;
  const int err = Exporter::Save(m, tmp.c_str(), mask);
  if (err != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot write mesh (" + Exporter::ErrorMsg(err) + ")");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot write file");
  }
}

}  // namespace edge_sharpener::io
