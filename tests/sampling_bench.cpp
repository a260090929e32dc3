// Speed of geodesic Poisson-disk sampling against one all-destination GSP on the same mesh,
// measured in the same run (issue: 10,000 samples on a 1M-vertex benign mesh in less than 5x
// one full propagation). A program, not a test: run it with
//   build/bin/sampling_bench [--benchmark_repetitions=3]
// The mesh is the bundled fertility split 4-to-1 four times (1,151,994 vertices, 2.3M faces).
// Each benchmark reports `x_full_gsp`: its time over the median of 5 full propagations
// timed right before it, both in process CPU seconds (everything here is single-threaded; on
// a shared machine wall time depends on the neighbours, CPU time much less).
#include "helpers/mesh_builders.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/sampling/sampler.hpp>

#include <benchmark/benchmark.h>

#include <ctime>

#include <algorithm>
#include <cmath>

namespace {

using namespace gsp;

double cpu_seconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

const sampling::Sampler& sampler() {
  static const TriangleMesh mesh = [] {
    TriangleMesh m = io::read_mesh(std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off").mesh;
    for (int i = 0; i < 4; ++i) m = midpoint_subdivide(m);
    return m;
  }();
  static const sampling::Sampler s(mesh);
  return s;
}

double full_gsp_seconds() {
  std::vector<double> t;
  for (int i = 0; i < 5; ++i) {
    const double t0 = cpu_seconds();
    benchmark::DoNotOptimize(sampler().solver().compute({Source::at_vertex(Index(i * 1000))}));
    t.push_back(cpu_seconds() - t0);
  }
  std::nth_element(t.begin(), t.begin() + 2, t.end());
  return t[2];
}

void BM_FullGsp(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(sampler().solver().compute({Source::at_vertex(0)}));
  state.counters["vertices"] = double(sampler().mesh().num_vertices());
}

// Dart throwing with the radius that gives about `samples` samples (Poisson-disk sampling
// packs about 2.19 samples per disk of the hexagonal-packing formula's radius).
void BM_Poisson(benchmark::State& state) {
  const double reference = full_gsp_seconds();
  const double n = double(state.range(0));
  sampling::SamplingOptions o;
  o.radius = std::sqrt(2.19 * sampler().area() / (2 * std::sqrt(3.0) * n));
  double total = 0;
  std::size_t runs = 0, count = 0;
  for (auto _ : state) {
    const double t0 = cpu_seconds();
    const sampling::SamplingResult r = sampler().sample(o);
    total += cpu_seconds() - t0, ++runs;
    count = r.samples.size();
    state.counters["faces_reached_over_mesh"] = double(r.stats.faces_reached) / double(sampler().mesh().num_faces());
  }
  state.counters["samples"] = double(count);
  state.counters["full_gsp_s"] = reference;
  state.counters["x_full_gsp"] = total / double(runs) / reference;
}

void BM_Farthest(benchmark::State& state) {
  const double reference = full_gsp_seconds();
  sampling::SamplingOptions o;
  o.mode = sampling::Mode::farthest;
  o.count = std::size_t(state.range(0));
  double total = 0;
  std::size_t runs = 0;
  for (auto _ : state) {
    const double t0 = cpu_seconds();
    benchmark::DoNotOptimize(sampler().sample(o));
    total += cpu_seconds() - t0, ++runs;
  }
  state.counters["x_full_gsp"] = total / double(runs) / reference;
}

}  // namespace

BENCHMARK(BM_FullGsp)->Unit(benchmark::kMillisecond)->Iterations(5);
BENCHMARK(BM_Poisson)->Arg(10000)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_Farthest)->Arg(1000)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
