// Helper of the MeshLab plugin tests (tests/plugin/*.sh): makes small input
// meshes and inspects/compares the PLY files that meshlabserver and the CLI
// write. Exit status 0 = OK, 1 = check failed, 2 = usage or I/O error.
//
//   plugin_test_tool make-lblock OUT.ply       sharp L-shaped block, rotated off the axes
//   plugin_test_tool make-pointcloud OUT.ply   vertices only
//   plugin_test_tool make-nonmanifold OUT.ply  three triangles on one edge
//   plugin_test_tool make-misoriented OUT.ply  a tetrahedron with one face flipped
//   plugin_test_tool paint-gradient IN OUT      IN with vertex colours varying along x and y
//   plugin_test_tool info IN.ply               counts, colours, selection (key=value lines)
//   plugin_test_tool compare A.ply B.ply [--rel-tol T] [--colors] [--vertex-colors] [--selection]
//       same vertex and face count, same positions within T x bbox diagonal (default
//       1e-5), same faces; with --colors also the same per-face colours, with
//       --vertex-colors the same per-vertex colours, with --selection the same
//       selected faces (both files need the data asked for).
//   plugin_test_tool spot-faces IN.ply OUT.ply
//       IN has faces at non-manifold spots, and each comes out in OUT as it was (the same
//       vertex indices, bit-identical positions); OUT has no other face at a spot.
//   plugin_test_tool mark-faces IN.ply FACES.txt OUT.ply
//       IN with face quality 1 on the faces FACES.txt lists (0-based indices, one per line,
//       # comments), 0 elsewhere: MeshLab's Conditional Face Selection reads it as fq.
//   plugin_test_tool kept-vertices IN.ply OUT.ply FACES.txt
//       every vertex of the listed faces of IN has its position in OUT, bit for bit.
#include <edge_sharpener/util/mesh_types.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/color.h>
#include <vcg/complex/algorithms/update/flag.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/import_ply.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "../reliability/invariants.h"

using Mesh = edge_sharpener::Mesh;
using Coord = Mesh::CoordType;

namespace {

struct Loaded {
  Mesh m;
  int mask = 0;
};

bool load(const std::string &path, Loaded &out) {
  int err = vcg::tri::io::ImporterPLY<Mesh>::Open(out.m, path.c_str(), out.mask);
  if (err != 0 && vcg::tri::io::ImporterPLY<Mesh>::ErrorCritical(err)) {
    std::cerr << path << ": " << vcg::tri::io::ImporterPLY<Mesh>::ErrorMsg(err) << "\n";
    return false;
  }
  vcg::tri::UpdateBounding<Mesh>::Box(out.m);
  return true;
}

bool save(Mesh &m, const std::string &path) {
  if (vcg::tri::io::ExporterPLY<Mesh>::Save(m, path.c_str(), false) != 0) {
    std::cerr << "cannot write " << path << "\n";
    return false;
  }
  return true;
}

void fromArrays(Mesh &m, const std::vector<Coord> &pts,
                const std::vector<std::array<int, 3>> &tris) {
  auto vi = vcg::tri::Allocator<Mesh>::AddVertices(m, pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) vi[i].P() = pts[i];
  for (const auto &t : tris)
    vcg::tri::Allocator<Mesh>::AddFace(m, &m.vert[t[0]], &m.vert[t[1]], &m.vert[t[2]]);
}

/// Rotation off every axis, so that a marching-cubes grid cuts all its edges.
Coord rotate(Coord p) {
  auto rot = [](double a, double &x, double &y) {
    const double c = std::cos(a), s = std::sin(a), nx = c * x - s * y;
    y = s * x + c * y;
    x = nx;
  };
  double x = p[0], y = p[1], z = p[2];
  rot(0.37, x, y);  // about z
  rot(0.51, y, z);  // about x
  rot(0.23, z, x);  // about y
  return Coord(float(x), float(y), float(z));
}

/// L-shaped prism: 4 convex edges per cap, one concave edge, 3-edge corners.
int makeLBlock(const std::string &out) {
  const double l[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  std::vector<Coord> pts;
  for (int z = 0; z < 2; ++z)
    for (const auto &q : l)
      pts.push_back(rotate(Coord(float(0.5 * q[0] - 0.5), float(0.5 * q[1] - 0.5), 0.5f * z)));
  std::vector<std::array<int, 3>> tris;
  for (int i = 1; i < 5; ++i) {
    tris.push_back({0, i + 1, i});      // bottom (z = 0), facing -z
    tris.push_back({6, 6 + i, 7 + i});  // top, facing +z
  }
  for (int i = 0; i < 6; ++i) {
    const int j = (i + 1) % 6;
    tris.push_back({i, j, 6 + j});
    tris.push_back({i, 6 + j, 6 + i});
  }
  Mesh m;
  fromArrays(m, pts, tris);
  return save(m, out) ? 0 : 2;
}

int makePointCloud(const std::string &out) {
  std::vector<Coord> pts;
  for (int i = 0; i < 64; ++i)
    pts.push_back(Coord(float(i % 4), float((i / 4) % 4), float(i / 16)));
  Mesh m;
  fromArrays(m, pts, {});
  return save(m, out) ? 0 : 2;
}

int makeNonManifold(const std::string &out) {
  // A closed tetrahedron plus a fin on one of its edges: edge 0-1 has three faces.
  std::vector<Coord> pts{Coord(0, 0, 0), Coord(1, 0, 0), Coord(0, 1, 0), Coord(0, 0, 1),
                         Coord(0.5f, -1, 0.5f)};
  Mesh m;
  fromArrays(m, pts, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 1, 4}});
  return save(m, out) ? 0 : 2;
}

