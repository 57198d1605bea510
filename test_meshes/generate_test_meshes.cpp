// generate-test-meshes OUTDIR [--cells 0.02,0.01] [--shapes cube,lblock] [--spots]
//                      [--bevel-faces]
// generate-test-meshes OUTDIR --designed-faces MESH --shapes NAME [--within D]
// Writes <shape>_reference.ply (exact triangulation) and <shape>_mc<percent>.ply (marching
// cubes with cells of <percent>% of the bounding-box diagonal) as binary PLY; with --spots
// also <shape>_mc<percent>_spots.ply, the same with two non-manifold spots added
// (non_manifold_spots.h): a vertex near a chamfer and an edge on one; with --bevel-faces,
// for bevelled_block, <shape>_mc<percent>_bevel.txt, the indices of the faces on its wide
// designed bevel (designed_faces.h), one per line: what a user deselects before sharpening.
// With --designed-faces MESH (a sampling of the one shape --shapes names, in its frame, by any
// tool) it writes only OUTDIR/<mesh>_designed.txt: the faces of MESH on any of the shape's
// designed bevels and fillets, within D (default: MESH's median edge length, one sample
// spacing) of them, with a comment line per designed feature (kind, size, width across).
#include <CLI/CLI.hpp>
#include <algorithm>
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
#include <wrap/io_trimesh/import.h>

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

/// The faces of `mesh` on designed features of `shape` as a list: a comment
/// line per feature, then one face index per line.
bool writeDesignedFaces(const std::filesystem::path &path, const std::string &of, const Mesh &mesh,
                        const std::string &shape, double within) {
  const auto *prism = shapes::finishedPrism(shape);
  if (prism == nullptr) {
    std::fprintf(stderr, "generate-test-meshes: error: %s has no designed features\n",
                 shape.c_str());
    return false;
  }
  const std::vector<shapes::DesignedFinish> finishes = shapes::designedFinishes(*prism);
  std::ofstream list(path);
  list << "# faces of " << of << " within " << within << " of a designed feature of " << shape
       << " (test_meshes/designed_faces.h)\n";
  for (const shapes::DesignedFinish &finish : finishes)
    list << "# " << finish.kindName() << " " << finish.size << ": " << finish.width() << " wide\n";
  const std::vector<char> on = shapes::designedFaces(mesh, *prism, finishes, within);
  for (std::size_t f = 0; f < on.size(); ++f)
    if (on[f]) list << f << "\n";
  if (!list.flush()) {
    std::fprintf(stderr, "generate-test-meshes: error: cannot write %s\n", path.c_str());
    return false;
  }
  std::printf("%s %zu faces\n", path.string().c_str(),
              std::size_t(std::count(on.begin(), on.end(), 1)));
  return true;
}

double medianEdgeLength(const Mesh &mesh) {
  std::vector<double> lengths;
  for (const auto &f : mesh.face)
    for (int i = 0; i < 3; ++i) lengths.push_back(vcg::Distance(f.cP(i), f.cP((i + 1) % 3)));
  if (lengths.empty()) return 0;
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  return lengths[lengths.size() / 2];
}

/// --designed-faces: reads the mesh, writes its list.
int designedFacesOf(const std::string &meshPath, const std::vector<std::string> &shapeNames,
                    const std::string &outputDir, double within) {
  if (shapeNames.size() != 1) {
    std::fprintf(stderr, "generate-test-meshes: error: --designed-faces needs one --shapes\n");
    return 1;
  }
  Mesh mesh;
  int loadMask = 0;
  if (vcg::tri::io::Importer<Mesh>::Open(mesh, meshPath.c_str(), loadMask) != 0 || mesh.fn == 0) {
    std::fprintf(stderr, "generate-test-meshes: error: cannot read a mesh from %s\n",
                 meshPath.c_str());
    return 1;
  }
  std::filesystem::create_directories(outputDir);
  const std::filesystem::path in(meshPath);
  const std::filesystem::path out =
      std::filesystem::path(outputDir) / (in.stem().string() + "_designed.txt");
  return writeDesignedFaces(out, in.filename().string(), mesh, shapeNames[0],
                            within > 0 ? within : medianEdgeLength(mesh))
             ? 0
             : 1;
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
  std::string designedFacesMesh;
  app.add_option("--designed-faces", designedFacesMesh,
                 "Write only OUTDIR/<mesh>_designed.txt: the faces of this mesh (a sampling of "
                 "the one shape --shapes names) on the shape's designed bevels and fillets");
  double within = 0;
  app.add_option("--within", within,
                 "--designed-faces: how near a face's centroid lies to a designed feature "
                 "(default: the mesh's median edge length)")
      ->check(CLI::NonNegativeNumber);
  CLI11_PARSE(app, argc, argv);
  if (!designedFacesMesh.empty())
    return designedFacesOf(designedFacesMesh, shapeNames, outputDir, within);

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
          const auto &prism = *shapes::finishedPrism(name);
          const std::vector<char> on = shapes::designedFaces(
              mesh, prism, {shapes::designedFinishes(prism)[shapes::kWideBevel]},
              shapes::cellSizeForDiagonalFraction(shape, fraction));
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
