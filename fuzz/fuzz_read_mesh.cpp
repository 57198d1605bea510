// libFuzzer target: the mesh readers (apps/mesh_io.h: our own PLY, OFF,
// OBJ and STL readers), then the core on whatever they accept.
// Input: first byte selects the format, the rest is the file's content.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "fuzz_sharpen_check.h"
#include "mesh_io.h"

namespace {

const char *const kExtensions[] = {"ply", "off", "obj", "stl"};
constexpr int kMaxFacesToSharpen = 4000;  // keeps executions fast

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size < 1) return 0;
  const std::string path =
      "/tmp/es-fuzz-read-" + std::to_string(getpid()) + "." + kExtensions[data[0] % 4];
  {
    std::FILE *f = std::fopen(path.c_str(), "wb");
    if (!f) return 0;
    if (size > 1) std::fwrite(data + 1, 1, size - 1, f);
    std::fclose(f);
  }
  es_fuzz::es::Mesh m;
  bool loaded = true;
  try {
    edge_sharpener::io::loadMesh(path, m);
  } catch (const std::runtime_error &) {
    loaded = false;
  }
  std::remove(path.c_str());
  if (!loaded) return 0;
  if (m.fn <= kMaxFacesToSharpen) es_fuzz::sharpenAndCheck(m, {});
  return 0;
}
