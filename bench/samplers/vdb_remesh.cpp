// vdb-remesh IN OUT --voxel-fraction F: the voxel remesher users meet in Blender and Houdini.
// The input mesh becomes an OpenVDB narrow-band level set (tools::meshToLevelSet, voxel size
// = F x the input's bounding-box diagonal), which tools::volumeToMesh turns back into a surface
// at iso-value 0 with adaptivity 0 (one vertex per cell, quads), quads split into triangles.
// It cuts every sharp edge into a chamfer, like marching cubes: one of the quality benchmark's
// sampler families (issue 19). Writes binary PLY.
#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <algorithm>
#include <fstream>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

#include "edge_sharpener/util/mesh_types.h"
#include "mesh_io.h"

namespace {

struct TriangleMesh {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
};

TriangleMesh readTriangles(const std::string& path, double& diagonal) {
  edge_sharpener::Mesh m;
  edge_sharpener::io::loadMesh(path, m);
  vcg::tri::UpdateBounding<edge_sharpener::Mesh>::Box(m);
  diagonal = m.bbox.Diag();
  TriangleMesh out;
  out.points.reserve(m.vert.size());
  for (const auto& v : m.vert) out.points.emplace_back(v.cP().X(), v.cP().Y(), v.cP().Z());
  for (const auto& f : m.face) {
    if (f.IsD()) continue;
    out.triangles.emplace_back(static_cast<unsigned>(vcg::tri::Index(m, f.cV(0))),
                               static_cast<unsigned>(vcg::tri::Index(m, f.cV(1))),
                               static_cast<unsigned>(vcg::tri::Index(m, f.cV(2))));
  }
  return out;
}

/// Six times the signed volume the triangles enclose: positive when they face outwards.
double signedVolume6(const TriangleMesh& m) {
  double sum = 0;
  for (const auto& t : m.triangles) {
    const openvdb::Vec3d a(m.points[t[0]]), b(m.points[t[1]]), c(m.points[t[2]]);
    sum += a.dot(b.cross(c));
  }
  return sum;
}

/// (boundary edges, edges with more than two faces): a closed 2-manifold has neither, and the
/// sharpener refuses a mesh that has any.
std::pair<std::size_t, std::size_t> edgeCounts(const TriangleMesh& m) {
  std::vector<std::pair<unsigned, unsigned>> edges;
  edges.reserve(3 * m.triangles.size());
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) {
      const unsigned a = t[i], b = t[(i + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  std::size_t boundary = 0, nonManifold = 0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) ++boundary;
    if (j - i > 2) ++nonManifold;
    i = j;
  }
  return {boundary, nonManifold};
}

void writeBinaryPly(const std::string& path, const TriangleMesh& m) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(path + ": cannot write file");
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << m.points.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
      << m.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& p : m.points) out.write(reinterpret_cast<const char*>(p.asPointer()), 12);
  for (const auto& t : m.triangles) {
    const unsigned char three = 3;
    const int idx[3] = {static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])};
    out.write(reinterpret_cast<const char*>(&three), 1);
    out.write(reinterpret_cast<const char*>(idx), 12);
  }
  if (!out) throw std::runtime_error(path + ": cannot write file");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5 || std::string(argv[3]) != "--voxel-fraction") {
    std::fprintf(stderr,
                 "usage: vdb-remesh IN OUT.ply --voxel-fraction F\n"
                 "  OpenVDB meshToLevelSet + volumeToMesh (adaptivity 0, quads triangulated),\n"
                 "  voxel size = F x the input's bounding-box diagonal.\n");
    return 2;
  }
  try {
    const double fraction = std::atof(argv[4]);
    if (!(fraction > 0 && fraction < 1)) throw std::runtime_error("--voxel-fraction must be in (0, 1)");
    openvdb::initialize();
    double diagonal = 0;
    const TriangleMesh input = readTriangles(argv[1], diagonal);
    if (!(diagonal > 0) || input.triangles.empty()) throw std::runtime_error("empty input mesh");
    const double voxel = fraction * diagonal;
    auto transform = openvdb::math::Transform::createLinearTransform(voxel);
    // World-space points: meshToLevelSet converts them to index space with the transform.
    const auto grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(
        *transform, input.points, input.triangles, /*halfWidth=*/3.0f);

    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(*grid, points, triangles, quads, /*isovalue=*/0.0,
                                 /*adaptivity=*/0.0);
    TriangleMesh out;
    out.points = std::move(points);
    out.triangles = std::move(triangles);
    for (const auto& q : quads) {
      out.triangles.emplace_back(q[0], q[1], q[2]);
      out.triangles.emplace_back(q[0], q[2], q[3]);
    }
    if (out.triangles.empty()) throw std::runtime_error("volumeToMesh made no faces");
    // OpenVDB winds its faces the other way round from the input's (Houdini's convention).
    if (signedVolume6(out) < 0)
      for (auto& t : out.triangles) std::swap(t[1], t[2]);
    writeBinaryPly(argv[2], out);
    const auto [boundary, nonManifold] = edgeCounts(out);
    std::printf(
        "{\"voxel\": %.9g, \"vertices\": %zu, \"faces\": %zu, \"quads\": %zu, "
        "\"boundary_edges\": %zu, \"non_manifold_edges\": %zu, \"closed_manifold\": %s}\n",
        voxel, out.points.size(), out.triangles.size(), quads.size(), boundary, nonManifold,
        boundary == 0 && nonManifold == 0 ? "true" : "false");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vdb-remesh: %s\n", e.what());
    return 1;
  }
  return 0;
}