int makeMisoriented(const std::string &out) {
  std::vector<Coord> pts{Coord(0, 0, 0), Coord(1, 0, 0), Coord(0, 1, 0), Coord(0, 0, 1)};
  Mesh m;
  fromArrays(m, pts, {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  return save(m, out) ? 0 : 2;
}

/// Whether every face of `in` at a non-manifold spot comes out in `out` as it was.
int spotFaces(const std::string &inPath, const std::string &outPath) {
  Loaded in, out;
  if (!load(inPath, in) || !load(outPath, out)) return 2;
  const auto spots = es_reliability::facesAtNonManifoldSpots(in.m);
  if (spots.empty()) {
    std::cout << "FAIL: " << inPath << " has no non-manifold spot\n";
    return 1;
  }
  const auto outSpots = es_reliability::facesAtNonManifoldSpots(out.m);
  std::size_t changed = 0;
  for (const auto &t : spots) {
    bool same = outSpots.count(t) > 0;
    for (std::size_t v : t)
      same = same && v < out.m.vert.size() && out.m.vert[v].cP() == in.m.vert[v].cP();
    changed += !same;
  }
  if (changed > 0 || outSpots.size() != spots.size()) {
    std::cout << "FAIL: " << changed << " of " << spots.size()
              << " faces at spots changed; the output has " << outSpots.size() << "\n";
    return 1;
  }
  std::cout << "OK: " << spots.size() << " faces at non-manifold spots as they came\n";
  return 0;
}

/// The face indices a list file holds (mark-faces, kept-vertices); false when
/// it cannot be read or names no face of `m`.
bool readFaceList(const std::string &path, const Mesh &m, std::vector<std::size_t> &faces) {
  std::ifstream in(path);
  if (!in) {
    std::cerr << "cannot read " << path << "\n";
    return false;
  }
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t f = std::stoul(line);
    if (f >= m.face.size()) {
      std::cerr << path << ": face " << f << " out of range\n";
      return false;
    }
    faces.push_back(f);
  }
  return true;
}

int markFaces(const std::string &inPath, const std::string &listPath, const std::string &out) {
  Loaded in;
  std::vector<std::size_t> listed;
  if (!load(inPath, in) || !readFaceList(listPath, in.m, listed)) return 2;
  for (auto &f : in.m.face) f.Q() = 0;
  for (const std::size_t f : listed) in.m.face[f].Q() = 1;
  if (vcg::tri::io::ExporterPLY<Mesh>::Save(in.m, out.c_str(), vcg::tri::io::Mask::IOM_FACEQUALITY,
                                            true) != 0) {
    std::cerr << "cannot write " << out << "\n";
    return 2;
  }
  return 0;
}

int keptVertices(const std::string &inPath, const std::string &outPath,
                 const std::string &listPath) {
  Loaded in, out;
  std::vector<std::size_t> listed;
  if (!load(inPath, in) || !load(outPath, out) || !readFaceList(listPath, in.m, listed)) return 2;
  std::set<std::size_t> vertices;
  for (const std::size_t f : listed)
    for (int i = 0; i < 3; ++i) vertices.insert(vcg::tri::Index(in.m, in.m.face[f].cV(i)));
  std::size_t moved = 0;
  for (const std::size_t v : vertices)
    moved += v >= out.m.vert.size() || !(out.m.vert[v].cP() == in.m.vert[v].cP());
  if (listed.empty() || moved > 0) {
    std::cout << "FAIL: " << moved << " of the " << vertices.size() << " vertices of the "
              << listed.size() << " listed faces moved\n";
    return 1;
  }
  std::cout << "OK: the " << vertices.size() << " vertices of the " << listed.size()
            << " listed faces as they came\n";
  return 0;
}

/// IN with vertex colours that vary along x and y (blue 7, opaque): a
/// coloured scan's stand-in.
int paintGradient(const std::string &in, const std::string &out) {
  Loaded a;
  if (!load(in, a)) return 2;
  const Coord lo = a.m.bbox.min, size = a.m.bbox.max - a.m.bbox.min;
  for (auto &v : a.m.vert) {
    const Coord t = v.P() - lo;
    v.C() = vcg::Color4b(static_cast<unsigned char>(250 * t[0] / size[0]),
                         static_cast<unsigned char>(250 * t[1] / size[1]), 7, 255);
  }
  if (vcg::tri::io::ExporterPLY<Mesh>::Save(a.m, out.c_str(), vcg::tri::io::Mask::IOM_VERTCOLOR,
                                            false) != 0) {
    std::cerr << "cannot write " << out << "\n";
    return 2;
  }
  return 0;
}

int info(const std::string &path) {
  Loaded a;
  if (!load(path, a)) return 2;
  std::size_t selected = 0, white = 0;
  for (const auto &v : a.m.vert) white += v.cC() == vcg::Color4b(vcg::Color4b::White);
  std::set<unsigned> faceColours;
  for (const auto &f : a.m.face) {
    if (f.IsS()) ++selected;
    if (a.mask & vcg::tri::io::Mask::IOM_FACECOLOR)
      faceColours.insert(f.cC()[0] << 16 | f.cC()[1] << 8 | f.cC()[2]);
  }
  std::cout << "vertices=" << a.m.vn << "\nfaces=" << a.m.fn
            << "\nvertex_color=" << bool(a.mask & vcg::tri::io::Mask::IOM_VERTCOLOR)
            << "\nface_color=" << bool(a.mask & vcg::tri::io::Mask::IOM_FACECOLOR)
            << "\nface_flags=" << bool(a.mask & vcg::tri::io::Mask::IOM_FACEFLAGS)
            << "\nselected_faces=" << selected << "\nface_colors=" << faceColours.size()
            << "\nwhite_vertices=" << white << "\nbbox_diag=" << a.m.bbox.Diag() << "\n";
  return 0;
}

/// Index of each vertex of `a` in `b` (positions within tol), or an empty
/// vector when some vertex has no partner. Order-independent fallback for
/// when the two writers do not order vertices alike.
std::vector<int> matchVertices(const Mesh &a, const Mesh &b, double tol) {
  std::multimap<double, int> byX;
  for (int i = 0; i < int(b.vert.size()); ++i) byX.emplace(b.vert[i].P()[0], i);
  std::vector<int> map(a.vert.size(), -1);
  std::vector<bool> used(b.vert.size(), false);
  for (int i = 0; i < int(a.vert.size()); ++i) {
    const Coord p = a.vert[i].P();
    double best = tol;
    for (auto it = byX.lower_bound(p[0] - tol); it != byX.end() && it->first <= p[0] + tol; ++it) {
      const double d = vcg::Distance(p, b.vert[it->second].P());
      if (!used[it->second] && d <= best) best = d, map[i] = it->second;
    }
    if (map[i] < 0) return {};
    used[map[i]] = true;
  }
  return map;
}

using FaceKey = std::array<int, 3>;
FaceKey key(const Mesh &m, const Mesh::FaceType &f, const std::vector<int> &vmap) {
  FaceKey k;
  for (int j = 0; j < 3; ++j) {
    int vi = int(vcg::tri::Index(m, f.cV(j)));
    k[j] = vmap.empty() ? vi : vmap[vi];
  }
  std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());  // keeps orientation
  return k;
}

