// Mesh reading and writing for the command-line programs (PLY, OFF, OBJ, STL),
// with one-line error messages: our own strict readers, vcglib's exporters.
#pragma once

// clang-format off
#include <cstring>  // first: vcglib's wrap/callback.h uses strcpy without including it
// clang-format on

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/export.h>
#include <wrap/io_trimesh/import.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
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
  std::vector<float> coords;          // 3 per vertex
  std::vector<unsigned char> colors;  // RGBA, 4 per vertex; empty: the file has none
  std::vector<long> index;            // the faces' vertex indices, 0-based, validated
  std::vector<std::size_t>
      offset;  // face f is index[offset[f], offset[f + 1]); back() = index.size()
  std::size_t faceCount() const { return offset.empty() ? 0 : offset.size() - 1; }
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

/// A colour channel read from a file as a byte: a float in [0, 1] scaled by
/// 255, an integer taken as it is; rounded and clamped to [0, 255], a
/// non-finite value read as 0.
inline unsigned char colourByte(double value, bool isFloat) {
  const double scaled = value * (isFloat ? 255.0 : 1.0);
  return static_cast<unsigned char>(
      std::isfinite(scaled) ? std::clamp(std::round(scaled), 0.0, 255.0) : 0.0);
}

/// A colour channel of a text format (colourByte): a float when written with
/// a point or an exponent. False when `token` is no number.
inline bool readColourChannel(const std::string &token, unsigned char &byte) {
  float value;
  if (!readStlNumber(token, value)) return false;
  byte = colourByte(value, token.find_first_of(".eE") != std::string::npos);
  return true;
}

inline bool parseLong(const std::string &token, long &value) {
  if (token.empty()) return false;
  char *end = nullptr;
  errno = 0;
  value = std::strtol(token.c_str(), &end, 10);
  return errno == 0 && end == token.c_str() + token.size();
}

