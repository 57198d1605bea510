// Google Benchmark of Edge-Sharpener on the benchmark meshes (make-bench-mesh):
//   floor/F      vcglib's UpdateTopology::FaceFace + UpdateNormal::PerFaceNormalized,
//                the unavoidable work, on the same mesh in the same binary
//   core/F/T     edge_sharpener::sharpen() on a fresh copy, T OpenMP threads
//                (counters: seconds per call between its progress callbacks)
//   extended/F, auto/F  the same with the extended and the auto method, all
//                threads
//   stages/F     the detection stages, split plan and subdivision one by one
// Usage: edge-sharpener-bench --meshes=a.ply,b.ply [benchmark flags]
// scripts/bench-performance.sh runs it and writes docs/performance.md.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "bench_mesh.h"
#include "edge_sharpener/edge_sharpener.h"
#include "edge_sharpener/util/fast_topology.h"
// (keep after the mesh headers)
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <wrap/io_trimesh/import_ply.h>

namespace {

namespace es = edge_sharpener;
using Clock = std::chrono::steady_clock;

int hardwareThreads() {
#ifdef _OPENMP
  return omp_get_num_procs();
#else
  return 1;
#endif
}

void setThreads(int n) {
#ifdef _OPENMP
  omp_set_num_threads(n);
#else
  (void)n;
#endif
}

/// The mesh last loaded (one at a time: the 4M-face mesh is large).
const es::Mesh &loadMesh(const std::string &path) {
  static std::string loaded;
  static std::unique_ptr<es::Mesh> mesh;
  if (loaded != path) {
    mesh.reset();
    mesh = std::make_unique<es::Mesh>();
    int mask = 0;
    if (vcg::tri::io::ImporterPLY<es::Mesh>::Open(*mesh, path.c_str(), mask) != 0) {
      std::fprintf(stderr, "edge-sharpener-bench: cannot read %s\n", path.c_str());
      std::exit(1);
    }
    vcg::tri::Allocator<es::Mesh>::CompactEveryVector(*mesh);
    loaded = path;
  }
  return *mesh;
}

/// A copy with twice its vertex and face counts reserved, as the command line
/// and the Python module reserve them: the subdivision appends without
/// reallocating, in every iteration of every size alike (Clear() keeps the
/// capacity of the iteration before, so a copy without spare capacity would
/// reallocate in the first iteration only, and the sizes run different
/// numbers of iterations). A reallocation's cost is the allocator's and, on a
/// virtual machine, the host's first touch of fresh pages: it varies by
/// several times from run to run.
void copyMesh(es::Mesh &dst, const es::Mesh &src) {
  dst.Clear();
  dst.vert.reserve(2 * src.vert.size());
  dst.face.reserve(2 * src.face.size());
  vcg::tri::Append<es::Mesh, es::Mesh>::MeshCopy(dst, const_cast<es::Mesh &>(src));
}

void setCommonCounters(benchmark::State &state, const es::Mesh &m) {
  state.counters["faces"] = m.fn;
  state.counters["vertices"] = m.vn;
}

/// Times step(m) on one copy of the mesh, run again and again (each run
/// rebuilds what the one before built).
template <class Step>
void benchStep(benchmark::State &state, const std::string &path, Step step) {
  es::Mesh m;
  copyMesh(m, loadMesh(path));
  for (auto _ : state) {
    const auto start = Clock::now();
    step(m);
    state.SetIterationTime(es::bench::secondsSince(start));
    benchmark::DoNotOptimize(m.face.data());
  }
  setCommonCounters(state, m);
}

void benchFloor(benchmark::State &state, const std::string &path) {
  benchStep(state, path, [](es::Mesh &m) {
    vcg::tri::UpdateTopology<es::Mesh>::FaceFace(m);
    vcg::tri::UpdateNormal<es::Mesh>::PerFaceNormalized(m);
  });
}

/// Stage laps of one sharpen() call, taken at its progress callbacks (a plain
/// function pointer, hence the globals). Between two callbacks:
///   0->5 input check + labels, 5->20 normals/angles + smooth test,
///   20->40 six filters + support planes, 40->60 split plan + subdivision,
///   60->80 placement, 80->100 cleanup + compaction + output normals.
struct ProgressLaps {
  Clock::time_point mark;
  int lastPercent = 0;
  std::map<int, double> seconds;  // keyed by the percent that ends the lap
};
ProgressLaps g_laps;

bool recordLap(const int percent, const char *) {
  const auto now = Clock::now();
  g_laps.seconds[percent] += std::chrono::duration<double>(now - g_laps.mark).count();
  g_laps.mark = now;
  return true;
}

const char *lapName(int endPercent) {
  switch (endPercent) {
    case 5: return "p05_input_check";
    case 20: return "p20_normals_angles";
    case 40: return "p40_filters";
    case 60: return "p60_plan_subdivision";
    case 80: return "p80_placement";
    case 100: return "p100_cleanup_output";
    default: return "p_other";
  }
}

/// The face-face adjacency of fast_topology.h alone (compare with floor/F).
void benchFastTopology(benchmark::State &state, const std::string &path) {
  benchStep(state, path, [](es::Mesh &m) { es::buildFaceFace(m); });
}

/// vcglib's face-face adjacency alone.
void benchVcgTopology(benchmark::State &state, const std::string &path) {
  benchStep(state, path, [](es::Mesh &m) { vcg::tri::UpdateTopology<es::Mesh>::FaceFace(m); });
}

void benchCore(benchmark::State &state, const std::string &path, int threads,
               es::SharpenOptions opt) {
  setThreads(threads);
  const es::Mesh &input = loadMesh(path);
  es::Mesh m;
  es::SharpenReport report;
  opt.progress = recordLap;
  g_laps = ProgressLaps();
  for (auto _ : state) {
    copyMesh(m, input);
    const auto start = Clock::now();
    g_laps.mark = start;
    report = es::sharpen(m, opt);
    state.SetIterationTime(es::bench::secondsSince(start));
  }
  setThreads(hardwareThreads());
  setCommonCounters(state, input);
  state.counters["threads"] = threads;
  state.counters["output_faces"] = double(report.outputFaces);
  for (const auto &[percent, seconds] : g_laps.seconds)
    state.counters[lapName(percent)] =
        benchmark::Counter(seconds, benchmark::Counter::kAvgIterations);
}

/// The first stages one at a time, to tell the split plan from the
/// subdivision (one progress lap in sharpen()). Times the run up to and
/// including subdivide().
void benchStages(benchmark::State &state, const std::string &path) {
  const es::Mesh &input = loadMesh(path);
  es::Mesh m;
  std::map<std::string, double> total;
  for (auto _ : state) {
    copyMesh(m, input);
    auto mark = Clock::now();
    double all = 0;
    const auto lap = [&](const char *stage) {
      const auto now = Clock::now();
      const double s = std::chrono::duration<double>(now - mark).count();
      total[stage] += s;
      all += s;
      mark = now;
    };
    if (!es::findInputProblem(m).empty()) state.SkipWithError("input rejected");
    lap("s1_input_check");
    es::MeshLabels<es::Mesh> labels(m);
    lap("s2_label_alloc");
    es::computeFaceNormals(m, labels);
    es::labelSmoothEdges(m, labels, 2.0);
    lap("s3_normals_angles");
    es::runSixFilters(m, labels);
    lap("s4_six_filters");
    const es::SplitPlan plan = es::planSplits(m, labels);
    lap("s5_split_plan");
    es::subdivide(m, plan, labels);
    lap("s6_subdivision");
    state.SetIterationTime(all);
  }
  setCommonCounters(state, input);
  for (const auto &[stage, seconds] : total)
    state.counters[stage] = benchmark::Counter(seconds, benchmark::Counter::kAvgIterations);
}

/// Iterations per repetition: about 3 M faces of work, at least 1.
int iterationsFor(const std::string &path) {
  const double faces = loadMesh(path).fn;
  return std::max(1, std::min(30, int(3e6 / faces)));
}

}  // namespace

