// Dual contouring (Ju, Losasso, Schaefer, Warren, "Dual Contouring of Hermite Data",
// SIGGRAPH 2002) with EXACT Hermite data, on the grid marchingCubes() samples: what an
// extractor could recover from the same grid if it knew the exact crossings and normals (the
// "information limit" a sharpener of marching-cubes meshes is measured against).
//
//  - Crossings: on every grid edge whose end nodes have different signs (inside = f < 0, as in
//    marchingCubes()), the root of f along the edge by bisection down to 1e-12 of a cell, then
//    one regula-falsi step in the last bracket (exact for a linear f).
//  - Normals: the given gradient function, or (the test shapes have none) central differences of
//    the exact distance function with a step of 1e-4 of a cell, divided by 16 (down to 1e-9 of a
//    cell) while two successive steps disagree by more than 1e-6: a crease closer to the crossing
//    than the step puts a kink inside the stencil, and a smaller step steps over it. On a face,
//    an exact signed distance is linear within the step, so the difference is exact up to
//    rounding (about 1e-16 / step).
//  - Vertices: one per cell with a crossing on one of its 12 edges, at the minimiser of the QEF
//    sum_i (n_i . (x - p_i))^2, by SVD of the stacked normals relative to the mass point c (the
//    mean of the crossings): x = c + V S+ U^T b with b_i = n_i . (p_i - c), singular values below
//    0.1 of the largest truncated (Ju et al.). One plane gives c's projection on it, two their
//    line's point nearest c, three or more their corner. The number kept is the vertex's rank.
//  - No clamping by default (Ju et al. do not clamp): with exact data the minimiser lies on the
//    feature (edge line, corner) even where the feature lies just outside the cell, and clamping
//    it into the cell would move it off the surface. DualContouringOptions::clampToCell clamps.
//  - Faces: one quad per sign-changing edge, joining the vertices of its 4 cells, oriented
//    outward (from the inside node to the outside one), split along its shorter diagonal.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "edge_sharpener/util/qef.h"
#include "test_meshes/shapes.h"

namespace edge_sharpener {
namespace test_meshes {

using ScalarField = std::function<double(const Point3d &)>;
/// Outward normal (gradient of the signed distance) at a surface point; need not be unit.
using NormalField = std::function<Point3d(const Point3d &)>;

struct DualContouringOptions {
  /// Singular values below this fraction of the largest are truncated (Ju et al.: 0.1).
  double singularValueCutoff = 0.1;
  /// Clamp every vertex into its cell (Ju et al. do not).
  bool clampToCell = false;
  /// Bisection stops when the bracket is shorter than this fraction of a cell.
  double rootTolerance = 1e-12;
  /// First central-difference step, as a fraction of a cell (when no normal field is given).
  double normalStep = 1e-4;
};

struct DualContouringResult {
  /// The DC mesh in double precision: vertex i belongs to cell vertexCell[i].
  TriangleList mesh;
  /// Integer coordinates of each vertex's cell (its minimum node).
  std::vector<vcg::Point3i> vertexCell;
  /// Singular values kept by the QEF solve: 1 on a face, 2 on an edge, 3 at a corner.
  std::vector<int> vertexRank;
  /// Sign-changing grid edges (= quads).
  std::size_t crossingEdges = 0;
  /// Vertices whose QEF minimiser lies outside their cell (before any clamping), and the
  /// largest such distance from the cell, in cells.
  std::size_t verticesOutsideCell = 0;
  double maxOutsideDistance = 0;
  /// Crossings whose central-difference normal needed a smaller step than the first (a crease
  /// within the first step of the crossing).
  std::size_t refinedNormals = 0;
};

namespace detail {

inline Point3d centralDifference(const ScalarField &f, const Point3d &p, double step) {
  Point3d g;
  for (int i = 0; i < 3; ++i) {
    Point3d d(0, 0, 0);
    d[i] = step;
    g[i] = (f(p + d) - f(p - d)) / (2 * step);
  }
  return g;
}

inline double maxAbsDifference(const Point3d &a, const Point3d &b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

}  // namespace detail

/// Unit outward normal of an exact signed distance `f` at `p`, by central differences with the
/// step `step`, divided by 16 (at most 4 times) while two successive steps disagree by more
/// than 1e-6 in a component. `refined` (if given) is set when a smaller step was taken.
inline Point3d signedDistanceNormal(const ScalarField &f, const Point3d &p, double step,
                                    bool *refined = nullptr) {
  Point3d g = detail::centralDifference(f, p, step);
  if (refined) *refined = false;
  for (int k = 0; k < 4; ++k) {
    step /= 16;
    const Point3d finer = detail::centralDifference(f, p, step);
    if (detail::maxAbsDifference(g, finer) < 1e-6) break;
    g = finer;
    if (refined) *refined = true;
  }
  const double norm = g.Norm();
  if (!(norm > 0)) throw std::runtime_error("dual contouring: zero gradient at a crossing");
  return g / norm;
}

/// One QEF solve (edge_sharpener::solveQef): the minimiser of sum_i (n_i . (x - p_i))^2
/// relative to the mass point of the p_i, singular values of the stacked n_i below `cutoff`
/// times the largest truncated. `rank` (if given) receives the number kept.
/// \pre points.size() == normals.size() > 0
inline Point3d solveQef(const std::vector<Point3d> &points, const std::vector<Point3d> &normals,
                        double cutoff, int *rank = nullptr) {
  Point3d c(0, 0, 0);
  for (const Point3d &p : points) c += p;
  c /= double(points.size());
  std::vector<Plane> planes(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) planes[i] = Plane{points[i], normals[i]};
  const QefSolution x = edge_sharpener::solveQef(planes, {}, c, cutoff);
  if (rank) *rank = x.rank;
  return x.point;
}

/// Dual contouring of `f` (signed distance, negative inside) on `grid`, with normals from
/// `normal` or, when it is empty, from signedDistanceNormal(). The surface must stay at least
/// one cell inside the grid. \throw std::invalid_argument otherwise.
inline DualContouringResult dualContour(const ScalarField &f, const NormalField &normal,
                                        const SamplingGrid &grid,
                                        const DualContouringOptions &options = {}) {
  const double h = grid.cellSize;
  const vcg::Point3i &n = grid.nodes;
  if (!(h > 0) || n[0] < 2 || n[1] < 2 || n[2] < 2)
    throw std::invalid_argument("dualContour: empty grid");
  auto nodeIndex = [&n](int x, int y, int z) {
    return std::size_t(x) + std::size_t(n[0]) * (std::size_t(y) + std::size_t(n[1]) * z);
  };
  // Cells are indexed by their minimum node, in the node array's layout.
  std::vector<double> value(std::size_t(n[0]) * n[1] * n[2]);
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x) value[nodeIndex(x, y, z)] = f(grid.node(x, y, z));
  auto inside = [](double v) { return v < 0; };

