// Shared by the fuzz targets: a broken invariant aborts, which libFuzzer
// reports as a finding (and the ctest replay as a failed test).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace es_fuzz {

[[noreturn]] inline void fail(const std::string &what) {
  std::fprintf(stderr, "fuzz invariant violated: %s\n", what.c_str());
  std::abort();
}

}  // namespace es_fuzz
