// libFuzzer target: the core fed small random triangle soups.
// Input layout: byte 0 = vertex count - 3 (mod 48), byte 1 = options, then per
// vertex 3 bytes (coordinates on a coarse grid, so that coincident and coplanar
// vertices are frequent; byte 1 bit 7 adds sub-grid jitter from the following
// bytes), then 3 bytes per face (indices mod the vertex count). Byte 0 bit 7
// sharpens only a selection (about half the faces, chosen by their index).
// Every mesh is sharpened; refusals must leave it untouched, results must keep
// the invariants.
#include <cstddef>
#include <cstdint>

#include "fuzz_sharpen_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size < 2) return 0;
  const int nv = 3 + data[0] % 48;
  const uint8_t flags = data[1];
  std::size_t at = 2;
  auto next = [&]() -> uint8_t { return at < size ? data[at++] : 0; };

  es_fuzz::es::Mesh m;
  auto vi = vcg::tri::Allocator<es_fuzz::es::Mesh>::AddVertices(m, nv);
  for (int i = 0; i < nv; ++i, ++vi)
    for (int k = 0; k < 3; ++k) vi->P()[k] = (int(next()) - 128) / 16.0f;
  if (flags & 0x80)
    for (auto &v : m.vert)
      for (int k = 0; k < 3; ++k) v.P()[k] += (int(next()) - 128) / 4096.0f;
  const std::size_t nf = at < size ? (size - at) / 3 : 0;
  if (nf == 0 || nf > 200) return 0;
  auto fi = vcg::tri::Allocator<es_fuzz::es::Mesh>::AddFaces(m, nf);
  for (std::size_t i = 0; i < nf; ++i, ++fi)
    for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[next() % nv];

  auto opt = edge_sharpener::SharpenOptions::paperMethod();  // its invariants are checked
  opt.smoothMultiplier = 1.0 + (flags & 7) * 0.5;            // 1 .. 4.5
  opt.edgeLengthCheck = !(flags & 8);
  opt.paper.convexityCheck = !(flags & 16);
  opt.degenerateAngleRad = ((flags >> 5) & 3) * M_PI / 180.0;  // 0 .. 3 degrees
  if (data[0] & 0x80) {
    opt.selectedFacesOnly = true;
    for (std::size_t i = 0; i < nf; ++i)
      if ((i * 2654435761u) & 0x100) m.face[i].SetS();
  }
  es_fuzz::sharpenAndCheck(m, opt);
  return 0;
}
