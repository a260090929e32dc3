#pragma once
// The figures reported per (mesh, method), and the machine-readable reports: JSON with every
// sample, CSV with one row per (mesh, method).
#include "bench.hpp"

#include <gsp/cli/json.hpp>

#include <string>
#include <vector>

namespace gsp::bench {

// NaN where a figure does not apply (no timing, no exact reference, not GSP, ...).
struct Summary {
  double precompute_s;
  double query_s;                    // median over sources of the per-source median time
  double vertices_per_s;             // median over sources of reached vertices / median time
  double cycles_per_vertex;          // median over sources of median ticks / reached vertices
  double update_steps_per_triangle;  // GSP: mean over sources of update_steps / faces reached
  double mre, max_re;                // mean over sources of the MRE; max over sources
  double signed_re;                  // mean over sources of the signed mean relative error
  std::size_t unreached;             // vertices left at +inf that exact reaches (all sources)
  double state_bytes_per_vertex;     // GSP: propagation state (GeodesicSolver::state_bytes)
  double solver_bytes_per_vertex;    // measured heap kept by the prepared solver (mallinfo2)
  double vs_dijkstra, vs_heat, vs_heat_idt, vs_gsp;   // query_s / the other method's query_s
  std::size_t timed_sources;
  std::size_t error_sources;
  BoundStats bounds;                 // physical bounds, the worst over sources (bounds.hpp)
  std::size_t bound_sources;         // sources whose distances were checked (0: bounds n/a)
};

cli::Json bounds_json(const BoundStats& b);

Summary summarise(const MeshRun& run, const MethodRun& method);

struct Report {
  cli::Json settings;                // what the run was asked to do (methods, seed, ...)
  int repetitions = 0;               // also in settings; repeated in every CSV row
  std::string clock;                 // "wall" or "cpu"
  cli::Json machine;                 // CPU, counters used
  std::vector<WorkItem> items;       // this shard's work items
  std::size_t total_items = 0;       // before sharding
  std::vector<const BenchMesh*> all_meshes;
  std::vector<MeshRun> runs;         // meshes with at least one work item in this shard
};

cli::Json to_json(const Report& report);
std::string to_csv(const Report& report);
std::string csv_header();

}  // namespace gsp::bench
