// Scoped (RAII) temporary per-face / per-vertex attributes: algorithm state
// lives in these for the duration of one call and is removed afterwards, even
// when an exception escapes. They follow the mesh through AddVertices /
// AddFaces / compaction like any vcglib attribute.
#pragma once

#include <cstddef>

#include <vcg/complex/complex.h>

namespace edge_sharpener {

template <class MeshType, class T>
class ScopedFaceAttribute {
 public:
  explicit ScopedFaceAttribute(MeshType &m, const T &init = T())
      : m_(m), h_(vcg::tri::Allocator<MeshType>::template AddPerFaceAttribute<T>(m)) {
    for (std::size_t i = 0; i < m.face.size(); ++i) h_[i] = init;
  }
  ~ScopedFaceAttribute() { vcg::tri::Allocator<MeshType>::DeletePerFaceAttribute(m_, h_); }
  ScopedFaceAttribute(const ScopedFaceAttribute &) = delete;
  ScopedFaceAttribute &operator=(const ScopedFaceAttribute &) = delete;

  T &operator[](const typename MeshType::FaceType *f) { return h_[f]; }
  T &operator[](std::size_t i) { return h_[i]; }
  // vcglib's handle has no const access; its storage is reached through a
  // pointer, so reading it does not change the handle.
  const T &operator[](const typename MeshType::FaceType *f) const { return (*h_._handle)[f]; }
  const T &operator[](std::size_t i) const { return (*h_._handle)[i]; }

 private:
  MeshType &m_;
  typename MeshType::template PerFaceAttributeHandle<T> h_;
};

template <class MeshType, class T>
class ScopedVertexAttribute {
 public:
  explicit ScopedVertexAttribute(MeshType &m, const T &init = T())
      : m_(m), h_(vcg::tri::Allocator<MeshType>::template AddPerVertexAttribute<T>(m)) {
    for (std::size_t i = 0; i < m.vert.size(); ++i) h_[i] = init;
  }
  ~ScopedVertexAttribute() { vcg::tri::Allocator<MeshType>::DeletePerVertexAttribute(m_, h_); }
  ScopedVertexAttribute(const ScopedVertexAttribute &) = delete;
  ScopedVertexAttribute &operator=(const ScopedVertexAttribute &) = delete;

  T &operator[](const typename MeshType::VertexType *v) { return h_[v]; }
  T &operator[](std::size_t i) { return h_[i]; }
  const T &operator[](const typename MeshType::VertexType *v) const { return (*h_._handle)[v]; }
  const T &operator[](std::size_t i) const { return (*h_._handle)[i]; }

 private:
  MeshType &m_;
  typename MeshType::template PerVertexAttributeHandle<T> h_;
};

/// Position of a mesh vertex in double precision.
template <class VertexType>
inline vcg::Point3d positionOf(const VertexType *v) {
  return vcg::Point3d::Construct(v->cP());
}

}  // namespace edge_sharpener
