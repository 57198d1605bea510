// Scoped (RAII) temporary per-face / per-vertex attributes: algorithm state
// lives in these for the duration of one call and is removed afterwards, even
// when an exception escapes. They follow the mesh through AddVertices /
// AddFaces / compaction like any vcglib attribute.
#pragma once

#include <vcg/complex/complex.h>

#include <cstddef>

namespace edge_sharpener {

namespace detail {

/// What differs between per-face and per-vertex attributes.
template <class MeshType>
struct FaceAttributes {
  using Element = typename MeshType::FaceType;
  template <class T>
  using Handle = typename MeshType::template PerFaceAttributeHandle<T>;
  static std::size_t count(const MeshType &m) { return m.face.size(); }
  template <class T>
  static Handle<T> add(MeshType &m) {
    return vcg::tri::Allocator<MeshType>::template AddPerFaceAttribute<T>(m);
  }
  template <class T>
  static void remove(MeshType &m, Handle<T> &h) {
    vcg::tri::Allocator<MeshType>::DeletePerFaceAttribute(m, h);
  }
};

template <class MeshType>
struct VertexAttributes {
  using Element = typename MeshType::VertexType;
  template <class T>
  using Handle = typename MeshType::template PerVertexAttributeHandle<T>;
  static std::size_t count(const MeshType &m) { return m.vert.size(); }
  template <class T>
  static Handle<T> add(MeshType &m) {
    return vcg::tri::Allocator<MeshType>::template AddPerVertexAttribute<T>(m);
  }
  template <class T>
  static void remove(MeshType &m, Handle<T> &h) {
    vcg::tri::Allocator<MeshType>::DeletePerVertexAttribute(m, h);
  }
};

/// A temporary attribute of type T on every element of one kind.
template <class MeshType, class T, class Kind>
class ScopedAttribute {
 public:
  using Element = typename Kind::Element;
  explicit ScopedAttribute(MeshType &m, const T &init = T()) : m_(m), h_(Kind::template add<T>(m)) {
    for (std::size_t i = 0; i < Kind::count(m); ++i) h_[i] = init;
  }
  ~ScopedAttribute() { Kind::remove(m_, h_); }
  ScopedAttribute(const ScopedAttribute &) = delete;
  ScopedAttribute &operator=(const ScopedAttribute &) = delete;

  T &operator[](const Element *e) { return h_[e]; }
  T &operator[](std::size_t i) { return h_[i]; }
  // vcglib's handle has no const access; its storage is reached through a
  // pointer, so reading it does not change the handle.
  const T &operator[](const Element *e) const { return (*h_._handle)[e]; }
  const T &operator[](std::size_t i) const { return (*h_._handle)[i]; }

 private:
  MeshType &m_;
  typename Kind::template Handle<T> h_;
};

}  // namespace detail

template <class MeshType, class T>
using ScopedFaceAttribute = detail::ScopedAttribute<MeshType, T, detail::FaceAttributes<MeshType>>;
template <class MeshType, class T>
using ScopedVertexAttribute =
    detail::ScopedAttribute<MeshType, T, detail::VertexAttributes<MeshType>>;

/// Position of a mesh vertex in double precision.
template <class VertexType>
inline vcg::Point3d positionOf(const VertexType *v) {
  return vcg::Point3d::Construct(v->cP());
}

}  // namespace edge_sharpener
