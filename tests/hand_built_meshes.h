// Small hand-built meshes for the stage tests (subdivision, cleanup, feature
// zones), and the checks every stage must leave true: closed, 2-manifold,
// consistently oriented, face-face adjacency as a rebuild gives it.
#pragma once

#include <gtest/gtest.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/complex.h>
#include <vcg/simplex/face/pos.h>
#include <vcg/simplex/face/topology.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "edge_sharpener/subdivision.h"
#include "edge_sharpener/util/geometry.h"
#include "edge_sharpener/util/mesh_types.h"

namespace edge_sharpener {
namespace hand_built {

/// Makes `m` the mesh of these vertices and triangles (vertex indices), FF adjacency built.
template <class MeshType>
void makeMesh(MeshType &m, const std::vector<Vec3> &points,
              const std::vector<std::array<int, 3>> &triangles) {
  using Alloc = vcg::tri::Allocator<MeshType>;
  using Coord = typename MeshType::CoordType;
  m.Clear();
  Alloc::AddVertices(m, points.size());
  for (std::size_t i = 0; i < points.size(); ++i) m.vert[i].P() = Coord::Construct(points[i]);
  for (const auto &t : triangles) Alloc::AddFace(m, &m.vert[t[0]], &m.vert[t[1]], &m.vert[t[2]]);
  vcg::tri::UpdateTopology<MeshType>::FaceFace(m);
}

template <class FaceType>
Vec3 areaNormal(const FaceType &f) {
  const Vec3 p0 = positionOf(f.cV(0)), p1 = positionOf(f.cV(1)), p2 = positionOf(f.cV(2));
  return (p1 - p0) ^ (p2 - p0);  // twice the area times the unit normal
}

template <class MeshType>
std::size_t liveFaces(const MeshType &m) {
  std::size_t n = 0;
  for (const auto &f : m.face) n += !f.IsD();
  return n;
}

template <class MeshType>
std::size_t liveVertices(const MeshType &m) {
  std::size_t n = 0;
  for (const auto &v : m.vert) n += !v.IsD();
  return n;
}

/// Whether the live faces have an edge between vertices u and w.
template <class MeshType>
bool hasEdge(const MeshType &m, std::size_t u, std::size_t w) {
  for (const auto &f : m.face) {
    if (f.IsD()) continue;
    for (int i = 0; i < 3; ++i) {
      const std::size_t a = vcg::tri::Index(m, f.cV(i)), b = vcg::tri::Index(m, f.cV((i + 1) % 3));
      if ((a == u && b == w) || (a == w && b == u)) return true;
    }
  }
  return false;
}

/// Number of distinct vertices joined to v by an edge of a live face.
template <class MeshType>
std::size_t valence(const MeshType &m, std::size_t v) {
  std::set<std::size_t> neighbours;
  for (const auto &f : m.face) {
    if (f.IsD()) continue;
    for (int i = 0; i < 3; ++i)
      if (vcg::tri::Index(m, f.cV(i)) == v)
        for (int k = 1; k < 3; ++k) neighbours.insert(vcg::tri::Index(m, f.cV((i + k) % 3)));
  }
  return neighbours.size();
}

/// The live faces form a closed, 2-manifold, consistently oriented surface
/// of genus 0 whose FF adjacency says so: every edge has exactly two faces
/// walking it in opposite directions, each face's FFp/FFi points at the
/// other (reciprocally), every vertex's faces form one fan, and
/// V - E + F = 2. Deleted vertices and faces are ignored.
template <class MeshType>
::testing::AssertionResult closedOrientedManifold(MeshType &m) {
  using FaceType = typename MeshType::FaceType;
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  std::vector<std::size_t> facesAt(m.vert.size(), 0);
  for (auto &f : m.face) {
    if (f.IsD()) continue;
    const std::size_t fi = vcg::tri::Index(m, &f);
    for (int i = 0; i < 3; ++i) {
      if (f.V(i)->IsD())
        return ::testing::AssertionFailure() << "face " << fi << " has a deleted vertex";
      ++facesAt[vcg::tri::Index(m, f.cV(i))];
      const std::size_t a = vcg::tri::Index(m, f.cV(i)), b = vcg::tri::Index(m, f.cV((i + 1) % 3));
      if (++directed[{a, b}] > 1)
        return ::testing::AssertionFailure()
               << "edge " << a << "->" << b << " walked twice in one direction";
      FaceType *g = f.FFp(i);
      const int j = f.FFi(i);
      if (g == &f)
        return ::testing::AssertionFailure() << "face " << fi << " edge " << i << " is a border";
      if (g->IsD())
        return ::testing::AssertionFailure()
               << "face " << fi << " edge " << i << " links a deleted face";
      if (g->FFp(j) != &f || g->FFi(j) != i)
        return ::testing::AssertionFailure()
               << "face " << fi << " edge " << i << " not linked back";
      if (g->V0(j) != f.V1(i) || g->V1(j) != f.V0(i))
        return ::testing::AssertionFailure()
               << "face " << fi << " edge " << i << " and its twin disagree in orientation";
    }
  }
  for (const auto &[edge, count] : directed)
    if (directed.count({edge.second, edge.first}) == 0)
      return ::testing::AssertionFailure()
             << "edge " << edge.first << "-" << edge.second << " has one face";
  // One fan per vertex: walking around it over FF meets all its faces.
  for (auto &f : m.face) {
    if (f.IsD()) continue;
    for (int i = 0; i < 3; ++i) {
      std::vector<vcg::face::Pos<FaceType>> star;
      vcg::face::VFOrderedStarFF(vcg::face::Pos<FaceType>(&f, i, f.V(i)), star);
      const std::size_t v = vcg::tri::Index(m, f.cV(i));
      if (star.size() != facesAt[v])
        return ::testing::AssertionFailure()
               << "vertex " << v << " has " << facesAt[v] << " faces but a fan of " << star.size();
    }
  }
  std::size_t usedVertices = 0;
  for (std::size_t v = 0; v < m.vert.size(); ++v) usedVertices += facesAt[v] > 0;
  const long euler = long(usedVertices) - long(directed.size() / 2) + long(liveFaces(m));
  if (euler != 2) return ::testing::AssertionFailure() << "Euler characteristic " << euler;
  return ::testing::AssertionSuccess();
}

/// The FF adjacency of the live faces is the one vcglib's full rebuild gives
/// (unique on a 2-manifold mesh). Rebuilds it to compare.
template <class MeshType>
::testing::AssertionResult adjacencyMatchesRebuild(MeshType &m) {
  using FaceType = typename MeshType::FaceType;
  std::vector<std::array<std::pair<FaceType *, int>, 3>> before(m.face.size());
  for (std::size_t f = 0; f < m.face.size(); ++f)
    for (int i = 0; i < 3; ++i) before[f][i] = {m.face[f].FFp(i), m.face[f].FFi(i)};
  vcg::tri::UpdateTopology<MeshType>::FaceFace(m);
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    if (m.face[f].IsD()) continue;
    for (int i = 0; i < 3; ++i)
      if (before[f][i] != std::make_pair(m.face[f].FFp(i), int(m.face[f].FFi(i))))
        return ::testing::AssertionFailure() << "face " << f << " edge " << i << " differs";
  }
  return ::testing::AssertionSuccess();
}

/// Makes `m` a regular grid of (nx+1) x (ny+1) vertices with spacing h over
/// z = height(x, y), every cell cut by the same diagonal (open, normal +z);
/// vertex (i, j) has index j * (nx + 1) + i.
template <class MeshType, class Height>
void heightField(MeshType &m, int nx, int ny, double h, Height &&height) {
  std::vector<Vec3> points;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) points.push_back(Vec3(i * h, j * h, height(i * h, j * h)));
  std::vector<std::array<int, 3>> triangles;
  const auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  makeMesh(m, points, triangles);
}

