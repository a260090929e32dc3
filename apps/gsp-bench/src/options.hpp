#pragma once
// What gsp-bench is asked to do, as parsed from the command line.
#include "bench.hpp"
#include "methods.hpp"
#include "workload.hpp"

#include <gsp/cli/load.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace gsp::bench {

struct Options {
  std::vector<std::string> meshes;
  std::string methods = default_method_list();
  int sources = 4;
  std::uint64_t seed = 1;          // the same default as gsp-train-heuristic: shared cache entries
  int repetitions = 5;
  std::string json, csv;           // "" = none, "-" = stdout
  std::string cache;               // exact-distance cache folder, "" = none
  std::string shard = "0/1";
  std::string clock = "wall";      // wall | cpu
  bool no_table = false;
  std::string domain = "mesh";     // mesh | points: what --methods defaults to
  unsigned neighbours = 10;        // k of the point-cloud methods' k-NN graph
  int subdivide = 0;               // rounds of subdivision applied to every mesh
  std::string subdivision = "loop";   // loop | midpoint
  cli::LoadOptions load;
  bool corpus = false;             // --corpus: MESH... are folders or files, one row per mesh
  std::string categories;          // --corpus: a SOURCES.md-like file for all meshes
  // Given on the command line: corpus mode has its own defaults, which a given flag overrides.
  bool methods_given = false, sources_given = false, repetitions_given = false;
};

// The corpus-mode defaults (the figures of a corpus evaluation: GSP, both baselines, exact).
inline const char* corpus_method_list() { return "gsp,dijkstra,heat,exact"; }
constexpr int kCorpusSources = 3, kCorpusRepetitions = 1;

void add_options(CLI::App& app, Options& options);

// The checked settings (UsageError for unknown methods, a malformed shard, two outputs on
// stdout, --shard or --categories without --corpus' consent). Applies the corpus defaults.
struct Settings {
  std::vector<MethodInfo> methods;
  Shard shard;
  bool table = true;   // the human-readable table on stdout
};
Settings check_options(Options& options, bool stats_to_stdout);

// The measuring loop's settings from the checked options (both modes, per-mesh and corpus).
BenchConfig bench_config(const Options& options, const Settings& settings, const reference::ExactCache& cache);

}  // namespace gsp::bench