  struct Crossing {
    vcg::Point3i node;  // lower end
    int axis;
    bool lowerInside;
    Point3d point, normal;
  };
  std::vector<Crossing> crossings;
  DualContouringResult result;
  const double stepLength = options.normalStep * h;
  for (int axis = 0; axis < 3; ++axis)
    for (int z = 0; z < n[2]; ++z)
      for (int y = 0; y < n[1]; ++y)
        for (int x = 0; x < n[0]; ++x) {
          vcg::Point3i lower(x, y, z), upper(x, y, z);
          ++upper[axis];
          if (upper[axis] >= n[axis]) continue;
          const double f0 = value[nodeIndex(x, y, z)];
          const double f1 = value[nodeIndex(upper[0], upper[1], upper[2])];
          if (inside(f0) == inside(f1)) continue;
          // Bracket [lo, hi] in the edge parameter, f(lo) on the lower node's side.
          const Point3d p0 = grid.node(x, y, z);
          const double a0 = p0[axis], a1 = grid.node(upper[0], upper[1], upper[2])[axis];
          auto at = [&](double t) {
            Point3d p = p0;
            p[axis] = a0 + t * (a1 - a0);
            return p;
          };
          double lo = 0, hi = 1, flo = f0, fhi = f1;
          while (hi - lo > options.rootTolerance) {
            const double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            const double fm = f(at(mid));
            if (inside(fm) == inside(f0)) {
              lo = mid;
              flo = fm;
            } else {
              hi = mid;
              fhi = fm;
            }
          }
          double t = flo != fhi ? lo + (hi - lo) * flo / (flo - fhi) : 0.5 * (lo + hi);
          t = std::clamp(t, lo, hi);
          Crossing c{lower, axis, inside(f0), at(t), Point3d()};
          if (normal) {
            c.normal = normal(c.point);
            c.normal /= c.normal.Norm();
          } else {
            bool refined = false;
            c.normal = signedDistanceNormal(f, c.point, stepLength, &refined);
            if (refined) ++result.refinedNormals;
          }
          crossings.push_back(c);
        }
  result.crossingEdges = crossings.size();

