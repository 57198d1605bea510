// libFuzzer target: the project's Metro (measureDistance) fed two small random
// triangle soups. Input layout: bytes 0-1 = vertex counts of A and B - 3 (mod
// 32), byte 2 = options (bit 0: shift both soups far from the origin, where
// float cells round coarsely; bit 1: sub-grid jitter from the following bytes),
// byte 3 = face count of A (mod 64, at least 1), then 3 bytes per vertex
// (coordinates on a coarse grid), then 3 bytes per face (indices mod the vertex
// count): A's faces first, the rest are B's. A soup without area must be
// refused; otherwise the distances must be finite and ordered
// (0 <= min <= mean <= RMS <= max) and the meshes left untouched.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>  // before vcglib: wrap/callback.h uses strcpy without including it
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh_distance.h"
#include "edge_sharpener/util/mesh_types.h"
#include "fuzz_fail.h"

namespace {

namespace es = edge_sharpener;
using es_fuzz::fail;

void checkSide(const es::OneSidedDistance &d, const char *side) {
  const double values[4] = {d.min, d.mean, d.rms, d.max};
  for (double x : values)
    if (!std::isfinite(x) || x < 0)
      fail(std::string(side) + ": a distance is negative or not finite");
  const double slack = 1e-6 * (1 + d.max);
  if (d.samples == 0) fail(std::string(side) + ": no sample");
  if (!(d.min <= d.mean + slack && d.mean <= d.rms + slack && d.rms <= d.max + slack))
    fail(std::string(side) + ": min <= mean <= RMS <= max does not hold");
}

std::vector<es::Mesh::CoordType> positions(const es::Mesh &m) {
  std::vector<es::Mesh::CoordType> p;
  for (const auto &v : m.vert) p.push_back(v.cP());
  return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size < 4) return 0;
  const int nv[2] = {3 + data[0] % 32, 3 + data[1] % 32};
  const uint8_t flags = data[2];
  const std::size_t nfA = 1 + data[3] % 64;
  std::size_t at = 4;
  auto next = [&]() -> uint8_t { return at < size ? data[at++] : 0; };
  const float shift = (flags & 1) ? 1000.0f : 0.0f;

  es::Mesh mesh[2];
  for (int s = 0; s < 2; ++s) {
    auto vi = vcg::tri::Allocator<es::Mesh>::AddVertices(mesh[s], nv[s]);
    for (int i = 0; i < nv[s]; ++i, ++vi)
      for (int k = 0; k < 3; ++k) vi->P()[k] = shift + (int(next()) - 128) / 16.0f;
  }
  if (flags & 2)
    for (auto &m : mesh)
      for (auto &v : m.vert)
        for (int k = 0; k < 3; ++k) v.P()[k] += (int(next()) - 128) / 4096.0f;
  const std::size_t rest = at < size ? (size - at) / 3 : 0;
  if (rest <= nfA || rest > 256) return 0;
  const std::size_t nf[2] = {nfA, rest - nfA};
  for (int s = 0; s < 2; ++s) {
    auto fi = vcg::tri::Allocator<es::Mesh>::AddFaces(mesh[s], nf[s]);
    for (std::size_t i = 0; i < nf[s]; ++i, ++fi)
      for (int k = 0; k < 3; ++k) fi->V(k) = &mesh[s].vert[next() % nv[s]];
  }

  const auto before0 = positions(mesh[0]), before1 = positions(mesh[1]);
  es::DistanceOptions options;
  options.faceSamples = 400;
  es::DistanceReport report;
  try {
    report = es::measureDistance(mesh[0], mesh[1], options);
  } catch (const std::invalid_argument &) {
    return 0;  // a soup without area: refused
  }
  checkSide(report.forward, "forward");
  checkSide(report.backward, "backward");
  if (positions(mesh[0]) != before0 || positions(mesh[1]) != before1)
    fail("measureDistance moved a vertex");
  return 0;
}
