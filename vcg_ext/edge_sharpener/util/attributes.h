// Scoped (RAII) temporary per-face / per-vertex attributes: algorithm state
// lives in these for the duration of one call and is removed afterwards, even
// when an exception escapes. They follow the mesh through AddVertices /
// AddFaces / compaction like any vcglib attribute.
#pragma once

#include <vcg/complex/complex.h>

#include <cstddef>
#include <type_traits>

namespace edge_sharpener {

namespace detail {

/// A temporary attribute of type T on every face (OnFaces) or every vertex.
template <class MeshType, class T, bool OnFaces>
class ScopedAttribute {
  using Allocator = vcg::tri::Allocator<MeshType>;
  using Handle = std::conditional_t<OnFaces, typename MeshType::template PerFaceAttributeHandle<T>,
                                    typename MeshType::template PerVertexAttributeHandle<T>>;

 public:
  using Element =
      std::conditional_t<OnFaces, typename MeshType::FaceType, typename MeshType::VertexType>;
  explicit ScopedAttribute(MeshType &m, const T &init = T()) : m_(m), h_(add(m)) {
    const std::size_t count = OnFaces ? m.face.size() : m.vert.size();
    for (std::size_t i = 0; i < count; ++i) h_[i] = init;
  }
  ~ScopedAttribute() {
    if constexpr (OnFaces)
      Allocator::DeletePerFaceAttribute(m_, h_);
    else
      Allocator::DeletePerVertexAttribute(m_, h_);
  }
  ScopedAttribute(const ScopedAttribute &) = delete;
  ScopedAttribute &operator=(const ScopedAttribute &) = delete;

  T &operator[](const Element *e) { return h_[e]; }
  T &operator[](std::size_t i) { return h_[i]; }
  // vcglib's handle has no const access; its storage is reached through a
  // pointer, so reading it does not change the handle.
  const T &operator[](const Element *e) const { return (*h_._handle)[e]; }
  const T &operator[](std::size_t i) const { return (*h_._handle)[i]; }

 private:
  static Handle add(MeshType &m) {
    if constexpr (OnFaces)
      return Allocator::template AddPerFaceAttribute<T>(m);
    else
      return Allocator::template AddPerVertexAttribute<T>(m);
  }

  MeshType &m_;
  Handle h_;
};

}  // namespace detail

template <class MeshType, class T>
using ScopedFaceAttribute = detail::ScopedAttribute<MeshType, T, true>;
template <class MeshType, class T>
using ScopedVertexAttribute = detail::ScopedAttribute<MeshType, T, false>;

/// Position of a mesh vertex in double precision.
template <class VertexType>
inline vcg::Point3d positionOf(const VertexType *v) {
  return vcg::Point3d::Construct(v->cP());
}

}  // namespace edge_sharpener