  // The four cells around each crossing edge, counter-clockwise seen from the +axis side.
  auto cellsAround = [&n](const Crossing &c) {
    const int u = (c.axis + 1) % 3, v = (c.axis + 2) % 3;
    std::array<vcg::Point3i, 4> cells;
    const int du[4] = {1, 0, 0, 1}, dv[4] = {1, 1, 0, 0};
    for (int k = 0; k < 4; ++k) {
      cells[k] = c.node;
      cells[k][u] -= du[k];
      cells[k][v] -= dv[k];
      for (int i = 0; i < 3; ++i)
        if (cells[k][i] < 0 || cells[k][i] > n[i] - 2)
          throw std::invalid_argument("dualContour: the surface reaches the grid's border");
    }
    return cells;
  };
  std::vector<int> cellVertex(value.size(), -1);
  std::vector<std::vector<int>> vertexCrossings;
  for (std::size_t i = 0; i < crossings.size(); ++i)
    for (const vcg::Point3i &cell : cellsAround(crossings[i])) {
      int &vertex = cellVertex[nodeIndex(cell[0], cell[1], cell[2])];
      if (vertex < 0) {
        vertex = static_cast<int>(vertexCrossings.size());
        vertexCrossings.emplace_back();
        result.vertexCell.push_back(cell);
      }
      vertexCrossings[vertex].push_back(static_cast<int>(i));
    }

  std::vector<Point3d> points, normals;
  for (std::size_t v = 0; v < vertexCrossings.size(); ++v) {
    points.clear();
    normals.clear();
    for (int i : vertexCrossings[v]) {
      points.push_back(crossings[i].point);
      normals.push_back(crossings[i].normal);
    }
    int rank = 0;
    Point3d x = solveQef(points, normals, options.singularValueCutoff, &rank);
    const vcg::Point3i &cell = result.vertexCell[v];
    const Point3d lo = grid.node(cell[0], cell[1], cell[2]);
    const Point3d hi = grid.node(cell[0] + 1, cell[1] + 1, cell[2] + 1);
    double outside = 0;
    for (int i = 0; i < 3; ++i) outside = std::max({outside, lo[i] - x[i], x[i] - hi[i]});
    if (outside > 0) {
      ++result.verticesOutsideCell;
      result.maxOutsideDistance = std::max(result.maxOutsideDistance, outside / h);
      if (options.clampToCell)
        for (int i = 0; i < 3; ++i) x[i] = std::clamp(x[i], lo[i], hi[i]);
    }
    result.mesh.addVertex(x);
    result.vertexRank.push_back(rank);
  }

  for (const Crossing &c : crossings) {
    const std::array<vcg::Point3i, 4> cells = cellsAround(c);
    std::array<int, 4> q;
    for (int k = 0; k < 4; ++k) q[k] = cellVertex[nodeIndex(cells[k][0], cells[k][1], cells[k][2])];
    // Counter-clockwise seen from +axis faces +axis: right when the lower node is inside.
    if (!c.lowerInside) std::swap(q[1], q[3]);
    const std::vector<Point3d> &p = result.mesh.vertices;
    if ((p[q[0]] - p[q[2]]).SquaredNorm() <= (p[q[1]] - p[q[3]]).SquaredNorm()) {
      result.mesh.addTriangle(q[0], q[1], q[2]);
      result.mesh.addTriangle(q[0], q[2], q[3]);
    } else {
      result.mesh.addTriangle(q[0], q[1], q[3]);
      result.mesh.addTriangle(q[1], q[2], q[3]);
    }
  }
  return result;
}

/// Dual contouring of a test shape on the grid of marchingCubes(shape, cellSize).
inline DualContouringResult dualContour(const Shape &shape, double cellSize,
                                        const DualContouringOptions &options = {}) {
  return dualContour(shape.signedDistance, NormalField(), marchingCubesGrid(shape, cellSize),
                     options);
}

/// `triangles` as a vcg mesh; FF adjacency (when the mesh has it), normals and bounding box
/// updated. Faces are kept as they are (a DC mesh can have zero-area faces).
template <class M>
void toVcgMesh(const TriangleList &triangles, M &mesh) {
  mesh.Clear();
  auto vertex = vcg::tri::Allocator<M>::AddVertices(mesh, triangles.vertices.size());
  for (const Point3d &p : triangles.vertices) (vertex++)->P().Import(p);
  auto face = vcg::tri::Allocator<M>::AddFaces(mesh, triangles.triangles.size());
  for (const auto &t : triangles.triangles) {
    for (int i = 0; i < 3; ++i) face->V(i) = &mesh.vert[t[i]];
    ++face;
  }
  if (vcg::tri::HasFFAdjacency(mesh)) vcg::tri::UpdateTopology<M>::FaceFace(mesh);
  vcg::tri::UpdateNormal<M>::PerVertexNormalizedPerFaceNormalized(mesh);
  vcg::tri::UpdateBounding<M>::Box(mesh);
}

}  // namespace test_meshes
}  // namespace edge_sharpener
