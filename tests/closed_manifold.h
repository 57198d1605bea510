// What a closed solid's mesh must be, for the tests of generated and extracted shapes.
#pragma once

#include <gtest/gtest.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/inertia.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <string>

namespace edge_sharpener::testing {

/// Two-manifold, watertight (no border edge), coherently oriented, outward (positive
/// volume), one component of the given genus (0: sphere-like).
template <class M>
void expectClosedManifold(M &mesh, const std::string &what, int genus = 0) {
  SCOPED_TRACE(what);
  ASSERT_GT(mesh.fn, 0);
  int edges = 0, borderEdges = 0, nonManifoldEdges = 0;
  vcg::tri::Clean<M>::CountEdgeNum(mesh, edges, borderEdges, nonManifoldEdges);
  EXPECT_EQ(borderEdges, 0);
  EXPECT_EQ(nonManifoldEdges, 0);
  vcg::tri::UpdateTopology<M>::FaceFace(mesh);
  // (not Clean::CountNonManifoldEdgeFF: it never releases the three face bit flags it
  // allocates, so a process can call it only a few times; CountEdgeNum covers it)
  EXPECT_EQ(vcg::tri::Clean<M>::CountNonManifoldVertexFF(mesh, /*selectVert=*/false), 0);
  EXPECT_TRUE(vcg::tri::Clean<M>::IsCoherentlyOrientedMesh(mesh));
  EXPECT_EQ(vcg::tri::Clean<M>::CountConnectedComponents(mesh), 1);
  EXPECT_EQ(mesh.vn - edges + mesh.fn, 2 - 2 * genus)
      << "Euler characteristic of a closed surface of genus " << genus;
  vcg::tri::Inertia<M> inertia(mesh);
  EXPECT_GT(inertia.Mass(), 0) << "faces must point outward";
}

}  // namespace edge_sharpener::testing
