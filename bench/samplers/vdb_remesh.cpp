// vdb-remesh IN OUT --voxel-fraction F [--project]: the voxel remesher users meet in Blender
// and Houdini. The input mesh becomes an OpenVDB narrow-band level set (tools::meshToLevelSet,
// voxel size = F x the input's bounding-box diagonal), which tools::volumeToMesh turns back into
// a surface at iso-value 0 with adaptivity 0 (one vertex per cell, quads), quads split into
// triangles. It cuts every sharp edge into a chamfer, like marching cubes: one of the quality
// benchmark's sampler families (issue 19).
//
// --project emulates Blender 3.4's voxel remesh with "Preserve Volume" on (its default), the
// "vdbproj" family, as Blender's source does it (object_remesh.cc voxel_remesh_exec,
// mesh_remesh_voxel.cc, shrinkwrap.cc BKE_shrinkwrap_remesh_target_project): the level set has
// a half-width of 1 voxel and the voxel size is a float; the surface is taken 0.3 voxel outside
// (isovalue = 0.3 x voxel); the faces keep Blender's winding (OpenVDB's reversed) and every
// vertex gets Blender's normal (Newell face normals weighted by the corner angles); each vertex
// is then cast along its normal both ways onto the input (shrinkwrap "Project", no culling) and
// moved to the nearer hit, or left where it is when there is none within 5 voxels; the quads
// are split as bmesh's triangulate (Beauty) splits them. The volume and the split are computed
// on the input scaled as the held-out check hands it to Blender (bench/heldout/blender_remesh.py:
// times the power of two that puts the diagonal in [1, 2)). The rays use vcglib's uniform grid
// and its ray iterator. Writes binary PLY.
#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "edge_sharpener/util/mesh_types.h"
#include "mesh_io.h"
// (vcglib's algorithm headers need complex.h, included above, first)
#include <vcg/complex/algorithms/closest.h>
#include <vcg/space/index/grid_static_ptr.h>
#include <vcg/space/index/space_iterators.h>

