// dual-contour SHAPE RES_PCT OUT.ply [--clamp] [--cutoff 0.1] [--double]
// Writes the dual-contouring mesh (exact Hermite data, test_meshes/dual_contouring.h) of a
// generated test shape, on the grid of its marching-cubes mesh at RES_PCT% of the bounding-box
// diagonal (the grid of generate-test-meshes' <shape>_mc<RES_PCT>.ply), as binary PLY.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

// vcglib's exporter relies on the mesh headers being included first.
#include "edge_sharpener/util/mesh_types.h"
#include "test_meshes/dual_contouring.h"
#include "test_meshes/shapes.h"
// (keep after the mesh headers)
#include <wrap/io_trimesh/export_ply.h>

namespace {

namespace shapes = edge_sharpener::test_meshes;

template <class M>
bool savePly(const shapes::TriangleList &triangles, const std::string &path) {
  M mesh;
  shapes::toVcgMesh(triangles, mesh);
  const int mask = vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_FACEINDEX;
  const int error = vcg::tri::io::ExporterPLY<M>::Save(mesh, path.c_str(), mask, /*binary=*/true);
  if (error != 0) {
    std::fprintf(stderr, "dual-contour: error: cannot write %s: %s\n", path.c_str(),
                 vcg::tri::io::ExporterPLY<M>::ErrorMsg(error));
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char **argv) {
  CLI::App app{
      "Writes the dual-contouring mesh (Ju et al. 2002) of a test shape from exact Hermite data, "
      "on the grid of its marching-cubes mesh, as binary PLY."};
  std::string shapeName, output;
  double percent = 0;
  shapes::DualContouringOptions options;
  bool doublePrecision = false;
  app.add_option("SHAPE", shapeName, "Test shape (as generate-test-meshes names them)")->required();
  app.add_option("RES_PCT", percent, "Cell size in % of the bounding-box diagonal (2, 1, 0.5)")
      ->required()
      ->check(CLI::PositiveNumber);
  app.add_option("OUT", output, "Output PLY file")->required();
  app.add_flag("--clamp", options.clampToCell, "Clamp every vertex into its cell");
  app.add_option("--cutoff", options.singularValueCutoff,
                 "Truncate singular values below this fraction of the largest")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_flag("--double", doublePrecision,
               "Write double-precision coordinates (default: float, like the other meshes)");
  CLI11_PARSE(app, argc, argv);

  try {
    const shapes::Shape &shape = shapes::shapeByName(shapeName);
    const double cellSize = shapes::cellSizeForDiagonalFraction(shape, percent / 100);
    const auto start = std::chrono::steady_clock::now();
    const shapes::DualContouringResult dc = shapes::dualContour(shape, cellSize, options);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double maxDistance = 0;
    for (const shapes::Point3d &p : dc.mesh.vertices)
      maxDistance = std::max(maxDistance, std::abs(shape.signedDistance(p)));
    int ranks[4] = {0, 0, 0, 0};
    for (int rank : dc.vertexRank) ++ranks[std::clamp(rank, 0, 3)];
    const bool saved = doublePrecision ? savePly<edge_sharpener::MeshD>(dc.mesh, output)
                                       : savePly<edge_sharpener::Mesh>(dc.mesh, output);
    if (!saved) return 1;
    std::printf(
        "%s: %zu vertices (%d face, %d edge, %d corner), %zu triangles, %zu crossing edges, "
        "%.2f s\n",
        output.c_str(), dc.mesh.vertices.size(), ranks[1], ranks[2], ranks[3],
        dc.mesh.triangles.size(), dc.crossingEdges, seconds);
    std::printf(
        "max |sdf| at the vertices %.3g (%.3g of the diagonal); %zu vertices outside their cell "
        "(at most %.3g cells%s); %zu normals with a refined step\n",
        maxDistance, maxDistance / shape.diagonal(), dc.verticesOutsideCell, dc.maxOutsideDistance,
        options.clampToCell ? ", clamped" : "", dc.refinedNormals);
  } catch (const std::exception &error) {
    std::fprintf(stderr, "dual-contour: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
