// OpenMP helpers shared by the stages (a serial build gets one thread).
// Every parallel loop in the core writes per-element results or per-thread
// lists merged in a fixed order, so the output never depends on the thread
// count (tests/test_determinism.cpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace edge_sharpener::detail {

inline int maxThreads() {
#ifdef _OPENMP
  return std::max(1, omp_get_max_threads());
#else
  return 1;
#endif
}

inline int threadNumber() {
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}

/// A value per thread on cache lines of its own: threads appending to
/// neighbouring vectors would otherwise keep taking the line that holds both
/// vectors' ends from each other (false sharing).
template <class T>
struct alignas(64) PerThread {
  T value;
};

/// The indices i in [0, n) where keep(i), in increasing order. Contiguous
/// ranges of indices are scanned on every core when n exceeds
/// `minParallel`, and their lists joined in order.
template <class Keep>
std::vector<std::uint32_t> indicesWhere(std::int64_t n, Keep &&keep, std::int64_t minParallel) {
  const int ranges = n > minParallel ? maxThreads() : 1;
  std::vector<PerThread<std::vector<std::uint32_t>>> parts(ranges);
#pragma omp parallel for schedule(static, 1) num_threads(ranges)
  for (int t = 0; t < ranges; ++t)
    for (std::int64_t i = n * t / ranges; i < n * (t + 1) / ranges; ++i)
      if (keep(i)) parts[t].value.push_back(std::uint32_t(i));
  std::vector<std::uint32_t> out = std::move(parts[0].value);
  for (int t = 1; t < ranges; ++t)
    out.insert(out.end(), parts[t].value.begin(), parts[t].value.end());
  return out;
}

}  // namespace edge_sharpener::detail
