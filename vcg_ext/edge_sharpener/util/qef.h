// The point several planes determine in the least-squares sense, with rank
// detection: dual contouring's quadric error function (Ju, Losasso, Schaefer,
// Warren, "Dual Contouring of Hermite Data", SIGGRAPH 2002). Pure.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "geometry.h"

namespace edge_sharpener {

/// The solution of one QEF: the point and the number of directions the
/// planes fix (1: a plane, 2: a line, 3: a point).
struct QefSolution {
  Vec3 point{0, 0, 0};
  int rank = 0;
};

/// Ju et al.'s truncation: a singular value below this fraction of the
/// largest fixes no direction (two planes closer than about 11 degrees meet
/// on no line that the data fix).
constexpr double kQefSingularValueCutoff = 0.1;

/// The minimiser of sum_i w_i (n_i . (x - p_i))^2 nearest `center`: the
/// stacked rows sqrt(w_i) n_i are solved by SVD relative to `center`, and
/// singular values below `cutoff` times the largest are truncated, so that
/// one plane gives center's projection on it, two their line's point
/// nearest center, three or more their corner. `weights` empty: all 1.
/// \pre planes non-empty; weights empty or of planes' size and positive.
inline QefSolution solveQef(const std::vector<Plane> &planes, const std::vector<double> &weights,
                            const Vec3 &center, double cutoff = kQefSingularValueCutoff) {
  const int n = static_cast<int>(planes.size());
  Eigen::MatrixXd a(n, 3);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) {
    const double scale = weights.empty() ? 1.0 : std::sqrt(weights[i]);
    for (int j = 0; j < 3; ++j) a(i, j) = scale * planes[i].normal[j];
    b(i) = scale * (planes[i].normal * (planes[i].point - center));
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd &sigma = svd.singularValues();
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  QefSolution out;
  for (int k = 0; k < sigma.size(); ++k) {
    if (!(sigma(k) > 0) || sigma(k) < cutoff * sigma(0)) continue;
    x += svd.matrixV().col(k) * (svd.matrixU().col(k).dot(b) / sigma(k));
    ++out.rank;
  }
  out.point = center + Vec3(x(0), x(1), x(2));
  return out;
}

}  // namespace edge_sharpener
