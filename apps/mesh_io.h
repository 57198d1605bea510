// Mesh reading and writing for the command-line programs, on vcglib's
// importers/exporters (PLY, OFF, OBJ, STL), with one-line error messages.
#pragma once

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/export.h>
#include <wrap/io_trimesh/import.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace edge_sharpener::io {

inline std::string lowerExtension(const std::string &path) {
  const std::string name = path.substr(path.find_last_of('/') + 1);  // npos + 1 == 0
  const auto dot = name.find_last_of('.');
  if (dot == std::string::npos) return "";
  std::string ext = name.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

inline bool isSupportedExtension(const std::string &ext) {
  return ext == "ply" || ext == "off" || ext == "obj" || ext == "stl";
}

namespace detail {

/// A triangle soup read from an STL file.
struct StlSoup {
  std::vector<float> coords;  // 9 per triangle
};

inline bool readStlNumber(const std::string &token, float &value) {
  if (token.empty()) return false;
  char *end = nullptr;
  value = std::strtof(token.c_str(), &end);
  return end == token.c_str() + token.size();
}

/// ASCII STL: "solid [name]" then facets "facet normal x y z / outer loop /
/// vertex x y z (x3) / endloop / endfacet", then "endsolid [name]" (several
/// solids allowed). Anything else is an error.
inline void parseAsciiStl(const std::string &text, StlSoup &soup) {
  std::istringstream in(text);
  std::string token;
  auto fail = [](const std::string &why) {
    throw std::runtime_error("malformed ASCII STL: " + why);
  };
  int solids = 0;
  while (in >> token) {
    if (token == "solid") {
      ++solids;
      std::getline(in, token);  // the name
      continue;
    }
    if (token == "endsolid") {
      std::getline(in, token);
      continue;
    }
    if (token != "facet") fail("unexpected '" + token.substr(0, 20) + "'");
    if (solids == 0) fail("facet before 'solid'");
    std::string normal, x, y, z, outer, loop;
    float n;
    if (!(in >> normal >> x >> y >> z) || normal != "normal" || !readStlNumber(x, n) ||
        !readStlNumber(y, n) || !readStlNumber(z, n))
      fail("bad 'facet normal' line");
    if (!(in >> outer >> loop) || outer != "outer" || loop != "loop") fail("missing 'outer loop'");
    for (int k = 0; k < 3; ++k) {
      std::string vertex, c[3];
      if (!(in >> vertex >> c[0] >> c[1] >> c[2]) || vertex != "vertex")
        fail("a facet needs three 'vertex x y z' lines");
      for (const std::string &ci : c) {
        float value;
        if (!readStlNumber(ci, value)) fail("bad coordinate '" + ci.substr(0, 20) + "'");
        soup.coords.push_back(value);
      }
    }
    std::string endloop, endfacet;
    if (!(in >> endloop >> endfacet) || endloop != "endloop" || endfacet != "endfacet")
      fail("missing 'endloop endfacet' (only triangles are allowed)");
  }
  if (solids == 0) fail("no 'solid'");
}

/// Reads an STL file defensively (vcglib's STL importer reads past the end of
/// short or empty files and loops forever on some): binary when the size is
/// exactly 84 + 50 x the declared triangle count, else ASCII starting with
/// "solid", else an error.
inline StlSoup readStl(const std::string &path) {
  std::ifstream file(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(file)), {});
  StlSoup soup;
  if (bytes.size() >= 84) {
    std::uint32_t count;
    std::memcpy(&count, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50 * std::uint64_t(count)) {
      soup.coords.resize(9 * std::size_t(count));
      for (std::size_t t = 0; t < count; ++t)
        std::memcpy(&soup.coords[9 * t], bytes.data() + 84 + 50 * t + 12, 36);  // skip the normal
      return soup;
    }
  }
  std::size_t start = 0;
  while (start < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[start]))) ++start;
  if (bytes.compare(start, 5, "solid") != 0) {
    if (bytes.size() >= 84) {
      std::uint32_t count;
      std::memcpy(&count, bytes.data() + 80, 4);
      throw std::runtime_error("malformed binary STL (declares " + std::to_string(count) +
                               " triangles, the file has room for " +
                               std::to_string((bytes.size() - 84) / 50) + ")");
    }
    throw std::runtime_error("not an STL file (too short for binary, no 'solid' for ASCII)");
  }
  if (std::find(bytes.begin(), bytes.end(), '\0') != bytes.end())
    throw std::runtime_error("malformed STL (binary data in an ASCII file)");
  parseAsciiStl(bytes, soup);
  return soup;
}

