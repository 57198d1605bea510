// Shared by the fuzz targets: runs sharpen() on a copy of a mesh and aborts
// (a finding for libFuzzer) when the result breaks an invariant of
// tests/reliability/invariants.h, or when a refused mesh was modified.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>  // before vcglib: wrap/callback.h uses strcpy without including it
#include <string>

#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/util/mesh_types.h"
#include "fuzz_fail.h"
#include "reliability/invariants.h"

namespace es_fuzz {

namespace es = edge_sharpener;

/// Sharpens a copy of `input` (compact, FF adjacency not needed) with `opt`.
inline void sharpenAndCheck(es::Mesh &input, const es::SharpenOptions &opt) {
  es::Mesh work, before;
  vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(work, input);
  vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(before, input);
  vcg::tri::UpdateTopology<es::Mesh>::FaceFace(work);
  es::SharpenReport r;
  try {
    r = es::sharpen(work, opt);
  } catch (const es::InputError &) {
    if (!es_reliability::identical(work, before)) fail("a refused mesh was modified");
    return;
  }
  const std::string problem =
      es_reliability::sharpenProblem(before, work, r, opt.degenerateAngleRad);
  if (!problem.empty()) fail(problem);
}

}  // namespace es_fuzz
