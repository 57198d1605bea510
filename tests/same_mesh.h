// Whether two meshes are the same, bit for bit, for the tests that compare
// two runs (or two routes to one result).
#pragma once

#include <gtest/gtest.h>
#include <vcg/complex/complex.h>

namespace edge_sharpener::testing {

/// The same vertex count and every vertex at the same position, bit for bit.
template <class MA, class MB>
::testing::AssertionResult samePositions(const MA &a, const MB &b) {
  if (a.vert.size() != b.vert.size())
    return ::testing::AssertionFailure() << a.vert.size() << " vertices against " << b.vert.size();
  for (std::size_t v = 0; v < a.vert.size(); ++v)
    if (!(a.vert[v].cP() == b.vert[v].cP()))
      return ::testing::AssertionFailure() << "vertex " << v << " differs";
  return ::testing::AssertionSuccess();
}

/// samePositions, and the same faces: the same count, each with the same
/// vertex indices in the same order.
template <class MA, class MB>
::testing::AssertionResult sameMesh(const MA &a, const MB &b) {
  if (::testing::AssertionResult positions = samePositions(a, b); !positions) return positions;
  if (a.face.size() != b.face.size())
    return ::testing::AssertionFailure() << a.face.size() << " faces against " << b.face.size();
  for (std::size_t f = 0; f < a.face.size(); ++f)
    for (int i = 0; i < 3; ++i)
      if (vcg::tri::Index(a, a.face[f].cV(i)) != vcg::tri::Index(b, b.face[f].cV(i)))
        return ::testing::AssertionFailure() << "face " << f << " differs";
  return ::testing::AssertionSuccess();
}

}  // namespace edge_sharpener::testing