/// An indexed polygon mesh read by the text readers below.
struct PolygonMesh {
  std::vector<float> coords;             // 3 per vertex
  std::vector<std::vector<long>> faces;  // 0-based, validated
};

/// Splits text into lines without comments ('#' to end of line) and blank lines.
inline std::vector<std::string> contentLines(const std::string &text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r\f\v") != std::string::npos) lines.push_back(line);
  }
  return lines;
}

inline bool parseLong(const std::string &token, long &value) {
  if (token.empty()) return false;
  char *end = nullptr;
  errno = 0;
  value = std::strtol(token.c_str(), &end, 10);
  return errno == 0 && end == token.c_str() + token.size();
}

/// ASCII OFF (header OFF, COFF, NOFF, CNOFF, STOFF...: per-vertex extras after
/// x y z and per-face colours after the indices are ignored). Binary and
/// 4D/nD OFF are refused.
inline PolygonMesh parseOff(const std::string &text) {
  auto fail = [](const std::string &why) { throw std::runtime_error("malformed OFF: " + why); };
  const std::vector<std::string> lines = contentLines(text);
  std::size_t at = 0;
  if (at == lines.size()) fail("no header");
  std::istringstream header(lines[0]);
  std::string first;
  header >> first;
  if (first.size() >= 3 && first.compare(first.size() - 3, 3, "OFF") == 0) {
    if (first.find('4') != std::string::npos || first.find('n') != std::string::npos)
      fail("only 3D OFF is supported");
    std::string rest;
    if (header >> rest) {
      if (rest == "BINARY") fail("binary OFF is not supported");
      header = std::istringstream(lines[0].substr(lines[0].find(first) + first.size()));
    } else {
      ++at;
      if (at == lines.size()) fail("no element counts");
      header = std::istringstream(lines[at]);
    }
  } else {
    header = std::istringstream(lines[0]);  // headerless OFF: counts first
  }
  std::string tv, tf;
  long nv, nf;
  if (!(header >> tv >> tf) || !parseLong(tv, nv) || !parseLong(tf, nf) || nv < 0 || nf < 0)
    fail("bad element counts");
  ++at;
  if (std::uint64_t(nv) + std::uint64_t(nf) > lines.size() - at)
    fail("declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
         " faces, the file has " + std::to_string(lines.size() - at) + " lines");
  PolygonMesh mesh;
  mesh.coords.reserve(3 * nv);
  for (long i = 0; i < nv; ++i, ++at) {
    std::istringstream in(lines[at]);
    std::string c[3];
    for (std::string &ci : c) {
      float value;
      if (!(in >> ci) || !readStlNumber(ci, value)) fail("bad vertex line " + std::to_string(i));
      mesh.coords.push_back(value);
    }
  }
  for (long i = 0; i < nf; ++i, ++at) {
    std::istringstream in(lines[at]);
    std::string tk;
    long k;
    if (!(in >> tk) || !parseLong(tk, k) || k < 0 || k > 1000000)
      fail("bad face line " + std::to_string(i));
    std::vector<long> face;
    for (long j = 0; j < k; ++j) {
      long index;
      if (!(in >> tk) || !parseLong(tk, index)) fail("face " + std::to_string(i) + " is short");
      if (index < 0 || index >= nv)
        fail("face " + std::to_string(i) + " has vertex index " + std::to_string(index) +
             " out of range [0, " + std::to_string(nv) + ")");
      face.push_back(index);
    }
    if (k < 3) fail("face " + std::to_string(i) + " has fewer than 3 vertices");
    mesh.faces.push_back(std::move(face));
  }
  return mesh;
}

