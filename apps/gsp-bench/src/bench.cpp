#include "bench.hpp"

#include <gsp/reference/exact_cache.hpp>

#include <gsp/dijkstra.hpp>
#include <gsp/errors.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

namespace gsp::bench {

namespace {

double heap_delta(std::size_t before) {
  if (!have_heap_counter()) return -1;
  const std::size_t after = heap_in_use();
  return after > before ? double(after - before) : 0.0;
}

std::size_t count_finite(const std::vector<double>& d) {
  return std::size_t(std::count_if(d.begin(), d.end(), [](double x) { return std::isfinite(x); }));
}

// Edge-path distances per source (the upper bound of bounds.hpp), computed once per mesh and
// shared by every method; empty per source where the edge graph cannot be built.
std::vector<std::vector<double>> edge_paths(const BenchMesh& mesh, const std::vector<Index>& sources,
                                            const NoteFn& note) {
  std::vector<std::vector<double>> out(sources.size());
  try {
    const DijkstraSolver solver(mesh.mesh);
    for (std::size_t k = 0; k < sources.size(); ++k)
      out[k] = solver.compute({Source::at_vertex(sources[k])}).vertex_distance;
  } catch (const Error& e) {
    note(mesh.name + ": no edge-path bound: " + e.what());
  }
  return out;
}

// One timed query; the outcome is destroyed by the caller, after the clocks stop.
Outcome timed_run(Runner& runner, Index source, bool cpu_clock, SourceRun& out) {
  const std::uint64_t c0 = cycle_counter();
  const Stopwatch watch;
  Outcome o = runner.run(source);
  const double wall = watch.wall(), cpu = watch.cpu();
  const std::uint64_t c1 = cycle_counter();
  out.wall_seconds.push_back(wall);
  out.cpu_seconds.push_back(cpu);
  out.seconds.push_back(cpu_clock && !runner.threaded() ? cpu : wall);
  out.cycles.push_back(double(c1 - c0));
  return o;
}

void time_runs(Runner& runner, Index source, int repetitions, bool cpu_clock, SourceRun& out) {
  for (int r = 0; r < repetitions; ++r) timed_run(runner, source, cpu_clock, out);
}

// Exact distances per source: read from the cache, computed when `exact` is among the methods
// (then timed once per source: seconds each, no repetitions), or absent.
MethodRun exact_references(const BenchMesh& mesh, const std::vector<Index>& sources, const BenchConfig& config,
                           bool timed, const std::vector<std::vector<double>>& edge,
                           std::vector<std::optional<std::vector<double>>>& refs,
                           std::size_t& cached, const StepFn& step, const NoteFn& note) {
  MethodRun r;
  r.method = method_info(Method::exact);
  refs.assign(sources.size(), std::nullopt);
  for (std::size_t k = 0; k < sources.size(); ++k)
    if (config.cache && (refs[k] = config.cache->load(mesh.hash, sources[k], mesh.mesh.num_vertices()))) ++cached;
  if (!timed) return r;
  const std::size_t heap0 = heap_in_use();
  std::unique_ptr<Runner> runner;
  try {
    const Stopwatch watch;
    runner = make_runner(Method::exact, mesh.mesh, config.seed);
    r.precompute_s = config.cpu_clock ? watch.cpu() : watch.wall();
    for (std::size_t k = 0; k < sources.size(); ++k) {
      SourceRun sr;
      sr.source = sources[k];
      if (refs[k]) {
        sr.from_cache = true;
        sr.reached = count_finite(*refs[k]);
      } else {
        Outcome o = timed_run(*runner, sources[k], config.cpu_clock, sr);
        sr.reached = count_finite(o.distance);
        refs[k] = std::move(o.distance);
        if (config.cache) config.cache->store(mesh.hash, sources[k], *refs[k]);
        char line[160];
        std::snprintf(line, sizeof line, "%s: exact distances from vertex %u (%.2f s)", mesh.name.c_str(),
                      sources[k], sr.seconds.back());
        note(line);
      }
      sr.bounds = physical_bounds(mesh.mesh, sources[k], *refs[k], edge[k]);
      sr.has_bounds = true;
      r.sources.push_back(std::move(sr));
      step();
    }
    r.solver_bytes = heap_delta(heap0);   // includes the sequence tree of the last source computed
  } catch (const IoError&) {   // the cache could not be written: a failure of the run, not of CGAL
    throw;
  } catch (const Error& e) {   // TopologyError, InvalidInput: CGAL cannot take this mesh
    r.skipped = e.what();
  }
  if (!r.ok()) {
    note(mesh.name + ": exact skipped: " + r.skipped);
    for (std::size_t k = r.sources.size(); k < sources.size(); ++k) step();
    r.sources.clear();
  }
  return r;
}

MethodRun bench_method(const MethodInfo& info, const BenchMesh& mesh, const std::vector<Index>& sources,
                       const BenchConfig& config, const std::vector<std::vector<double>>& edge,
                       const std::vector<std::optional<std::vector<double>>>& refs,
                       const StepFn& step, const NoteFn& note) {
  MethodRun r;
  r.method = info;
  std::size_t done = 0;
  try {
    const std::size_t heap0 = heap_in_use();
    const Stopwatch watch;
    std::unique_ptr<Runner> runner = make_runner(info.id, mesh.mesh, config.seed, config.neighbours);
    r.precompute_s = config.cpu_clock ? watch.cpu() : watch.wall();
    r.state_bytes = runner->state_bytes();
    r.intrinsic_flips = runner->intrinsic_flips();
    for (std::size_t k = 0; k < sources.size(); ++k) {
      SourceRun sr;
      sr.source = sources[k];
      {
        Outcome warm = runner->run(sources[k]);   // warm-up; deterministic, so its distances are the method's
        sr.reached = count_finite(warm.distance);
        sr.stats = warm.stats;
        sr.has_stats = warm.has_stats;
        const std::vector<double> d = runner->to_mesh_order(std::move(warm.distance));
        sr.bounds = physical_bounds(mesh.mesh, sources[k], d, edge[k]);
        sr.has_bounds = true;
        if (refs[k]) {
          sr.errors = relative_errors(d, *refs[k]);
          sr.has_errors = true;
        }
      }
      if (k == 0) r.solver_bytes = heap_delta(heap0);
      time_runs(*runner, sources[k], config.repetitions, config.cpu_clock, sr);
      r.sources.push_back(std::move(sr));
      ++done;
      step();
    }
  } catch (const Error& e) {   // TopologyError, InvalidInput, a failed factorisation
    r.skipped = e.what();
    r.sources.clear();
    note(mesh.name + ": " + info.name + " skipped: " + r.skipped);
    for (; done < sources.size(); ++done) step();
  }
  return r;
}

}  // namespace

MeshRun bench_mesh(const BenchMesh& mesh, const std::vector<Index>& sources, const BenchConfig& config,
                   const StepFn& step, const NoteFn& note) {
  MeshRun run;
  run.mesh = &mesh;
  run.sources = sources;
  const bool exact_timed = std::any_of(config.methods.begin(), config.methods.end(),
                                       [](const MethodInfo& m) { return m.id == Method::exact; });
  const std::vector<std::vector<double>> edge = edge_paths(mesh, sources, note);
  std::vector<std::optional<std::vector<double>>> refs;
  MethodRun exact = exact_references(mesh, sources, config, exact_timed, edge, refs, run.exact_cached, step, note);
  run.exact_references = std::size_t(std::count_if(refs.begin(), refs.end(), [](const auto& d) { return d.has_value(); }));
  if (run.exact_references < sources.size())
    run.notes.push_back(run.exact_references == 0
                            ? "no exact distances: errors not measured"
                            : "exact distances for " + std::to_string(run.exact_references) + " of " +
                                  std::to_string(sources.size()) + " sources only");
  if (!exact.ok()) run.notes.push_back("exact skipped: " + exact.skipped);
  for (const MethodInfo& info : config.methods) {
    if (info.id == Method::exact) {
      run.methods.push_back(exact);
      continue;
    }
    run.methods.push_back(bench_method(info, mesh, sources, config, edge, refs, step, note));
    if (!run.methods.back().ok()) run.notes.push_back(std::string(info.name) + " skipped: " + run.methods.back().skipped);
  }
  return run;
}

}  // namespace gsp::bench
