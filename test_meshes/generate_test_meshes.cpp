// generate-test-meshes OUTDIR [--cells 0.02,0.01] [--shapes cube,lblock] [--spots]
//                      [--bevel-faces]
// Writes <shape>_reference.ply (exact triangulation) and <shape>_mc<percent>.ply (marching
// cubes with cells of <percent>% of the bounding-box diagonal) as binary PLY; with --spots
// also <shape>_mc<percent>_spots.ply, the same with two non-manifold spots added
// (non_manifold_spots.h): a vertex near a chamfer and an edge on one; with --bevel-faces,
// for bevelled_block, <shape>_mc<percent>_bevel.txt, the indices of the faces on its wide
// designed bevel (designed_faces.h), one per line: what a user deselects before sharpening.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

// vcglib's exporter relies on the mesh headers being included first.
#include "edge_sharpener/util/mesh_types.h"
#include "test_meshes/designed_faces.h"
#include "test_meshes/non_manifold_spots.h"
#include "test_meshes/shapes.h"
// (keep after the mesh headers)
#include <wrap/io_trimesh/export_ply.h>

namespace {

using edge_sharpener::Mesh;
namespace shapes = edge_sharpener::test_meshes;

bool savePly(Mesh &mesh, const std::filesystem::path &path) {
  const int mask = vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_FACEINDEX;
  const int error =
      vcg::tri::io::ExporterPLY<Mesh>::Save(mesh, path.string().c_str(), mask, /*binary=*/true);
  if (error != 0) {
    std::fprintf(stderr, "generate-test-meshes: error: cannot write %s: %s\n",
                 path.string().c_str(), vcg::tri::io::ExporterPLY<Mesh>::ErrorMsg(error));
    return false;
  }
  return true;
}

void report(const std::filesystem::path &path, const Mesh &mesh, double seconds) {
  std::printf("%-40s %8d vertices %8d faces %7.2f s\n", path.string().c_str(), mesh.vn, mesh.fn,
              seconds);
}

}  // namespace

int main(int argc, char **argv) {
  CLI::App app{"Writes the exact test shapes and their marching-cubes meshes as binary PLY."};
  std::string outputDir;
  std::vector<double> cellFractions = {0.02, 0.01};
  std::vector<std::string> shapeNames = shapes::shapeNames();
  app.add_option("OUTDIR", outputDir, "Output directory (created if missing)")->required();
  app.add_option("--cells", cellFractions,
                 "Marching-cubes cell sizes as fractions of the bounding-box diagonal")
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  app.add_option("--shapes", shapeNames, "Shapes to write (default: all)")->delimiter(',');
  bool spots = false;
  app.add_flag("--spots", spots,
               "Also write each marching-cubes mesh with a non-manifold vertex near a chamfer "
               "and a non-manifold edge on one (<name>_spots.ply)");
  bool bevelFaces = false;
  app.add_flag("--bevel-faces", bevelFaces,
               "For bevelled_block, also write the indices of the faces on its wide designed "
               "bevel (<name>_bevel.txt)");
  CLI11_PARSE(app, argc, argv);

  try {
    std::filesystem::create_directories(outputDir);
    for (const std::string &name : shapeNames) {
      const shapes::Shape &shape = shapes::shapeByName(name);
      Mesh mesh;
      auto start = std::chrono::steady_clock::now();
      shapes::buildReference(shape, mesh);
      auto elapsed = [&start] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      };
      const std::filesystem::path referencePath =
          std::filesystem::path(outputDir) / (name + "_reference.ply");
      if (!savePly(mesh, referencePath)) return 1;
      report(referencePath, mesh, elapsed());
      for (double fraction : cellFractions) {
        start = std::chrono::steady_clock::now();
        shapes::marchingCubes(shape, shapes::cellSizeForDiagonalFraction(shape, fraction), mesh);
        const std::filesystem::path mcPath =
            std::filesystem::path(outputDir) /
            (name + "_mc" + shapes::percentLabel(fraction) + ".ply");
        if (!savePly(mesh, mcPath)) return 1;
        report(mcPath, mesh, elapsed());
        if (bevelFaces && name == "bevelled_block") {
          std::filesystem::path listPath = mcPath;
          listPath.replace_extension().concat("_bevel.txt");
          std::ofstream list(listPath);
          list << "# faces of " << mcPath.filename().string()
               << " on the designed bevel 0.07 wide (test_meshes/designed_faces.h)\n";
          const std::vector<char> on = shapes::bevelledBlockBevelFaces(
              mesh, shapes::cellSizeForDiagonalFraction(shape, fraction), shapes::kWideBevel);
          for (std::size_t f = 0; f < on.size(); ++f)
            if (on[f]) list << f << "\n";
          if (!list.flush()) throw std::runtime_error("cannot write " + listPath.string());
          std::printf("%s\n", listPath.string().c_str());
        }
        if (!spots) continue;
        using shapes::SpotKind, shapes::SpotPlace;
        // Both places chosen on the clean mesh (a spot's tetrahedron is bent too).
        const std::size_t near = shapes::spotVertex(mesh, SpotPlace::NearChamfer);
        const std::size_t on = shapes::spotVertex(mesh, SpotPlace::OnChamfer);
        shapes::addSpot(mesh, SpotKind::Vertex, near);
        shapes::addSpot(mesh, SpotKind::Edge, on);
        std::filesystem::path spotsPath = mcPath;
        spotsPath.replace_extension().concat("_spots.ply");
        if (!savePly(mesh, spotsPath)) return 1;
        report(spotsPath, mesh, elapsed());
      }
    }
  } catch (const std::exception &error) {
    std::fprintf(stderr, "generate-test-meshes: error: %s\n", error.what());
    return 1;
  }
  return 0;
}
