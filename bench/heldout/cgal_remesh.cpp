// cgal-remesh: the held-out check's two CGAL samplers (bench/heldout/cgal_remesh.py builds it).
//
//   cgal-remesh isotropic FRACTION IN.off OUT.off   Polygon Mesh Processing's isotropic
//       remeshing, target edge length FRACTION of IN's bounding-box diagonal, features not
//       protected (CGAL's default), vertices projected back onto IN (its default), 5 iterations.
//   cgal-remesh wrap FRACTION IN.off OUT.off        3D Alpha Wrapping, alpha FRACTION of the
//       diagonal, offset alpha / 30.
//
// Exits non-zero with a message when IN cannot be read or is not a closed triangle mesh.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

double diagonal(const Mesh &mesh) {
  const CGAL::Bbox_3 box = PMP::bbox(mesh);
  const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(),
               dz = box.zmax() - box.zmin();
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

int fail(const std::string &why) {
  std::cerr << "cgal-remesh: " << why << "\n";
  return 1;
}

}  // namespace

int main(int argc, char **argv) {
  if (argc != 5) return fail("usage: cgal-remesh isotropic|wrap FRACTION IN.off OUT.off");
  const std::string mode = argv[1];
  const double fraction = std::atof(argv[2]);
  if (!(fraction > 0)) return fail("FRACTION must be positive");
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(argv[3], mesh) || mesh.is_empty())
    return fail(std::string("cannot read ") + argv[3]);
  if (!CGAL::is_triangle_mesh(mesh) || !CGAL::is_closed(mesh))
    return fail(std::string(argv[3]) + " is not a closed triangle mesh");
  const double length = fraction * diagonal(mesh);

  Mesh out;
  if (mode == "isotropic") {
    out = mesh;
    PMP::isotropic_remeshing(faces(out), length, out, CGAL::parameters::number_of_iterations(5));
  } else if (mode == "wrap") {
    CGAL::alpha_wrap_3(mesh, length, length / 30, out);
  } else {
    return fail("unknown mode " + mode);
  }
  if (!CGAL::IO::write_polygon_mesh(argv[4], out, CGAL::parameters::stream_precision(17)))
    return fail(std::string("cannot write ") + argv[4]);
  return 0;
}