namespace {

struct TriangleMesh {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
};

/// The triangles of `m` (read from `path`, bounding box updated) in OpenVDB's form.
TriangleMesh readTriangles(const std::string &path, edge_sharpener::Mesh &m) {
  edge_sharpener::io::loadMesh(path, m);
  vcg::tri::UpdateBounding<edge_sharpener::Mesh>::Box(m);
  TriangleMesh out;
  out.points.reserve(m.vert.size());
  for (const auto &v : m.vert) out.points.emplace_back(v.cP().X(), v.cP().Y(), v.cP().Z());
  for (const auto &f : m.face) {
    if (f.IsD()) continue;
    out.triangles.emplace_back(static_cast<unsigned>(vcg::tri::Index(m, f.cV(0))),
                               static_cast<unsigned>(vcg::tri::Index(m, f.cV(1))),
                               static_cast<unsigned>(vcg::tri::Index(m, f.cV(2))));
  }
  return out;
}

// ---- Blender 3.4's voxel remesh with Preserve Volume (--project) ----

using Vec3f = openvdb::Vec3s;

/// A face of the remeshed mesh with its corners in Blender's order (mesh_remesh_voxel.cc takes
/// OpenVDB's quads and triangles in reverse): 3 or 4 corners.
struct Polygon {
  std::array<unsigned, 4> v;
  int size;
};

/// Scales `v` to unit length and returns true, or leaves it and returns false when it is
/// (almost) zero, as Blender's normalize_v3 tells them apart.
bool normalizeInPlace(Vec3f &v) {
  const float d = v.dot(v);
  if (!(d > 1.0e-35f)) return false;
  v *= 1.0f / std::sqrt(d);
  return true;
}

/// Blender's vertex normals of the remeshed mesh (mesh_normals.cc): each face's normal by
/// Newell's method, added to its corners weighted by the corner's angle, normalized; a vertex
/// whose sum vanishes takes its normalized position.
std::vector<Vec3f> blenderVertexNormals(const std::vector<Vec3f> &p,
                                        const std::vector<Polygon> &polys) {
  std::vector<Vec3f> sum(p.size(), Vec3f(0.0f));
  for (const auto &f : polys) {
    Vec3f n(0.0f);
    for (int i = 0; i < f.size; ++i) {
      const Vec3f &a = p[f.v[(i + f.size - 1) % f.size]], &b = p[f.v[i]];
      n[0] += (a[1] - b[1]) * (a[2] + b[2]);
      n[1] += (a[2] - b[2]) * (a[0] + b[0]);
      n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    if (!normalizeInPlace(n)) n = Vec3f(0.0f, 0.0f, 1.0f);
    for (int i = 0; i < f.size; ++i) {
      const Vec3f &at = p[f.v[i]];
      Vec3f toPrev = p[f.v[(i + f.size - 1) % f.size]] - at, toNext = p[f.v[(i + 1) % f.size]] - at;
      normalizeInPlace(toPrev);
      normalizeInPlace(toNext);
      const float angle = std::acos(std::clamp(toPrev.dot(toNext), -1.0f, 1.0f));
      sum[f.v[i]] += n * angle;
    }
  }
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!normalizeInPlace(sum[i])) {
      sum[i] = p[i];
      if (!normalizeInPlace(sum[i])) sum[i] = Vec3f(0.0f);
    }
  return sum;
}

/// Ray-triangle test for vcglib's ray iterator: both sides of the triangle, edges included, the
/// hit's distance along the ray (>= 0) in `t`, computed in double precision without an absolute
/// tolerance (vcglib's own functor rejects triangles under 1e-6 square units, which the small
/// inputs are made of). Blender's ray cast (watertight, BLI_kdopbvh) culls no side either.
struct TwoSidedRayTriangle {
  template <class Face, class S>
  bool operator()(const Face &f, const vcg::Ray3<S> &ray, S &t) const {
    const auto o = vcg::Point3d::Construct(ray.Origin());
    const auto d = vcg::Point3d::Construct(ray.Direction());
    const auto a = vcg::Point3d::Construct(f.cP(0));
    const vcg::Point3d e1 = vcg::Point3d::Construct(f.cP(1)) - a;
    const vcg::Point3d e2 = vcg::Point3d::Construct(f.cP(2)) - a;
    const vcg::Point3d pv = d ^ e2;
    const double det = e1 * pv;
    if (det == 0 || !std::isfinite(det)) return false;
    const vcg::Point3d tv = o - a;
    const double u = (tv * pv) / det;
    if (u < 0 || u > 1) return false;
    const vcg::Point3d qv = tv ^ e1;
    const double v = (d * qv) / det;
    if (v < 0 || u + v > 1) return false;
    const double along = (e2 * qv) / det;
    if (!(along >= 0)) return false;
    t = static_cast<S>(along);
    return true;
  }
};

struct ProjectionStats {
  std::size_t moved = 0, kept = 0;
  double longest = 0;
};

/// Blender's Preserve Volume projection (BKE_shrinkwrap_remesh_target_project: shrinkwrap
/// "Project" along the vertex normal, positive and negative direction, on surface, no offset,
/// limit 5 voxels): every point is cast along its normal both ways onto `surface` and moved to
/// the nearer hit (the positive one on a tie); a point whose nearer hit is farther than `limit`,
/// or that has none, stays where it is.
ProjectionStats projectAlongNormals(edge_sharpener::Mesh &surface, std::vector<Vec3f> &points,
                                    const std::vector<Vec3f> &normals, float limit) {
  using Mesh = edge_sharpener::Mesh;
  using Scalar = Mesh::ScalarType;
  using Coord = Mesh::CoordType;
  using Grid = vcg::GridStaticPtr<Mesh::FaceType, Scalar>;
  using Marker = vcg::tri::FaceTmark<Mesh>;
  using Rays = vcg::RayIterator<Grid, TwoSidedRayTriangle, Marker>;
  vcg::Box3<Scalar> span = surface.bbox;
  for (const auto &p : points) span.Add(Coord(p.x(), p.y(), p.z()));
  span.Offset(2 * limit + span.Diag() * Scalar(0.01));
  Grid grid;
  grid.Set(surface.face.begin(), surface.face.end(), span);
  TwoSidedRayTriangle hitTest;
  Marker marker(&surface);
  // The iterator can drop hits that lie past the corner of the last cell it visits: search two
  // cells further than the limit, which is applied after.
  const Scalar reach = limit + 2 * grid.voxel.Norm();
  const auto nearestHit = [&](const Coord &origin, const Coord &direction) {
    Rays rays(grid, hitTest, reach);
    rays.SetMarker(marker);
    rays.Init(vcg::Ray3<Scalar>(origin, direction));
    Scalar best = std::numeric_limits<Scalar>::infinity();
    for (; !rays.End(); ++rays) best = std::min(best, rays.Dist());
    return best;
  };
  ProjectionStats stats;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3f &n = normals[i];
    if (n.dot(n) == 0.0f) {
      ++stats.kept;
      continue;
    }
    const Coord origin(points[i].x(), points[i].y(), points[i].z()), dir(n.x(), n.y(), n.z());
    const Scalar ahead = nearestHit(origin, dir), behind = nearestHit(origin, -dir);
    const bool back = behind < ahead;
    const Scalar t = back ? behind : ahead;
    const Vec3f hit = points[i] + (back ? -n : n) * static_cast<float>(t);
    if (!std::isfinite(t) || (hit - points[i]).lengthSqr() > limit * limit) {
      ++stats.kept;
      continue;
    }
    stats.longest = std::max(stats.longest, static_cast<double>((hit - points[i]).length()));
    points[i] = hit;
    ++stats.moved;
  }
  return stats;
}