/// ASCII OFF (header OFF, COFF, NOFF, CNOFF, STOFF...: per-vertex colours of a
/// C header are read, 3 or 4 channels after x y z and the normal of an N
/// header; other per-vertex extras and per-face colours after the indices are
/// ignored). Binary and 4D/nD OFF are refused.
inline PolygonMesh parseOff(const std::string &text) {
  auto fail = [](const std::string &why) { throw std::runtime_error("malformed OFF: " + why); };
  const std::vector<std::string> lines = contentLines(text);
  std::size_t at = 0;
  if (at == lines.size()) fail("no header");
  std::istringstream header(lines[0]);
  std::string first;
  header >> first;
  bool coloured = false, normals = false, texCoords = false;
  if (first.size() >= 3 && first.compare(first.size() - 3, 3, "OFF") == 0) {
    const std::string prefix = first.substr(0, first.size() - 3);
    coloured = prefix.find('C') != std::string::npos;
    normals = prefix.find('N') != std::string::npos;
    texCoords = prefix.find("ST") != std::string::npos;
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
  if (coloured) mesh.colors.assign(4 * std::size_t(nv), 255);
  for (long i = 0; i < nv; ++i, ++at) {
    std::istringstream in(lines[at]);
    std::string c[3];
    for (std::string &ci : c) {
      float value;
      if (!(in >> ci) || !readStlNumber(ci, value)) fail("bad vertex line " + std::to_string(i));
      mesh.coords.push_back(value);
    }
    if (!coloured) continue;
    std::vector<std::string> rest;
    for (std::string tk; in >> tk;) rest.push_back(tk);
    const std::size_t skip = normals ? 3 : 0, channels = rest.size() - skip - (texCoords ? 2 : 0);
    if (rest.size() < skip + (texCoords ? 2 : 0) + 3 || channels > 4)
      fail("vertex line " + std::to_string(i) + " has no colour");
    for (std::size_t k = 0; k < channels; ++k)
      if (!readColourChannel(rest[skip + k], mesh.colors[4 * std::size_t(i) + k]))
        fail("bad colour on vertex line " + std::to_string(i));
  }
  for (long i = 0; i < nf; ++i, ++at) {
    std::istringstream in(lines[at]);
    std::string tk;
    long k;
    if (!(in >> tk) || !parseLong(tk, k) || k < 0 || k > 1000000)
      fail("bad face line " + std::to_string(i));
    mesh.offset.push_back(mesh.index.size());
    for (long j = 0; j < k; ++j) {
      long index;
      if (!(in >> tk) || !parseLong(tk, index)) fail("face " + std::to_string(i) + " is short");
      if (index < 0 || index >= nv)
        fail("face " + std::to_string(i) + " has vertex index " + std::to_string(index) +
             " out of range [0, " + std::to_string(nv) + ")");
      mesh.index.push_back(index);
    }
    if (k < 3) fail("face " + std::to_string(i) + " has fewer than 3 vertices");
  }
  mesh.offset.push_back(mesh.index.size());
  return mesh;
}

/// OBJ: "v x y z [...]" and "f a b c ..." (a = v, v/t, v//n or v/t/n; negative
/// = relative to the last vertex); "v x y z r g b" gives the vertex a colour
/// (the common extension; vertices without one are white); other statements
/// (vt, vn, g, o, s, usemtl, mtllib, l, ...) are ignored. An index out of
/// range is an error.
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
      std::string rgb[3], more;
      unsigned char byte[3];
      if (in >> rgb[0] >> rgb[1] >> rgb[2] && !(in >> more) && readColourChannel(rgb[0], byte[0]) &&
          readColourChannel(rgb[1], byte[1]) && readColourChannel(rgb[2], byte[2])) {
        const std::size_t v = mesh.coords.size() / 3 - 1;
        if (mesh.colors.empty()) mesh.colors.assign(4 * v, 255);  // the vertices before: white
        mesh.colors.insert(mesh.colors.end(), {byte[0], byte[1], byte[2], 255});
      } else if (!mesh.colors.empty()) {
        mesh.colors.insert(mesh.colors.end(), {255, 255, 255, 255});
      }
    } else if (kw == "f") {
      const std::size_t first = mesh.index.size();
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
        mesh.index.push_back(index);
      }
      if (mesh.index.size() - first < 3) fail("face with fewer than 3 vertices");
      mesh.offset.push_back(first);
    } else {
      static const char *const kIgnored[] = {
          "vt",     "vn",     "vp",  "l",    "p",     "g",    "o",    "s",   "mg",   "usemtl",
          "mtllib", "cstype", "deg", "curv", "curv2", "surf", "parm", "end", "trim", "hole"};
      if (std::find(std::begin(kIgnored), std::end(kIgnored), kw) == std::end(kIgnored))
        fail("unknown statement '" + kw.substr(0, 20) + "' on content line " +
             std::to_string(lineNo));
    }
  }
  mesh.offset.push_back(mesh.index.size());
  return mesh;
}

/// Triangulates each polygon as a fan from its first vertex (exact for convex
/// polygons, which is what quad-dominant meshes hold).
template <class MeshType>
void buildFromPolygons(const PolygonMesh &p, MeshType &m) {
  std::size_t triangles = 0;
  for (std::size_t f = 0; f < p.faceCount(); ++f) triangles += p.offset[f + 1] - p.offset[f] - 2;
  const std::size_t nv = p.coords.size() / 3;
  if (nv > 0) {
    auto vi = vcg::tri::Allocator<MeshType>::AddVertices(m, nv);
    for (std::size_t i = 0; i < nv; ++i, ++vi) {
      for (int c = 0; c < 3; ++c) vi->P()[c] = p.coords[3 * i + c];
      if (!p.colors.empty())
        vi->C() = vcg::Color4b(p.colors[4 * i], p.colors[4 * i + 1], p.colors[4 * i + 2],
                               p.colors[4 * i + 3]);
    }
  }
  if (triangles == 0) return;
  auto fi = vcg::tri::Allocator<MeshType>::AddFaces(m, triangles);
  for (std::size_t f = 0; f < p.faceCount(); ++f) {
    const long *v = p.index.data() + p.offset[f];
    const std::size_t n = p.offset[f + 1] - p.offset[f];
    for (std::size_t j = 1; j + 1 < n; ++j, ++fi) {
      fi->V(0) = &m.vert[v[0]];
      fi->V(1) = &m.vert[v[j]];
      fi->V(2) = &m.vert[v[j + 1]];
    }
  }
}