struct CompareWhat {
  bool vertexColours = false, selection = false;
};

int compare(const std::string &pa, const std::string &pb, double relTol, bool colours,
            CompareWhat what = {}) {
  Loaded a, b;
  if (!load(pa, a) || !load(pb, b)) return 2;
  std::cout << "A " << pa << ": " << a.m.vn << " vertices, " << a.m.fn << " faces\n"
            << "B " << pb << ": " << b.m.vn << " vertices, " << b.m.fn << " faces\n";
  if (a.m.vn != b.m.vn || a.m.fn != b.m.fn) {
    std::cout << "FAIL: different vertex or face count\n";
    return 1;
  }
  const double tol = relTol * std::max(double(a.m.bbox.Diag()), 1e-30);
  double maxDist = 0;
  for (std::size_t i = 0; i < a.m.vert.size(); ++i)
    maxDist = std::max(maxDist, double(vcg::Distance(a.m.vert[i].P(), b.m.vert[i].P())));
  std::vector<int> vmap;  // empty: identity
  if (maxDist > tol) {
    std::cout << "vertex order differs (max same-index distance " << maxDist
              << "); matching by position\n";
    vmap = matchVertices(a.m, b.m, tol);
    if (vmap.empty()) {
      std::cout << "FAIL: some vertex of A has no vertex of B within " << tol << "\n";
      return 1;
    }
    maxDist = 0;
    for (std::size_t i = 0; i < vmap.size(); ++i)
      maxDist = std::max(maxDist, double(vcg::Distance(a.m.vert[i].P(), b.m.vert[vmap[i]].P())));
  }
  std::map<FaceKey, const Mesh::FaceType *> facesB;
  for (const auto &f : b.m.face) facesB[key(b.m, f, {})] = &f;
  std::size_t missing = 0, colourDiff = 0, selectionDiff = 0, vertexColourDiff = 0;
  for (const auto &f : a.m.face) {
    auto it = facesB.find(key(a.m, f, vmap));
    if (it == facesB.end()) {
      ++missing;
      continue;
    }
    if (colours && it->second->cC() != f.cC()) ++colourDiff;
    if (what.selection && it->second->IsS() != f.IsS()) ++selectionDiff;
  }
  if (what.vertexColours)
    for (std::size_t i = 0; i < a.m.vert.size(); ++i)
      if (a.m.vert[i].cC() != b.m.vert[vmap.empty() ? i : std::size_t(vmap[i])].cC())
        ++vertexColourDiff;
  std::cout << "max vertex distance " << maxDist << " (tolerance " << tol
            << "), faces of A not in B " << missing;
  if (colours) std::cout << ", faces with different colour " << colourDiff;
  if (what.vertexColours) std::cout << ", vertices with different colour " << vertexColourDiff;
  if (what.selection) std::cout << ", faces selected in one only " << selectionDiff;
  std::cout << "\n";
  const int both = a.mask & b.mask;
  if (what.vertexColours && !(both & vcg::tri::io::Mask::IOM_VERTCOLOR)) {
    std::cout << "FAIL: --vertex-colors but a file has no vertex colour\n";
    return 1;
  }
  if (what.selection && !(both & vcg::tri::io::Mask::IOM_FACEFLAGS)) {
    std::cout << "FAIL: --selection but a file has no face flags\n";
    return 1;
  }
  if (selectionDiff || vertexColourDiff) {
    std::cout << "FAIL\n";
    return 1;
  }
  if (colours && !((a.mask & b.mask) & vcg::tri::io::Mask::IOM_FACECOLOR)) {
    std::cout << "FAIL: --colors but a file has no face colour\n";
    return 1;
  }
  if (missing || colourDiff) {
    std::cout << "FAIL\n";
    return 1;
  }
  std::cout << "OK: same mesh\n";
  return 0;
}