/// OBJ: "v x y z [...]" and "f a b c ..." (a = v, v/t, v//n or v/t/n; negative
/// = relative to the last vertex); other statements (vt, vn, g, o, s, usemtl,
/// mtllib, l, ...) are ignored. An index out of range is an error.
inline PolygonMesh parseObj(const std::string &text) {
  auto fail = [](const std::string &why) { throw std::runtime_error("malformed OBJ: " + why); };
  PolygonMesh mesh;
  std::size_t lineNo = 0;
  std::vector<std::string> lines = contentLines(text);
  for (std::string &line : lines) {
    ++lineNo;
    while (!line.empty() && line.back() == '\\') line.pop_back();  // continuation: same line
    std::istringstream in(line);
    std::string kw;
    in >> kw;
    if (kw == "v") {
      for (int c = 0; c < 3; ++c) {
        std::string tk;
        float value;
        if (!(in >> tk) || !readStlNumber(tk, value))
          fail("bad vertex statement on content line " + std::to_string(lineNo));
        mesh.coords.push_back(value);
      }
    } else if (kw == "f") {
      std::vector<long> face;
      const long nv = long(mesh.coords.size() / 3);
      std::string tk;
      while (in >> tk) {
        long index;
        if (!parseLong(tk.substr(0, tk.find('/')), index) || index == 0)
          fail("bad face index '" + tk.substr(0, 20) + "'");
        index = index > 0 ? index - 1 : nv + index;
        if (index < 0 || index >= nv)
          fail("face index " + tk.substr(0, 20) + " out of range (" + std::to_string(nv) +
               " vertices so far)");
        face.push_back(index);
      }
      if (face.size() < 3) fail("face with fewer than 3 vertices");
      mesh.faces.push_back(std::move(face));
    } else {
      static const char *const kIgnored[] = {
          "vt",     "vn",     "vp",  "l",    "p",     "g",    "o",    "s",   "mg",   "usemtl",
          "mtllib", "cstype", "deg", "curv", "curv2", "surf", "parm", "end", "trim", "hole"};
      if (std::find(std::begin(kIgnored), std::end(kIgnored), kw) == std::end(kIgnored))
        fail("unknown statement '" + kw.substr(0, 20) + "' on content line " +
             std::to_string(lineNo));
    }
  }
  return mesh;
}

/// Triangulates each polygon as a fan from its first vertex (exact for convex
/// polygons, which is what quad-dominant meshes hold).
template <class MeshType>
void buildFromPolygons(const PolygonMesh &p, MeshType &m) {
  std::size_t triangles = 0;
  for (const auto &f : p.faces) triangles += f.size() - 2;
  const std::size_t nv = p.coords.size() / 3;
  if (nv > 0) {
    auto vi = vcg::tri::Allocator<MeshType>::AddVertices(m, nv);
    for (std::size_t i = 0; i < nv; ++i, ++vi)
      for (int c = 0; c < 3; ++c) vi->P()[c] = p.coords[3 * i + c];
  }
  if (triangles == 0) return;
  auto fi = vcg::tri::Allocator<MeshType>::AddFaces(m, triangles);
  for (const auto &f : p.faces)
    for (std::size_t j = 1; j + 1 < f.size(); ++j, ++fi) {
      fi->V(0) = &m.vert[f[0]];
      fi->V(1) = &m.vert[f[j]];
      fi->V(2) = &m.vert[f[j + 1]];
    }
}