/// Blender's is_quad_flip_v3: bit 0 when the diagonal a-c splits the quad into triangles that
/// face apart, bit 1 when b-d does.
int quadFlip(const Vec3f &a, const Vec3f &b, const Vec3f &c, const Vec3f &d) {
  const Vec3f ab = a - b, bc = b - c, cd = c - d, da = d - a;
  int flip = 0;
  if (ab.cross(bc).dot(cd.cross(da)) < 0.0f) flip |= 1;
  if (bc.cross(cd).dot(da.cross(ab)) < 0.0f) flip |= 2;
  return flip;
}

/// Twice the signed area of the 2D triangle (p, q, r) (Blender's cross_tri_v2).
float area2(const std::array<float, 2> &p, const std::array<float, 2> &q,
            const std::array<float, 2> &r) {
  return (p[0] - q[0]) * (q[1] - r[1]) + (p[1] - q[1]) * (r[0] - q[0]);
}

float distance2(const std::array<float, 2> &p, const std::array<float, 2> &q) {
  const float dx = p[0] - q[0], dy = p[1] - q[1];
  return std::sqrt(dx * dx + dy * dy);
}

/// bmesh's Beauty cost of trading the diagonal 2-4 of the quad (v1, v2, v3, v4) for 1-3
/// (BM_verts_calc_rotate_beauty, area method, after BLI_polyfill_beautify_quad_rotate_calc):
/// the quad is laid flat on the plane of its two triangles' summed normal, and each split is
/// scored by its triangles' area over perimeter; negative when 1-3 scores better, FLT_MAX when the
/// quad cannot be judged.
float rotateBeautyCost(const Vec3f &v1, const Vec3f &v2, const Vec3f &v3, const Vec3f &v4) {
  Vec3f n = (v2 - v3).cross(v3 - v4) + (v2 - v4).cross(v4 - v1);
  const float length = n.length();
  if (!(length > FLT_EPSILON)) return FLT_MAX;
  n *= 1.0f / length;
  // Any orthonormal basis of the plane gives the same lengths and the same signs up to one flip.
  Vec3f e1, e2;
  const float xy = n[0] * n[0] + n[1] * n[1];
  if (xy > FLT_EPSILON) {
    const float k = 1.0f / std::sqrt(xy);
    e1 = Vec3f(n[1] * k, -n[0] * k, 0.0f);
    e2 = n.cross(e1);
  } else {
    e1 = Vec3f(n[2] < 0.0f ? -1.0f : 1.0f, 0.0f, 0.0f);
    e2 = Vec3f(0.0f, 1.0f, 0.0f);
  }
  const auto flat = [&](const Vec3f &v) { return std::array<float, 2>{e1.dot(v), e2.dot(v)}; };
  const auto p1 = flat(v1), p2 = flat(v2), p3 = flat(v3), p4 = flat(v4);
  const auto side = [](float x) { return x > 1e-5f ? 1 : (x < -1e-5f ? -1 : 0); };
  // Triangles already facing apart (or both degenerate): not judged.
  if (side(area2(p2, p3, p4) / length) + side(area2(p2, p4, p1) / length) == 0) return FLT_MAX;
  const float zero = 1e-12f;
  const float a234 = area2(p2, p3, p4), a241 = area2(p2, p4, p1);
  const float a123 = area2(p1, p2, p3), a134 = area2(p1, p3, p4);
  if ((a123 >= 0.0f) != (a134 >= 0.0f)) return FLT_MAX;
  if (std::fabs(a123) <= zero || std::fabs(a134) <= zero) return FLT_MAX;
  if ((a234 >= 0.0f) != (a241 >= 0.0f)) return -FLT_MAX;
  if (std::fabs(a234) <= zero || std::fabs(a241) <= zero) return -FLT_MAX;
  const float l12 = distance2(p1, p2), l23 = distance2(p2, p3), l34 = distance2(p3, p4);
  const float l41 = distance2(p4, p1), l13 = distance2(p1, p3), l24 = distance2(p2, p4);
  const float keep = std::fabs(a234) / (l23 + l34 + l24) + std::fabs(a241) / (l41 + l12 + l24);
  const float trade = std::fabs(a123) / (l12 + l23 + l13) + std::fabs(a134) / (l34 + l41 + l13);
  return keep - trade;
}

