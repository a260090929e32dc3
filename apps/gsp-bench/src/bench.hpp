#pragma once
// The measuring loop for one mesh: exact references first (from the cache or computed), then
// each method in turn: precompute (timed), per source one warm-up run (its distances give the
// errors) and R timed repetitions. Methods run one after another, never interleaved, so each
// finds the caches as its own queries left them.
#include "bounds.hpp"
#include "measure.hpp"
#include "methods.hpp"
#include "workload.hpp"

#include <functional>
#include <string>
#include <vector>

namespace gsp::reference {
class ExactCache;
}

namespace gsp::bench {

struct SourceRun {
  Index source = 0;
  std::vector<double> seconds;   // the timed repetitions on the chosen clock (empty for exact read from the cache)
  std::vector<double> wall_seconds, cpu_seconds;   // the same runs on both clocks
  std::vector<double> cycles;    // time-stamp counter ticks of the same runs
  std::size_t reached = 0;       // vertices given a finite distance (the work actually done:
                                 // a source reaches its own component only)
  PropagationStats stats;
  bool has_stats = false;
  bool has_errors = false;       // an exact reference was available
  ErrorStats errors;
  bool from_cache = false;       // exact only: read from the cache, not computed in this run
  bool has_bounds = false;       // the warm-up's distances checked against the physical bounds
  BoundStats bounds;
};

struct MethodRun {
  MethodInfo method{};
  std::string skipped;                   // why the method refused the mesh; empty when it ran
  double precompute_s = 0;               // the Runner's constructor (chosen clock)
  std::size_t state_bytes = 0;           // GSP: GeodesicSolver::state_bytes
  double solver_bytes = -1;              // heap held by the prepared solver after a query (mallinfo2); < 0 unmeasured
  std::size_t intrinsic_flips = 0;
  std::vector<SourceRun> sources;
  bool ok() const { return skipped.empty(); }
};

struct MeshRun {
  const BenchMesh* mesh = nullptr;
  std::vector<Index> sources;            // this shard's sources, in pick order
  std::vector<MethodRun> methods;        // in --methods order
  std::vector<std::string> notes;
  std::size_t exact_references = 0;      // sources with exact distances (computed or cached)
  std::size_t exact_cached = 0;          // of those, read from the cache
};

struct BenchConfig {
  std::vector<MethodInfo> methods;
  int repetitions = 5;
  bool cpu_clock = false;                // time by thread CPU time instead of wall time
  std::uint64_t seed = 1;
  unsigned neighbours = 10;              // k of the point-cloud methods' graph
  const reference::ExactCache* cache = nullptr;
};

using StepFn = std::function<void()>;                     // one (method, source) done
using NoteFn = std::function<void(const std::string&)>;   // a remark for stderr

MeshRun bench_mesh(const BenchMesh& mesh, const std::vector<Index>& sources, const BenchConfig& config,
                   const StepFn& step, const NoteFn& note);

}  // namespace gsp::bench