int main(int argc, char **argv) {
  std::vector<std::string> meshes;
  std::vector<char *> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--meshes=", 9) == 0) {
      std::stringstream list(argv[i] + 9);
      for (std::string item; std::getline(list, item, ',');)
        if (!item.empty()) meshes.push_back(item);
    } else {
      rest.push_back(argv[i]);
    }
  }
  int restc = int(rest.size());
  benchmark::Initialize(&restc, rest.data());
  if (meshes.empty()) {
    std::fprintf(stderr, "usage: edge-sharpener-bench --meshes=a.ply,b.ply [benchmark flags]\n");
    return 2;
  }
  benchmark::AddCustomContext("omp_max_threads", std::to_string(hardwareThreads()));
  for (const std::string &path : meshes) {
    const int iterations = iterationsFor(path);
    const std::string faces = std::to_string(loadMesh(path).fn);
    // Each times its own runs (SetIterationTime: copying the mesh is left out).
    const auto timed = [&](auto *b) {
      b->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(iterations);
    };
    timed(benchmark::RegisterBenchmark(("floor/" + faces).c_str(), benchFloor, path));
    timed(benchmark::RegisterBenchmark(("vcg_ff/" + faces).c_str(), benchVcgTopology, path));
    timed(benchmark::RegisterBenchmark(("fast_ff/" + faces).c_str(), benchFastTopology, path));
    for (int t = 1; t <= hardwareThreads(); ++t)
      timed(
          benchmark::RegisterBenchmark(("core/" + faces + "/threads:" + std::to_string(t)).c_str(),
                                       benchCore, path, t, es::SharpenOptions::paperMethod()));
    es::SharpenOptions extended;
    extended.method = es::Method::Extended;
    es::SharpenOptions autoMethod;  // the default
    autoMethod.method = es::Method::Auto;
    for (const auto &[name, opt] :
         {std::pair{"extended/", extended}, std::pair{"auto/", autoMethod}})
      timed(benchmark::RegisterBenchmark((name + faces).c_str(), benchCore, path, hardwareThreads(),
                                         opt));
    timed(benchmark::RegisterBenchmark(("stages/" + faces).c_str(), benchStages, path));
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