/// One property of a PLY element: a scalar, or a list (count type + item type).
struct PlyProperty {
  std::string name;
  int type = 0;  ///< byte size of the value (list items); 0: unknown
  bool isFloat = false, isSigned = false;
  bool list = false;
  int countType = 0;  ///< byte size of the list count
  bool countSigned = false;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  enum Format { Ascii, BinaryLittle, BinaryBig } format = Ascii;
  std::vector<PlyElement> elements;
  std::size_t bodyStart = 0;  ///< byte offset of the first byte after "end_header\n"
};

/// Size/kind of a PLY scalar type name (both spellings: "uchar" and "uint8").
inline bool plyScalarType(const std::string &t, int &size, bool &isFloat, bool &isSigned) {
  struct Kind {
    const char *a, *b;
    int size;
    bool isFloat, isSigned;
  };
  static const Kind kKinds[] = {
      {"char", "int8", 1, false, true},    {"uchar", "uint8", 1, false, false},
      {"short", "int16", 2, false, true},  {"ushort", "uint16", 2, false, false},
      {"int", "int32", 4, false, true},    {"uint", "uint32", 4, false, false},
      {"float", "float32", 4, true, true}, {"double", "float64", 8, true, true}};
  for (const Kind &k : kKinds)
    if (t == k.a || t == k.b) {
      size = k.size, isFloat = k.isFloat, isSigned = k.isSigned;
      return true;
    }
  return false;
}

/// Parses a PLY header (strictly: every line must be well-formed, every type
/// known). \throws std::runtime_error naming the bad line.
inline PlyHeader parsePlyHeader(const std::string &bytes) {
  const auto tokens = [](const std::string &l) {
    std::vector<std::string> out;
    std::size_t i = 0;
    while (i < l.size()) {
      while (i < l.size() && std::strchr(" \t\r", l[i])) ++i;
      const std::size_t start = i;
      while (i < l.size() && !std::strchr(" \t\r", l[i])) ++i;
      if (i > start) out.push_back(l.substr(start, i - start));
    }
    return out;
  };
  const auto isCount = [](const std::string &t) {
    return !t.empty() && t.size() < 12 &&
           std::all_of(t.begin(), t.end(), [](unsigned char c) { return std::isdigit(c); });
  };
  PlyHeader h;
  bool haveFormat = false;
  std::size_t at = 0;
  constexpr int kMaxHeaderLines = 10000;
  for (int n = 0; n < kMaxHeaderLines && at < bytes.size(); ++n) {
    std::size_t eol = bytes.find('\n', at);
    if (eol == std::string::npos) break;
    const std::string line = bytes.substr(at, eol - at);
    at = eol + 1;
    const std::vector<std::string> t = tokens(line);
    const std::string where = "PLY header line " + std::to_string(n + 1);
    if (n == 0) {
      if (t.size() != 1 || t[0] != "ply") throw std::runtime_error("not a PLY file");
      continue;
    }
    if (t.empty()) throw std::runtime_error(where + " is empty");
    const std::string &key = t[0];
    if (key == "end_header") {
      if (t.size() != 1) throw std::runtime_error(where + " is malformed");
      if (!haveFormat) throw std::runtime_error("PLY header has no format line");
      h.bodyStart = at;
      return h;
    }
    if (key == "comment" || key == "obj_info") continue;
    if (key == "format" && t.size() == 3 && !haveFormat) {
      if (t[1] == "ascii")
        h.format = PlyHeader::Ascii;
      else if (t[1] == "binary_little_endian")
        h.format = PlyHeader::BinaryLittle;
      else if (t[1] == "binary_big_endian")
        h.format = PlyHeader::BinaryBig;
      else
        throw std::runtime_error(where + ": unknown format '" + t[1].substr(0, 20) + "'");
      haveFormat = true;
      continue;
    }
    if (key == "element" && t.size() == 3 && isCount(t[2])) {
      h.elements.push_back({t[1], std::stoull(t[2]), {}});
      continue;
    }
    if (key == "property" && !h.elements.empty()) {
      PlyProperty p;
      bool ok = false;
      if (t.size() == 3 && t[1] != "list") {
        p.name = t[2];
        ok = plyScalarType(t[1], p.type, p.isFloat, p.isSigned);
      } else if (t.size() == 5 && t[1] == "list") {
        p.name = t[4];
        p.list = true;
        bool countFloat = false;
        ok = plyScalarType(t[2], p.countType, countFloat, p.countSigned) && !countFloat &&
             plyScalarType(t[3], p.type, p.isFloat, p.isSigned);
      }
      if (!ok) throw std::runtime_error(where + ": bad property");
      h.elements.back().properties.push_back(p);
      continue;
    }
    throw std::runtime_error(where + " is malformed");
  }
  throw std::runtime_error("PLY header has no end_header");
}

