// The input's surface measures (guards/surface_measures.h): the noise at the
// scale of the samples, on hand-made height fields, and the share of the area
// on planes, on hand-made face normals.
#include <gtest/gtest.h>

#include <cmath>

#include "edge_sharpener/guards/surface_measures.h"
#include "edge_sharpener/util/mesh_types.h"
#include "hand_built_meshes.h"

namespace es = edge_sharpener;

namespace {

/// The noise of a height field of 30 x 30 cells of spacing h, every vertex sampled.
template <class Height>
double heightFieldNoise(double h, Height &&height) {
  es::Mesh m;
  es::hand_built::heightField(m, 30, 30, h, height);
  return es::surfaceNoiseSpacings(m, es::VertexFaceTable(m), h, 1);
}

}  // namespace

TEST(SurfaceNoise, NoneOnAPlane) {
  EXPECT_NEAR(heightFieldNoise(0.1, [](double x, double y) { return 0.2 * x - 0.3 * y; }), 0,
              1e-5);  // float positions
}

TEST(SurfaceNoise, SmoothCurvatureCancelsBumpsOneSampleWideDoNot) {
  const double h = 0.1;
  // A cylinder-like bend of radius 2 (20 samples): its curvature is the same at every vertex.
  const double bend = heightFieldNoise(h, [](double x, double) { return 0.25 * x * x; });
  // The plane with every other vertex raised by 0.05 samples: a fused scan's ripple.
  const double bumps = heightFieldNoise(h, [&](double x, double y) {
    const long i = std::lround(x / h), j = std::lround(y / h);
    return (i + j) % 2 == 0 ? 0.05 * h : 0.0;
  });
  EXPECT_LT(bend, 0.002);
  EXPECT_GT(bumps, 0.02);
}

TEST(PlanarAreaFraction, FlatRegionsCountWholeCurvedOnesOnlyNearTheirMeanNormal) {
  const double degree = M_PI / 180;
  std::vector<es::Vec3> area;
  std::vector<int> region;
  // Region 0: four faces of area 1 (area vectors of length 2) facing +z.
  for (int k = 0; k < 4; ++k) area.push_back(es::Vec3(0, 0, 2)), region.push_back(0);
  // Region 1: four faces turning from -40 to +20 degrees about y, mean at -10.
  for (double a : {-40.0, -20.0, 0.0, 20.0}) {
    area.push_back(es::Vec3(2 * std::sin(a * degree), 0, 2 * std::cos(a * degree)));
    region.push_back(1);
  }
  // Two faces outside every region: counted in the total only.
  for (int k = 0; k < 2; ++k) area.push_back(es::Vec3(2, 0, 0)), region.push_back(-1);
  // Of 10 faces of equal area: region 0 whole, none of region 1 within 3 degrees of its mean.
  EXPECT_NEAR(es::planarAreaFraction(area, region, 3 * degree), 0.4, 1e-12);
  // Within 15 degrees of region 1's mean (-10 degrees): the faces at -20 and 0 degrees too.
  EXPECT_NEAR(es::planarAreaFraction(area, region, 15 * degree), 0.6, 1e-12);
  EXPECT_EQ(es::planarAreaFraction({}, {}, 3 * degree), 0);
}