/// Per face of `m`: region 0 when all its vertices lie at x <= x0, region 1
/// when all lie at x >= x1, else the zone (kZone): two regions of a height
/// field on either side of a feature zone across x.
template <class MeshType>
std::vector<int> regionsAcrossX(const MeshType &m, double x0, double x1, int zone) {
  std::vector<int> region(m.face.size(), zone);
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    double lo = 1e9, hi = -1e9;
    for (int k = 0; k < 3; ++k) {
      lo = std::min(lo, double(m.face[f].cP(k)[0]));
      hi = std::max(hi, double(m.face[f].cP(k)[0]));
    }
    if (hi <= x0 + 1e-6) region[f] = 0;
    if (lo >= x1 - 1e-6) region[f] = 1;
  }
  return region;
}

/// Makes `m` the closed surface of a set of unit voxels (cells given by their lowest
/// corner), every voxel face cut into n x n squares of two triangles:
/// outward-oriented, 2-manifold when the voxels meet face to face.
template <class MeshType>
void voxelSurface(MeshType &m, const std::vector<std::array<int, 3>> &cells, int n) {
  std::set<std::array<int, 3>> filled(cells.begin(), cells.end());
  std::map<std::array<int, 3>, int> vertexAt;  // on the grid refined n times
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  const auto vertex = [&](std::array<int, 3> g) {
    auto [it, added] = vertexAt.emplace(g, int(points.size()));
    if (added) points.push_back(Vec3(g[0], g[1], g[2]) / double(n));
    return it->second;
  };
  for (const auto &c : cells)
    for (int axis = 0; axis < 3; ++axis)
      for (const int side : {0, 1}) {
        std::array<int, 3> across = c;
        across[axis] += side ? 1 : -1;
        if (filled.count(across)) continue;  // an inner face
        // (u, v, axis) right-handed: u x v points along +axis, so the
        // outward normal is +axis on side 1 and -axis on side 0 (u, v swapped).
        int u = (axis + 1) % 3, v = (axis + 2) % 3;
        if (!side) std::swap(u, v);
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j) {
            const auto corner = [&](int di, int dj) {
              std::array<int, 3> g{c[0] * n, c[1] * n, c[2] * n};
              g[axis] += side * n;
              g[u] += i + di;
              g[v] += j + dj;
              return vertex(g);
            };
            const int p00 = corner(0, 0), p10 = corner(1, 0), p11 = corner(1, 1),
                      p01 = corner(0, 1);
            triangles.push_back({p00, p10, p11});
            triangles.push_back({p00, p11, p01});
          }
      }
  makeMesh(m, points, triangles);
}

/// A split plan of `originalVertexCount` input vertices and one inserted
/// vertex per rest position in `rests` (each between input vertices 0 and 1),
/// for a test that places new vertices by hand.
inline SplitPlan planWithInserted(std::size_t originalVertexCount, const std::vector<Vec3> &rests) {
  SplitPlan plan;
  plan.originalVertexCount = originalVertexCount;
  for (const Vec3 &rest : rests) {
    InsertedVertexSource source;
    source.original = {0, 1, 0};
    source.originalCount = 2;
    source.rest = rest;
    plan.inserted.push_back(source);
  }
  return plan;
}

}  // namespace hand_built
}  // namespace edge_sharpener
