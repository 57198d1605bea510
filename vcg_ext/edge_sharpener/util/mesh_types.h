// Concrete vcglib mesh types used by the command-line tools and the tests.
// The algorithms in this folder are templates over any vcg triangle mesh that
// satisfies their `tri::Require*` preconditions (MeshLab's CMeshO included);
// these types only fix a layout for the programs that own their meshes.
#pragma once

#include <vcg/complex/complex.h>

namespace edge_sharpener {

/// One vertex/face/mesh layout, instantiated with float or double
/// coordinate and normal components (vcglib components are templates, hence
/// the template-template parameters).
template <template <class> class VertexCoord, template <class> class VertexNormal,
          template <class> class FaceNormal>
struct MeshTypesOf {
  class Vertex;
  class Face;
  struct UsedTypes : public vcg::UsedTypes<vcg::Use<Vertex>::template AsVertexType,
                                           vcg::Use<Face>::template AsFaceType> {};
  class Vertex
      : public vcg::Vertex<UsedTypes, VertexCoord, VertexNormal, vcg::vertex::Color4b,
                           vcg::vertex::Qualityf, vcg::vertex::BitFlags, vcg::vertex::Mark> {};
  class Face : public vcg::Face<UsedTypes, vcg::face::VertexRef, FaceNormal, vcg::face::Color4b,
                                vcg::face::Qualityf, vcg::face::FFAdj, vcg::face::BitFlags,
                                vcg::face::Mark> {};
  class Mesh : public vcg::tri::TriMesh<std::vector<Vertex>, std::vector<Face>> {};
};

/// Single precision, like MeshLab's CMeshO: what the CLI reads and writes.
using Mesh = MeshTypesOf<vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::face::Normal3f>::Mesh;
/// Double precision variant, used by tests to show the core is scalar-generic.
using MeshD = MeshTypesOf<vcg::vertex::Coord3d, vcg::vertex::Normal3d, vcg::face::Normal3d>::Mesh;

}  // namespace edge_sharpener
