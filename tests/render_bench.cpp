// Speed of gsp::render on a mesh of about a million triangles (the figure quoted in
// docs/apps/gsp-render.md). A program, not a test: run it with
//   build/bin/render_bench [--benchmark_repetitions=5]
// The mesh is the Stanford bunny split 4-to-1 twice (1,111,216 faces) when the shared meshes
// are there, else a level-8 icosphere (1,310,720 faces).
#include "helpers/mesh_builders.hpp"
#include "test_data.hpp"

#include <gsp/io/mesh_io.hpp>
#include <gsp/render/render.hpp>

#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <cmath>
#include <filesystem>

namespace {

using namespace gsp;

// CPU seconds of the whole process (all threads, Embree's included): on a busy shared
// machine wall time depends on the neighbours, CPU time much less.
double process_cpu_seconds() {
  rusage r;
  getrusage(RUSAGE_SELF, &r);
  return double(r.ru_utime.tv_sec + r.ru_stime.tv_sec) + 1e-6 * double(r.ru_utime.tv_usec + r.ru_stime.tv_usec);
}

const render::Scene& big_scene() {
  static const render::Scene scene = [] {
    render::Scene s;
    const std::string bunny = test::shared_mesh("stanford_bunny.obj");
    if (std::filesystem::exists(bunny)) {
      s.mesh = midpoint_subdivide(midpoint_subdivide(io::read_mesh(bunny).mesh));
    } else {
      s.mesh = test::icosphere(8);
    }
    // A smooth field with iso-lines, like a distance field: distance from the first vertex.
    for (const Vec3& p : s.mesh.positions) s.vertex_field.push_back(distance(p, s.mesh.positions[0]));
    s.sources = {s.mesh.positions[0]};
    return s;
  }();
  return scene;
}

void BM_Render(benchmark::State& state) {
  const render::Scene& scene = big_scene();
  render::RenderOptions o;   // 1024 x 1024, 20 iso-lines, all cores
  o.supersample = int(state.range(0));
  o.threads = int(state.range(1));
  render::RenderTimings t, sum;
  const double cpu0 = process_cpu_seconds();
  for (auto _ : state) {
    benchmark::DoNotOptimize(render::render(scene, o, &t));
    sum.build += t.build;
    sum.trace += t.trace;
  }
  state.counters["cpu_s"] = benchmark::Counter(process_cpu_seconds() - cpu0, benchmark::Counter::kAvgIterations);
  state.counters["faces"] = double(scene.mesh.num_faces());
  state.counters["build_s"] = benchmark::Counter(sum.build, benchmark::Counter::kAvgIterations);
  state.counters["trace_s"] = benchmark::Counter(sum.trace, benchmark::Counter::kAvgIterations);
}
// Arguments: samples per pixel along each axis, threads (0 = all cores).
BENCHMARK(BM_Render)->Args({1, 0})->Args({2, 0})->Args({1, 1})->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
