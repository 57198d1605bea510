// make-bench-mesh OUT.ply FACES
// Writes the benchmark mesh of about FACES faces (marching cubes of the tilted
// L-block, see bench_mesh.h) as binary PLY and prints its size.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bench_mesh.h"
// (keep after the mesh headers)
#include <wrap/io_trimesh/export_ply.h>

int main(int argc, char **argv) {
  namespace es = edge_sharpener;
  if (argc != 3) {
    std::fprintf(stderr, "usage: make-bench-mesh OUT.ply FACES\n");
    return 2;
  }
  const double faces = std::atof(argv[2]);
  if (!(faces >= 100)) {
    std::fprintf(stderr, "make-bench-mesh: FACES must be at least 100\n");
    return 2;
  }
  const auto &shape = es::test_meshes::shapeByName(es::bench::kShape);
  const auto start = std::chrono::steady_clock::now();
  es::Mesh m;
  es::test_meshes::marchingCubes(shape, es::bench::cellSizeForFaces(shape, faces), m);
  const int mask = vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_FACEINDEX;
  if (vcg::tri::io::ExporterPLY<es::Mesh>::Save(m, argv[1], mask, /*binary=*/true) != 0) {
    std::fprintf(stderr, "make-bench-mesh: cannot write %s\n", argv[1]);
    return 1;
  }
  std::printf("%s %d vertices %d faces %.1f s\n", argv[1], m.vn, m.fn,
              es::bench::secondsSince(start));
  return 0;
}
