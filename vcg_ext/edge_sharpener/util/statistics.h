// Order statistics of a list of values, for the measures the method takes
// over many samples (medians, quantiles). Pure; they reorder their input.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace edge_sharpener::detail {

/// The median of `values` (the upper middle of an even count; 0 for none).
/// Reorders `values`.
inline double medianOf(std::vector<double> &values) {
  if (values.empty()) return 0;
  auto mid = values.begin() + values.size() / 2;
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

/// The value below which a fraction `q` (in [0, 1]) of `values` lie (the
/// nearest rank; 0 for none). Reorders `values`.
inline double quantileOf(std::vector<double> &values, double q) {
  if (values.empty()) return 0;
  auto at = values.begin() + std::size_t(std::lround(q * double(values.size() - 1)));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

}  // namespace edge_sharpener::detail