/// Reads the values of a PLY body one at a time, ASCII or binary, never past
/// its end. \throws std::runtime_error on a short or malformed body.
class PlyBodyReader {
 public:
  PlyBodyReader(const std::string &bytes, const PlyHeader &h)
      : p_(bytes.data() + h.bodyStart), end_(bytes.data() + bytes.size()), format_(h.format) {}

  std::size_t remaining() const { return std::size_t(end_ - p_); }
  bool ascii() const { return format_ == PlyHeader::Ascii; }

  /// The next value of the given type, as a double (exact for every integer type).
  double read(int size, bool isFloat, bool isSigned) {
    if (ascii()) return readToken();
    if (remaining() < std::size_t(size))
      throw std::runtime_error("malformed PLY: the file is truncated");
    unsigned char b[8];
    std::memcpy(b, p_, size);
    p_ += size;
    if (format_ == PlyHeader::BinaryBig) std::reverse(b, b + size);
    if (isFloat) {
      if (size == 4) {
        float f;
        std::memcpy(&f, b, 4);
        return f;
      }
      double d;
      std::memcpy(&d, b, 8);
      return d;
    }
    std::uint64_t u = 0;
    for (int i = size - 1; i >= 0; --i) u = (u << 8) | b[i];  // little endian after the swap
    if (isSigned && size < 8 && (u >> (8 * size - 1)) & 1)
      return double(std::int64_t(u) - (std::int64_t(1) << (8 * size)));
    return double(u);
  }

  /// An integer value (list count or index): non-integral ASCII values are an error.
  long readInteger(int size, bool isSigned) {
    const double v = read(size, false, isSigned);
    if (!(v == std::floor(v)) || std::fabs(v) > 4e18)
      throw std::runtime_error("malformed PLY: expected an integer");
    return long(v);
  }

  void skip(const PlyProperty &p) {
    if (!p.list) {
      read(p.type, p.isFloat, p.isSigned);
      return;
    }
    const long n = readInteger(p.countType, p.countSigned);
    if (n < 0) throw std::runtime_error("malformed PLY: negative list length");
    if (!ascii()) {
      if (std::uint64_t(n) * std::uint64_t(p.type) > remaining())
        throw std::runtime_error("malformed PLY: the file is truncated");
      p_ += std::size_t(n) * std::size_t(p.type);
      return;
    }
    for (long i = 0; i < n; ++i) read(p.type, p.isFloat, p.isSigned);
  }

 private:
  double readToken() {
    while (p_ < end_ && std::isspace(static_cast<unsigned char>(*p_))) ++p_;
    if (p_ == end_) throw std::runtime_error("malformed PLY: the file is truncated");
    const char *start = p_;
    while (p_ < end_ && !std::isspace(static_cast<unsigned char>(*p_))) ++p_;
    const std::string token(start, std::min<std::size_t>(p_ - start, 64));
    char *stop = nullptr;
    const double v = std::strtod(token.c_str(), &stop);
    if (token.empty() || stop != token.c_str() + token.size() || std::size_t(p_ - start) > 64)
      throw std::runtime_error("malformed PLY: bad number '" + token.substr(0, 20) + "'");
    return v;
  }

  const char *p_, *end_;
  PlyHeader::Format format_;
};