/// The faces split into triangles as bmesh.ops.triangulate splits them with its defaults
/// (BM_face_triangulate, quad method Beauty), judged on the coordinates times `scale`.
std::vector<openvdb::Vec3I> triangulateBeauty(const std::vector<Vec3f> &p,
                                              const std::vector<Polygon> &polys, float scale) {
  std::vector<openvdb::Vec3I> out;
  out.reserve(2 * polys.size());
  for (const auto &f : polys) {
    const unsigned c0 = f.v[0], c1 = f.v[1], c2 = f.v[2], c3 = f.v[3];
    if (f.size == 3) {
      out.emplace_back(c0, c1, c2);
      continue;
    }
    // bmesh names the corners from the second: v1..v4 = c1, c2, c3, c0.
    const Vec3f v1 = p[c1] * scale, v2 = p[c2] * scale, v3 = p[c3] * scale, v4 = p[c0] * scale;
    const int flip = quadFlip(v1, v2, v3, v4);
    const bool split24 = (flip & 1)   ? true
                         : (flip & 2) ? false
                                      : rotateBeautyCost(v1, v2, v3, v4) > 0.0f;
    if (split24) {  // diagonal c0-c2
      out.emplace_back(c0, c1, c2);
      out.emplace_back(c0, c2, c3);
    } else {  // diagonal c1-c3
      out.emplace_back(c1, c2, c3);
      out.emplace_back(c1, c3, c0);
    }
  }
  return out;
}

/// Six times the signed volume the triangles enclose: positive when they face outwards.
double signedVolume6(const TriangleMesh &m) {
  double sum = 0;
  for (const auto &t : m.triangles) {
    const openvdb::Vec3d a(m.points[t[0]]), b(m.points[t[1]]), c(m.points[t[2]]);
    sum += a.dot(b.cross(c));
  }
  return sum;
}

