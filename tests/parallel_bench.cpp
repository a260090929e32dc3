// Speed-up of the parallel propagation and of independent queries in parallel, each against
// one thread measured in the same benchmark (issue: on a 2-core machine at least 1.6x with 2
// threads for a 1M-vertex mesh with 1000 sources, at least 1.8x for 16 independent
// single-source queries, no slowdown on a 10k-vertex mesh with the default thread count).
// A program, not a test (wall time; run it on an otherwise idle machine):
//   build/bin/parallel_bench [--benchmark_filter=...]
// Meshes: the bundled fertility split 4-to-1 (k times): k = 4 gives 1,151,994 vertices.
#include "helpers/geodesic_fixtures.hpp"

#include <gsp/batch.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>

namespace {

using namespace gsp;
using Clock = std::chrono::steady_clock;

const GeodesicSolver& solver(int splits) {
  static std::map<int, std::unique_ptr<GeodesicSolver>> cache;
  auto& s = cache[splits];
  if (!s) {
    TriangleMesh m = io::read_mesh(std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off").mesh;
    for (int i = 0; i < splits; ++i) m = midpoint_subdivide(m);
    s = std::make_unique<GeodesicSolver>(m);
  }
  return *s;
}

std::vector<Source> sources(std::size_t vertices, int n) {
  test::SplitMix rng{42};
  std::vector<Source> s;
  for (int i = 0; i < n; ++i) s.push_back(Source::at_vertex(Index(rng.next() % vertices)));
  return s;
}

template <class F>
double median_seconds(int runs, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = Clock::now();
    f();
    t.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// One propagation from range(1) sources on fertility split range(0) times, range(2) threads
// (0 = automatic), against one thread.
void BM_Propagation(benchmark::State& state) {
  const GeodesicSolver& s = solver(int(state.range(0)));
  const std::size_t nv = s.num_vertices();
  const std::vector<Source> src = sources(nv, int(state.range(1)));
  GeodesicOptions one, many;
  one.threads = 1;
  many.threads = unsigned(state.range(2));
  const double t1 = median_seconds(3, [&] { benchmark::DoNotOptimize(s.compute(src, one)); });
  double total = 0;
  std::size_t runs = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    benchmark::DoNotOptimize(s.compute(src, many));
    const double t = std::chrono::duration<double>(Clock::now() - t0).count();
    total += t, ++runs;
    state.SetIterationTime(t);
  }
  state.counters["vertices"] = double(nv);
  state.counters["one_thread_s"] = t1;
  state.counters["speedup"] = t1 / (total / double(runs));
}

// 16 independent single-source queries (compute_many) on range(1) threads against one.
void BM_Independent(benchmark::State& state) {
  const GeodesicSolver& s = solver(int(state.range(0)));
  std::vector<std::vector<Source>> queries;
  for (const Source& x : sources(s.num_vertices(), 16)) queries.push_back({x});
  const double t1 = median_seconds(3, [&] { benchmark::DoNotOptimize(compute_many(s, queries, {}, 1)); });
  double total = 0;
  std::size_t runs = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    benchmark::DoNotOptimize(compute_many(s, queries, {}, unsigned(state.range(1))));
    const double t = std::chrono::duration<double>(Clock::now() - t0).count();
    total += t, ++runs;
    state.SetIterationTime(t);
  }
  state.counters["one_thread_s"] = t1;
  state.counters["speedup"] = t1 / (total / double(runs));
}

}  // namespace

// fertility split 4x (1.15M vertices), 1000 sources, 2 threads; split 1x (18k vertices) with
// the default thread count (automatic: one thread below kParallelMinFaces).
BENCHMARK(BM_Propagation)->Args({4, 1000, 2})->Args({4, 1, 2})->Args({1, 1, 0})->UseManualTime()->Iterations(5)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Independent)->Args({2, 2})->UseManualTime()->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