/// Reads a PLY file (ASCII, binary little or big endian) with our own strict
/// parser: vertex x, y, z and, where the file has them, red, green, blue
/// (alpha) as bytes or as floats in [0, 1]; faces from "face" (list vertex_indices or
/// vertex_index) and "tristrips" (list vertex_indices, -1 restarts a strip);
/// every other element and property is skipped. Every face index is checked
/// against the vertex count, polygons need 3 or more vertices.
/// (vcglib's PLY importer reads freed memory on a polygon with an index out
/// of range, and crashes on malformed headers.)
inline PolygonMesh readPly(const std::string &bytes) {
  auto fail = [](const std::string &why) { throw std::runtime_error("malformed PLY: " + why); };
  const PlyHeader h = parsePlyHeader(bytes);
  PlyBodyReader in(bytes, h);
  // Smallest byte size of one item of an element: a cap on how many fit in the file.
  const auto minimalSize = [&](const PlyElement &e) {
    std::uint64_t size = 0;
    for (const PlyProperty &p : e.properties)
      size += in.ascii() ? 2 : (p.list ? p.countType : p.type);
    return size;
  };
  PolygonMesh mesh;
  bool haveVertices = false;
  long nv = -1;
  std::vector<std::uint64_t> source;  // per face: its item in the face/tristrips element
  for (const PlyElement &e : h.elements) {
    if (e.properties.empty()) continue;  // nothing to read, whatever its count
    // ASCII: a value takes at least 2 bytes (digit + separator), except the last one.
    const std::uint64_t room = in.ascii() ? in.remaining() + 1 : in.remaining();
    const std::uint64_t minSize = minimalSize(e);
    if (e.count > room / minSize)
      fail("element '" + e.name.substr(0, 20) + "' declares " + std::to_string(e.count) +
           " items, the file has room for " + std::to_string(room / minSize));
    if (e.name == "vertex") {
      if (haveVertices) fail("two vertex elements");
      haveVertices = true;
      // Each property's role, found once: 0-2 the coordinate x, y, z; 3-6 the
      // colour channel red, green, blue, alpha (bytes or floats in [0, 1]); -1 skipped.
      static const char *const kRoles[7] = {"x", "y", "z", "red", "green", "blue", "alpha"};
      std::vector<int> role(e.properties.size(), -1);
      bool has[7] = {};
      for (std::size_t i = 0; i < e.properties.size(); ++i)
        for (int r = 0; r < 7; ++r)
          if (!e.properties[i].list && e.properties[i].name == kRoles[r])
            role[i] = r, has[r] = true;
      if (e.count > 0 && !(has[0] && has[1] && has[2])) fail("vertex element without x, y, z");
      if (e.count >= 0xffffffffu) fail("too many vertices");
      const bool coloured = has[3] && has[4] && has[5];
      if (!coloured)
        for (int &r : role) r = r >= 3 ? -1 : r;
      nv = long(e.count);
      mesh.coords.resize(3 * e.count);
      if (coloured) mesh.colors.assign(4 * e.count, 255);
      for (std::uint64_t v = 0; v < e.count; ++v)
        for (std::size_t i = 0; i < e.properties.size(); ++i) {
          const PlyProperty &p = e.properties[i];
          if (role[i] < 0)
            in.skip(p);
          else if (role[i] < 3)
            mesh.coords[3 * v + role[i]] = float(in.read(p.type, p.isFloat, p.isSigned));
          else
            mesh.colors[4 * v + role[i] - 3] =
                colourByte(in.read(p.type, p.isFloat, p.isSigned), p.isFloat);
        }
      continue;
    }
    const bool isFace = e.name == "face", isStrip = e.name == "tristrips";
    int list = -1;
    for (std::size_t i = 0; i < e.properties.size(); ++i)
      if (e.properties[i].list && (e.properties[i].name == "vertex_indices" ||
                                   (isFace && e.properties[i].name == "vertex_index")))
        list = int(i);
    if ((isFace || isStrip) && e.count > 0 && list < 0)
      fail(e.name + " element without a vertex_indices list");
    if ((isFace || isStrip) && e.properties[list < 0 ? 0 : list].isFloat && e.count > 0)
      fail("vertex indices must be integers");
    std::vector<long> strip;
    for (std::uint64_t f = 0; f < e.count; ++f)
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        const PlyProperty &p = e.properties[i];
        if (!(isFace || isStrip) || int(i) != list) {
          in.skip(p);
          continue;
        }
        const long n = in.readInteger(p.countType, p.countSigned);
        if (n < 0) fail(e.name + " " + std::to_string(f) + " has a negative list length");
        if (std::uint64_t(n) >
            (in.ascii() ? (in.remaining() + 1) / 2 : in.remaining() / std::uint64_t(p.type)))
          fail("the file is truncated (" + e.name + " " + std::to_string(f) + " declares " +
               std::to_string(n) + " vertices)");
        if (isFace) {
          if (n < 3) fail("face " + std::to_string(f) + " has fewer than 3 vertices");
          source.push_back(f);
          mesh.offset.push_back(mesh.index.size());
          for (long j = 0; j < n; ++j) mesh.index.push_back(in.readInteger(p.type, p.isSigned));
          continue;
        }
        strip.clear();
        for (long j = 0; j < n; ++j) strip.push_back(in.readInteger(p.type, p.isSigned));
        // Triangles (s[k], s[k+1], s[k+2]), every other one flipped; -1 restarts.
        for (std::size_t begin = 0; begin < strip.size();) {
          std::size_t stop = begin;
          while (stop < strip.size() && strip[stop] != -1) ++stop;
          for (std::size_t k = begin; k + 2 < stop; ++k) {
            long a = strip[k], b = strip[k + 1];
            const long c = strip[k + 2];
            if ((k - begin) % 2) std::swap(a, b);
            if (a == b || b == c || a == c) continue;  // strip-joining degenerate triangle
            source.push_back(f);
            mesh.offset.push_back(mesh.index.size());
            for (long x : {a, b, c}) mesh.index.push_back(x);
          }
          begin = stop + 1;
        }
      }
  }
  mesh.offset.push_back(mesh.index.size());
  for (std::size_t f = 0; f + 1 < mesh.offset.size(); ++f)
    for (std::size_t j = mesh.offset[f]; j < mesh.offset[f + 1]; ++j)
      if (mesh.index[j] < 0 || mesh.index[j] >= nv)
        fail("face " + std::to_string(source[f]) + " has vertex index " +
             std::to_string(mesh.index[j]) + " out of range [0, " + std::to_string(nv) + ")");
  return mesh;
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
/// Polygons are triangulated as fans from their first vertex (all formats).
/// Malformed files (truncated, garbage, indices out of range, empty) throw.
/// \return what was read beside positions and faces, as a vcg::tri::io::Mask
///         combination: IOM_VERTCOLOR for vertex colours (PLY, COFF, OBJ's
///         "v x y z r g b"), else 0 (the same mask makes saveMesh write them).
/// \throws std::runtime_error with a one-line message.
template <class MeshType>
int loadMesh(const std::string &path, MeshType &m) {
  const std::string ext = lowerExtension(path);
  if (!isSupportedExtension(ext))
    throw std::runtime_error(path + ": unsupported format (use .ply, .off, .obj or .stl)");
  std::ifstream probe(path, std::ios::binary | std::ios::ate);
  if (!probe.good()) throw std::runtime_error(path + ": cannot open file");
  if (probe.tellg() <= 0) throw std::runtime_error(path + ": cannot read mesh (empty file)");
  probe.close();
  m.Clear();
  int read = 0;
  // Every format is read by the strict readers above: vcglib's importers
  // accept out-of-range indices, drop faces silently, read past the end of
  // malformed files, or (PLY) read freed memory on a bad polygon index.
  try {
    if (ext == "stl") {
      detail::buildFromSoup(detail::readStl(path), m);
      vcg::tri::Clean<MeshType>::RemoveDuplicateVertex(m, false);
    } else {
      std::ifstream file(path, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(file)), {});
      const detail::PolygonMesh polygons = ext == "off"   ? detail::parseOff(bytes)
                                           : ext == "obj" ? detail::parseObj(bytes)
                                                          : detail::readPly(bytes);
      if (!polygons.colors.empty()) read |= vcg::tri::io::Mask::IOM_VERTCOLOR;
      detail::buildFromPolygons(polygons, m);
    }
  } catch (const std::exception &e) {  // also bad_alloc / length_error from absurd counts
    m.Clear();
    std::string why = e.what();
    std::replace(why.begin(), why.end(), '\n', ' ');
    throw std::runtime_error(path + ": cannot read mesh (" + why + ")");
  }
  vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
  return read;
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
