// mesh-roundtrip IN OUT: reads and writes a mesh exactly as the edge-sharpener
// CLI does (the same allocator setting and capacity reservation, apps/capacity_hint.h, and the same
// reader and writer, apps/mesh_io.h), nothing else: the memory and time
// baseline of the CLI's end-to-end measurement.
#include <cstdio>
#include <exception>

#include "capacity_hint.h"
#include "edge_sharpener/util/mesh_types.h"
#include "mesh_io.h"

int main(int argc, char **argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: mesh-roundtrip IN OUT\n");
    return 2;
  }
  try {
    edge_sharpener::io::returnLargeBlocksToTheSystem();
    edge_sharpener::Mesh m;
    edge_sharpener::io::reserveForSharpening(argv[1], m);
    edge_sharpener::io::loadMesh(argv[1], m);
    edge_sharpener::io::saveMesh(m, argv[2], 0);
  } catch (const std::exception &e) {
    std::fprintf(stderr, "mesh-roundtrip: %s\n", e.what());
    return 1;
  }
  return 0;
}