/// (boundary edges, edges with more than two faces): a closed 2-manifold has neither, and the
/// sharpener refuses a mesh that has any.
std::pair<std::size_t, std::size_t> edgeCounts(const TriangleMesh &m) {
  std::vector<std::pair<unsigned, unsigned>> edges;
  edges.reserve(3 * m.triangles.size());
  for (const auto &t : m.triangles)
    for (int i = 0; i < 3; ++i) {
      const unsigned a = t[i], b = t[(i + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  std::size_t boundary = 0, nonManifold = 0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) ++boundary;
    if (j - i > 2) ++nonManifold;
    i = j;
  }
  return {boundary, nonManifold};
}

void writeBinaryPly(const std::string &path, const TriangleMesh &m) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(path + ": cannot write file");
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << m.points.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
      << m.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto &p : m.points) out.write(reinterpret_cast<const char *>(p.asPointer()), 12);
  for (const auto &t : m.triangles) {
    const unsigned char three = 3;
    const int idx[3] = {static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])};
    out.write(reinterpret_cast<const char *>(&three), 1);
    out.write(reinterpret_cast<const char *>(idx), 12);
  }
  if (!out) throw std::runtime_error(path + ": cannot write file");
}

/// The plain voxel remesh (no --project): level set of half-width 3, iso-value 0, quads split
/// along q0-q2, faces turned to face outwards.
TriangleMesh plainRemesh(const TriangleMesh &input, double voxel, std::size_t &quadCount) {
  auto transform = openvdb::math::Transform::createLinearTransform(voxel);
  // World-space points: meshToLevelSet converts them to index space with the transform.
  const auto grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(
      *transform, input.points, input.triangles, /*halfWidth=*/3.0f);

  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, points, triangles, quads, /*isovalue=*/0.0,
                               /*adaptivity=*/0.0);
  TriangleMesh out;
  out.points = std::move(points);
  out.triangles = std::move(triangles);
  for (const auto &q : quads) {
    out.triangles.emplace_back(q[0], q[1], q[2]);
    out.triangles.emplace_back(q[0], q[2], q[3]);
  }
  quadCount = quads.size();
  if (out.triangles.empty()) throw std::runtime_error("volumeToMesh made no faces");
  // OpenVDB winds its faces the other way round from the input's (Houdini's convention).
  if (signedVolume6(out) < 0)
    for (auto &t : out.triangles) std::swap(t[1], t[2]);
  return out;
}

/// Blender 3.4's voxel remesh with Preserve Volume, triangulated (see the top of the file), as
/// the held-out check runs it: on the input times `scale`, the power of two that puts its
/// diagonal in [1, 2) (exact both ways). OpenVDB's meshToLevelSet is not scale-invariant (at
/// abc6's size, diagonal 0.0074, its surface at iso-value 0 lies 0.0013 voxel further out than
/// at the scaled size), so the level set is made at that scale too.
TriangleMesh blenderRemesh(const TriangleMesh &input, edge_sharpener::Mesh &source, float voxel,
                           float isovalue, float scale, std::size_t &quadCount,
                           ProjectionStats &stats) {
  std::vector<openvdb::Vec3s> scaled = input.points;
  for (auto &p : scaled) p *= scale;
  auto transform = openvdb::math::Transform::createLinearTransform(voxel * scale);
  const auto grid = openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(
      *transform, scaled, input.triangles, /*halfWidth=*/1.0f);
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*grid, points, triangles, quads, isovalue * scale,
                               /*adaptivity=*/0.0, /*relaxDisorientedTriangles=*/false);
  if (quads.empty() && triangles.empty()) throw std::runtime_error("volumeToMesh made no faces");
  for (auto &p : points) p *= 1.0f / scale;
  std::vector<Polygon> polys;
  polys.reserve(quads.size() + triangles.size());
  for (const auto &q : quads) polys.push_back({{q[0], q[3], q[2], q[1]}, 4});
  for (const auto &t : triangles) polys.push_back({{t[2], t[1], t[0], 0}, 3});
  quadCount = quads.size();
  const std::vector<Vec3f> normals = blenderVertexNormals(points, polys);
  stats = projectAlongNormals(source, points, normals, voxel * 5.0f);
  TriangleMesh out;
  out.triangles = triangulateBeauty(points, polys, scale);
  out.points = std::move(points);
  if (signedVolume6(out) < 0)
    for (auto &t : out.triangles) std::swap(t[1], t[2]);
  return out;
}

}  // namespace

