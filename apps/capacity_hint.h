// Capacity for a mesh about to be read and sharpened, from the element counts
// in the file's header (PLY, OFF; other formats get none).
//
// Sharpening appends vertices and faces (the split of chamfer and corner
// triangles). Without spare capacity, std::vector reallocates the face array
// there: old and new array are both resident while the faces are copied, and
// the peak memory of a run becomes about twice the mesh. Reserved before
// reading, the spare capacity is only address space: the kernel backs pages
// when they are first written, so the resident size grows by what the
// subdivision really adds and nothing is copied. vcglib's per-element
// attributes reserve their container's capacity too, so they do not
// reallocate either.
#pragma once

#include <cctype>
#include <cstddef>
#include <exception>
#include <fstream>
#include <sstream>
#include <string>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace edge_sharpener::io {

/// Large blocks (from 128 KiB) go to their own mappings and back to the
/// system when freed. glibc's default raises that threshold after the first
/// such block is freed (up to 32 MiB), after which the reader's and the
/// stages' temporary arrays of a few MiB pile up on the heap: about 20 MB more
/// peak on a 1M-face mesh. Call once at the start of a program that reads
/// big meshes.
inline void returnLargeBlocksToTheSystem() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
}

/// Vertex and face counts declared in the header of a PLY or OFF file; false
/// when the format has none or the header cannot be read (the reader will
/// say why).
inline bool declaredElementCounts(const std::string &path, std::size_t &vertices,
                                  std::size_t &faces) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line)) return false;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  constexpr int kMaxHeaderLines = 10000;
  if (line == "ply") {
    bool haveV = false, haveF = false;
    for (int n = 0; n < kMaxHeaderLines && std::getline(in, line); ++n) {
      std::istringstream s(line);
      std::string key, name;
      unsigned long long count = 0;
      if (!(s >> key) || key == "end_header") break;
      if (key != "element" || !(s >> name >> count)) continue;
      if (name == "vertex") vertices = std::size_t(count), haveV = true;
      if (name == "face") faces = std::size_t(count), haveF = true;
    }
    return haveV && haveF;
  }
  // OFF: "OFF" (possibly followed by the counts), then "nv nf ne", '#' comments.
  std::string rest;
  if (line.compare(0, 3, "OFF") != 0) return false;
  rest = line.substr(3);
  for (int n = 0; n < kMaxHeaderLines; ++n) {
    const std::size_t hash = rest.find('#');
    if (hash != std::string::npos) rest.resize(hash);
    std::istringstream s(rest);
    unsigned long long nv = 0, nf = 0;
    if (s >> nv >> nf) {
      vertices = std::size_t(nv);
      faces = std::size_t(nf);  // polygons: at least this many triangles
      return true;
    }
    if (rest.find_first_not_of(" \t\r") != std::string::npos) return false;
    if (!std::getline(in, rest)) return false;
  }
  return false;
}

/// Reserves twice the declared vertex and face counts in `m` (empty, before
/// io::loadMesh): room for what sharpening adds in all but extreme cases
/// (every face split in two), as untouched address space. Counts a file of
/// its size cannot hold (a corrupt header) are ignored, and so is a failed
/// reservation: the mesh then grows as it would have without one.
template <class MeshType>
void reserveForSharpening(const std::string &path, MeshType &m) {
  std::size_t vertices = 0, faces = 0;
  if (!declaredElementCounts(path, vertices, faces) || vertices == 0 || faces == 0) return;
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  const std::streamoff bytes = file.good() ? std::streamoff(file.tellg()) : 0;
  // Every vertex and face takes at least one byte of the file.
  if (bytes <= 0 || vertices > std::size_t(bytes) || faces > std::size_t(bytes)) return;
  try {
    m.vert.reserve(2 * vertices);
    m.face.reserve(2 * faces);
  } catch (const std::exception &) {  // bad_alloc, length_error
  }
}

}  // namespace edge_sharpener::io
