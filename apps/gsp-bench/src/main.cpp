// gsp-bench: GSP side by side with Dijkstra, the heat method and exact geodesics: the same
// meshes, the same random source vertices, one warm-up and R timed repetitions per query,
// medians reported with errors against exact distances, memory, and the ratios between
// methods measured in the same run.
//
//   gsp-bench fertility.off camelhead.off --sources 4 --cache exact-cache --csv bench.csv
//   gsp-bench *.obj --methods gsp,dijkstra,heat --shard 1/4 --json part1.json
//   gsp-bench --corpus ../shared/data/corpus --cache exact-cache --csv corpus.csv
//
// Meshes CGAL refuses (non-manifold, degenerate faces) get the exact and heat methods skipped
// with a note; the others are still timed. See docs/apps/gsp-bench.md.
#include "bench.hpp"
#include "corpus_main.hpp"
#include <gsp/reference/exact_cache.hpp>
#include "options.hpp"
#include "output.hpp"
#include "report.hpp"
#include "table.hpp"

#include <gsp/cli/app.hpp>

#include <cstdio>
#include <memory>
#include <thread>

namespace {

using namespace gsp;
using namespace gsp::bench;

cli::Json settings_json(const Options& o, const Settings& s) {
  cli::Json j;
  cli::Json& methods = j["methods"] = cli::Json::array();
  for (const MethodInfo& m : s.methods) methods.push_back(m.name);
  j["sources"] = o.sources;
  j["seed"] = o.seed;
  j["repetitions"] = o.repetitions;
  j["clock"] = o.clock;
  j["domain"] = o.domain;
  j["neighbours"] = o.neighbours;
  j["subdivide"] = o.subdivide;
  j["subdivision"] = o.subdivision;
  j["warm_up_runs"] = 1;
  j["shard"] = std::to_string(s.shard.index) + "/" + std::to_string(s.shard.count);
  j["cache"] = o.cache.empty() ? cli::Json() : cli::Json(o.cache);
  return j;
}

cli::Json machine_json() {
  cli::Json j;
  j["cpu"] = cpu_model();
  j["hardware_threads"] = std::thread::hardware_concurrency();
  j["cycle_counter"] = have_cycle_counter() ? "rdtsc (reference cycles)" : "none";
  j["heap_counter"] = have_heap_counter() ? "mallinfo2" : "none";
  return j;
}

void run(cli::Context& ctx, Options& o) {
  const Settings settings = check_options(o, ctx.stats_to_stdout());
  if (o.corpus) return run_corpus(ctx, o, settings);
  Output json(o.json), csv(o.csv);   // fail on an unwritable path before any work

  std::vector<BenchMesh> meshes;
  for (const std::string& path : o.meshes) {
    ctx.set_input(path);
    meshes.push_back(ctx.timer().time("read", [&] { return load_bench_mesh(path, o.load, o.sources, o.seed, o.subdivide, o.subdivision == "midpoint"); }));
  }

  Report report;
  report.settings = settings_json(o, settings);
  report.repetitions = o.repetitions;
  report.clock = o.clock;
  report.machine = machine_json();
  report.items = work_items(meshes, settings.shard);
  report.total_items = total_work_items(meshes);
  for (const BenchMesh& m : meshes) report.all_meshes.push_back(&m);

  const reference::ExactCache cache(o.cache);
  const BenchConfig config = bench_config(o, settings, cache);

  const auto progress = ctx.progress("benchmarking");
  const double total_steps = double(report.items.size() * settings.methods.size());
  std::size_t steps = 0;
  const StepFn step = [&] { progress->update(total_steps > 0 ? double(++steps) / total_steps : 1.0); };
  const NoteFn note = [&](const std::string& line) {
    // Erase a drawn progress line first, so the note starts at the left margin; the next
    // update draws the progress again.
    if (progress->enabled() && !ctx.quiet()) std::fputs("\r\033[K", stderr);
    ctx.note(line);
  };
  {
    auto timed = ctx.timer().scope("compute");
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      std::vector<Index> sources;
      for (const WorkItem& w : report.items)
        if (w.mesh == m) sources.push_back(w.source);
      if (sources.empty()) continue;
      ctx.set_input(meshes[m].path);
      report.runs.push_back(bench_mesh(meshes[m], sources, config, step, note));
    }
  }
  progress->finish();

  ctx.input()["meshes"] = meshes.size();
  ctx.input()["work_items"] = report.total_items;
  ctx.settings() = report.settings;
  ctx.operations()["work_items_run"] = report.items.size();

  ctx.timer().time("write", [&] {
    if (!o.json.empty()) {
      cli::Json doc = to_json(report);
      cli::Json full;
      full["app"] = "gsp-bench";
      full["version"] = cli::version();
      for (const char* key : {"settings", "machine", "total_work_items", "work_items", "meshes"})
        full[key] = *doc.find(key);
      json.write(full.dump() + "\n");
    }
    if (!o.csv.empty()) csv.write(to_csv(report));
  });
  if (settings.table) {
    const std::string table = format_table(report);
    std::fwrite(table.data(), 1, table.size(), stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  return gsp::cli::run_app(
      argc, argv, "gsp-bench",
      "GSP side by side with Dijkstra, the heat method and exact geodesics: time per query, "
      "throughput, cycles per vertex, update steps, errors against exact, memory.",
      [&](CLI::App& app) { add_options(app, options); },
      [&](gsp::cli::Context& ctx) { run(ctx, options); });
}