int main(int argc, char **argv) {
  bool project = false;
  const char *fractionArg = nullptr;
  std::vector<std::string> positional;
  bool usage = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--project")
      project = true;
    else if (arg == "--voxel-fraction" && i + 1 < argc)
      fractionArg = argv[++i];
    else if (arg.rfind("--", 0) == 0)
      usage = true;
    else
      positional.push_back(arg);
  }
  if (usage || positional.size() != 2 || fractionArg == nullptr) {
    std::fprintf(stderr,
                 "usage: vdb-remesh IN OUT.ply --voxel-fraction F [--project]\n"
                 "  OpenVDB meshToLevelSet + volumeToMesh (adaptivity 0, quads triangulated),\n"
                 "  voxel size = F x the input's bounding-box diagonal.\n"
                 "  --project: as Blender 3.4's voxel remesh with Preserve Volume: surface 0.3\n"
                 "  voxel outside, every vertex cast along its normal both ways onto IN's surface\n"
                 "  (kept when no hit within 5 voxels), quads split as bmesh's Beauty.\n");
    return 2;
  }
  try {
    const double fraction = std::atof(fractionArg);
    if (!(fraction > 0 && fraction < 1))
      throw std::runtime_error("--voxel-fraction must be in (0, 1)");
    openvdb::initialize();
    edge_sharpener::Mesh source;
    const TriangleMesh input = readTriangles(positional[0], source);
    const double diagonal = source.bbox.Diag();
    if (!(diagonal > 0) || input.triangles.empty()) throw std::runtime_error("empty input mesh");
    std::size_t quadCount = 0;
    ProjectionStats stats;
    double voxel = fraction * diagonal;
    float isovalue = 0.0f;
    TriangleMesh out;
    if (project) {
      // Blender keeps the voxel size as a float and meshes at 0.3 of it.
      const float voxelF = static_cast<float>(voxel);
      voxel = voxelF;
      isovalue = voxelF * 0.3f;
      const auto scale = static_cast<float>(std::exp2(-std::floor(std::log2(diagonal))));
      out = blenderRemesh(input, source, voxelF, isovalue, scale, quadCount, stats);
    } else {
      out = plainRemesh(input, voxel, quadCount);
    }
    writeBinaryPly(positional[1], out);
    const auto [boundary, nonManifold] = edgeCounts(out);
    std::string projected;
    if (project) {
      char buf[160];
      std::snprintf(buf, sizeof buf,
                    ", \"isovalue\": %.9g, \"projected\": %zu, \"unprojected\": %zu, "
                    "\"projected_max_move\": %.9g",
                    isovalue, stats.moved, stats.kept, stats.longest);
      projected = buf;
    }
    std::printf(
        "{\"voxel\": %.9g, \"vertices\": %zu, \"faces\": %zu, \"quads\": %zu, "
        "\"boundary_edges\": %zu, \"non_manifold_edges\": %zu, \"closed_manifold\": %s%s}\n",
        voxel, out.points.size(), out.triangles.size(), quadCount, boundary, nonManifold,
        boundary == 0 && nonManifold == 0 ? "true" : "false", projected.c_str());
  } catch (const std::exception &e) {
    std::fprintf(stderr, "vdb-remesh: %s\n", e.what());
    return 1;
  }
  return 0;
}