int usage() {
  std::cerr << "usage: plugin_test_tool make-lblock|make-pointcloud|make-nonmanifold|"
               "make-misoriented OUT\n"
               "       plugin_test_tool spot-faces IN OUT\n"
               "       plugin_test_tool mark-faces IN FACES.txt OUT\n"
               "       plugin_test_tool kept-vertices IN OUT FACES.txt\n"
               "       plugin_test_tool paint-gradient IN OUT\n"
               "       plugin_test_tool info IN\n"
               "       plugin_test_tool compare A B [--rel-tol T] [--colors] [--vertex-colors] "
               "[--selection]\n";
  return 2;
}

}  // namespace

int main(int argc, char **argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 2 && args[0] == "make-lblock") return makeLBlock(args[1]);
  if (args.size() == 2 && args[0] == "make-pointcloud") return makePointCloud(args[1]);
  if (args.size() == 2 && args[0] == "make-nonmanifold") return makeNonManifold(args[1]);
  if (args.size() == 2 && args[0] == "make-misoriented") return makeMisoriented(args[1]);
  if (args.size() == 3 && args[0] == "spot-faces") return spotFaces(args[1], args[2]);
  if (args.size() == 4 && args[0] == "mark-faces") return markFaces(args[1], args[2], args[3]);
  if (args.size() == 4 && args[0] == "kept-vertices")
    return keptVertices(args[1], args[2], args[3]);
  if (args.size() == 2 && args[0] == "info") return info(args[1]);
  if (args.size() == 3 && args[0] == "paint-gradient") return paintGradient(args[1], args[2]);
  if (args.size() >= 3 && args[0] == "compare") {
    double tol = 1e-5;
    bool colours = false;
    CompareWhat what;
    for (std::size_t i = 3; i < args.size(); ++i) {
      if (args[i] == "--rel-tol" && i + 1 < args.size())
        tol = std::atof(args[++i].c_str());
      else if (args[i] == "--colors")
        colours = true;
      else if (args[i] == "--vertex-colors")
        what.vertexColours = true;
      else if (args[i] == "--selection")
        what.selection = true;
      else
        return usage();
    }
    return compare(args[1], args[2], tol, colours, what);
  }
  return usage();
}
