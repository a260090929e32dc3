#include "options.hpp"

#include <gsp/cli/app.hpp>

#include <CLI/CLI.hpp>

namespace gsp::bench {

void add_options(CLI::App& app, Options& o) {
  app.add_option("MESH", o.meshes, "meshes to benchmark (.ply .obj .off .stl .gltf .glb); with --corpus also folders")
      ->required();
  app.add_flag("--corpus", o.corpus,
               "corpus evaluation: every mesh of each folder, one row per mesh, failures kept as rows, "
               "aggregate per category (defaults: --methods " + std::string(corpus_method_list()) +
                   " --sources 3 --repetitions 1)");
  app.add_option("--categories", o.categories,
                 "--corpus: markdown table (File, Character columns) giving each mesh benign/malign (default: "
                 "the SOURCES.md beside each mesh)")
      ->type_name("FILE");
  app.add_option("--methods", o.methods, "comma-separated methods (default: all; see docs/apps/gsp-bench.md): " +
                                             method_names())
      ->type_name("LIST")
      ->each([&o](const std::string&) { o.methods_given = true; });
  app.add_option("--sources", o.sources, "random source vertices per mesh (default 4)")
      ->check(CLI::Range(1, 100000))
      ->each([&o](const std::string&) { o.sources_given = true; });
  app.add_option("--seed", o.seed, "seed of the source picks and of the random layout (default 1)");
  app.add_option("--repetitions", o.repetitions, "timed runs per source after one warm-up; the median is reported (default 5)")
      ->check(CLI::Range(1, 100000))
      ->each([&o](const std::string&) { o.repetitions_given = true; });
  app.add_option("--json", o.json, "full report as JSON (- for stdout)")->type_name("FILE");
  app.add_option("--csv", o.csv, "one row per (mesh, method) as CSV (- for stdout)")->type_name("FILE");
  app.add_option("--cache", o.cache, "folder for exact distances, keyed by mesh content and source vertex")
      ->type_name("DIR");
  app.add_option("--shard", o.shard, "run only every n-th (mesh, source) work item, starting at i (default 0/1)")
      ->type_name("i/n");
  app.add_option("--clock", o.clock,
                 "what a query's time is: wall (default) or cpu (thread CPU time, for busy shared machines)")
      ->check(CLI::IsMember({"wall", "cpu"}));
  app.add_flag("--no-table", o.no_table, "print no table on stdout");
  app.add_option("--domain", o.domain,
                 "mesh (default) or points: the mesh's vertices as a point cloud; --methods then defaults to " +
                     points_method_list())
      ->check(CLI::IsMember({"mesh", "points"}));
  app.add_option("--subdivide", o.subdivide,
                 "Loop-subdivide every mesh K times first (each round: 4x the faces), for 100k-1M-vertex inputs "
                 "made from small meshes; the reports name them MESH@loopK")
      ->check(CLI::Range(0, 6))
      ->type_name("K");
  app.add_option("--subdivision", o.subdivision,
                 "how --subdivide splits: loop (default: every vertex moved, curved everywhere) or midpoint "
                 "(4 faces per face, new vertices on the old faces: keeps needles and flat regions; MESH@midK; "
                 "any soup)")
      ->check(CLI::IsMember({"loop", "midpoint"}));
  app.add_option("--neighbours", o.neighbours, "k of the point-cloud methods' k-nearest-neighbour graph (default 10)")
      ->check(CLI::Range(1u, 1000u));
  cli::add_load_options(app, o.load);
}

Settings check_options(Options& o, bool stats_to_stdout) {
  Settings s;
  if (o.corpus) {
    if (o.shard != "0/1") throw cli::UsageError("--shard does not apply to --corpus (run folders separately)");
    if (!o.methods_given && o.domain == "mesh") o.methods = corpus_method_list();
    if (!o.sources_given) o.sources = kCorpusSources;
    if (!o.repetitions_given) o.repetitions = kCorpusRepetitions;
  } else if (!o.categories.empty()) {
    throw cli::UsageError("--categories needs --corpus");
  }
  // --domain points changes the default list only; an explicit --methods is taken as given.
  const bool default_list = !o.methods_given;
  s.methods = parse_methods(o.domain == "points" && default_list ? points_method_list() : o.methods);
  s.shard = parse_shard(o.shard);
  const int on_stdout = int(o.json == "-") + int(o.csv == "-") + int(stats_to_stdout);
  if (on_stdout > 1) throw cli::UsageError("only one of --json, --csv and --stats can be - (stdout)");
  s.table = !o.no_table && on_stdout == 0;
  return s;
}

BenchConfig bench_config(const Options& o, const Settings& settings, const reference::ExactCache& cache) {
  BenchConfig config;
  config.methods = settings.methods;
  config.repetitions = o.repetitions;
  config.cpu_clock = o.clock == "cpu";
  config.seed = o.seed;
  config.neighbours = o.neighbours;
  config.cache = &cache;
  return config;
}

}  // namespace gsp::bench
