// OpenMP helpers shared by the stages (a serial build gets one thread).
// Every parallel loop in the core writes per-element results or per-thread
// lists merged in a fixed order, so the output never depends on the thread
// count (tests/test_determinism.cpp).
#pragma once

#include <algorithm>
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

}  // namespace edge_sharpener::detail