/// Checks the PLY header line by line before vcglib parses it: vcglib's
/// parser dereferences missing tokens (an "element" line without a count
/// crashes it). \throws std::runtime_error naming the bad line.
inline void checkPlyHeader(const std::string &path) {
  std::ifstream file(path, std::ios::binary);
  std::string line;
  const auto tokens = [](const std::string &l) {
    std::vector<std::string> out;
    std::size_t i = 0;
    while (i < l.size()) {
      while (i < l.size() && std::strchr(" \t\r\n", l[i])) ++i;
      const std::size_t start = i;
      while (i < l.size() && !std::strchr(" \t\r\n", l[i])) ++i;
      if (i > start) out.push_back(l.substr(start, i - start));
    }
    return out;
  };
  const auto isCount = [](const std::string &t) {
    return !t.empty() && t.size() < 12 &&
           std::all_of(t.begin(), t.end(), [](unsigned char c) { return std::isdigit(c); });
  };
  constexpr int kMaxHeaderLines = 10000;
  for (int n = 0; n < kMaxHeaderLines && std::getline(file, line); ++n) {
    const std::vector<std::string> t = tokens(line);
    const std::string where = "PLY header line " + std::to_string(n + 1);
    if (n == 0) {
      if (t.size() != 1 || t[0] != "ply") throw std::runtime_error("not a PLY file");
      continue;
    }
    if (t.empty()) throw std::runtime_error(where + " is empty");
    const std::string &key = t[0];
    if (key == "end_header") return;
    if (key == "comment" || key == "obj_info") continue;
    if (key == "format" && t.size() == 3) continue;
    if (key == "element" && t.size() == 3 && isCount(t[2])) continue;
    if (key == "property" && ((t.size() == 3 && t[1] != "list") ||
                              (t.size() == 5 && t[1] == "list")))
      continue;
    throw std::runtime_error(where + " is malformed");
  }
  throw std::runtime_error("PLY header has no end_header");
}

template <class MeshType>
void buildFromSoup(const StlSoup &soup, MeshType &m) {
  const std::size_t triangles = soup.coords.size() / 9;
  if (triangles == 0) return;
  auto vi = vcg::tri::Allocator<MeshType>::AddVertices(m, 3 * triangles);
  auto fi = vcg::tri::Allocator<MeshType>::AddFaces(m, triangles);
  for (std::size_t t = 0; t < triangles; ++t, ++fi)
    for (int k = 0; k < 3; ++k, ++vi) {
      for (int c = 0; c < 3; ++c) vi->P()[c] = soup.coords[9 * t + 3 * k + c];
      fi->V(k) = &*vi;
    }
}

}  // namespace detail

/// Loads `path` into `m` (cleared first). STL stores a triangle soup, so its
/// coincident vertices are merged; other formats are taken as they are.
/// Polygons are triangulated: as fans in OFF and OBJ, by vcglib in PLY.
/// Malformed files (truncated, garbage, indices out of range, empty) throw.
/// \throws std::runtime_error with a one-line message.
template <class MeshType>
void loadMesh(const std::string &path, MeshType &m) {
  const std::string ext = lowerExtension(path);
  if (!isSupportedExtension(ext))
    throw std::runtime_error(path + ": unsupported format (use .ply, .off, .obj or .stl)");
  std::ifstream probe(path, std::ios::binary | std::ios::ate);
  if (!probe.good()) throw std::runtime_error(path + ": cannot open file");
  if (probe.tellg() <= 0) throw std::runtime_error(path + ": cannot read mesh (empty file)");
  probe.close();
  m.Clear();
  // STL, OFF and OBJ are read by the strict readers above (vcglib's importers
  // accept out-of-range indices, drop faces silently or read past the end of
  // malformed files); PLY by vcglib, whose PLY importer checks indices and length.
  try {
    if (ext == "stl") {
      detail::buildFromSoup(detail::readStl(path), m);
      vcg::tri::Clean<MeshType>::RemoveDuplicateVertex(m, false);
    } else if (ext == "off" || ext == "obj") {
      std::ifstream file(path, std::ios::binary);
      const std::string text((std::istreambuf_iterator<char>(file)), {});
      detail::buildFromPolygons(ext == "off" ? detail::parseOff(text) : detail::parseObj(text), m);
    } else {
      detail::checkPlyHeader(path);
      int mask = 0;
      using Importer = vcg::tri::io::Importer<MeshType>;
      const int err = Importer::Open(m, path.c_str(), mask);
      if (err != 0 && Importer::ErrorCritical(err))
        throw std::runtime_error(Importer::ErrorMsg(err));
    }
  } catch (const std::exception &e) {  // also bad_alloc / length_error from absurd counts
    m.Clear();
    std::string why = e.what();
    std::replace(why.begin(), why.end(), '\n', ' ');
    throw std::runtime_error(path + ": cannot read mesh (" + why + ")");
  }
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
