#include "corpus_main.hpp"

#include "categories.hpp"
#include "corpus_files.hpp"
#include "corpus_report.hpp"
#include <gsp/reference/exact_cache.hpp>
#include "output.hpp"

#include <gsp/errors.hpp>

#include <cstdio>
#include <new>

namespace gsp::bench {

namespace {

cli::Json corpus_settings(const Options& o, const Settings& s) {
  cli::Json j;
  j["methods"] = cli::Json::array();
  for (const MethodInfo& m : s.methods) j["methods"].push_back(m.name);
  j["paths"] = cli::Json::array_of(o.meshes);
  j["categories"] = o.categories.empty() ? cli::Json("SOURCES.md beside each mesh") : cli::Json(o.categories);
  j["sources"] = o.sources;
  j["seed"] = o.seed;
  j["repetitions"] = o.repetitions;
  j["clock"] = o.clock;
  j["domain"] = o.domain;
  j["subdivide"] = o.subdivide;
  j["subdivision"] = o.subdivision;
  j["cache"] = o.cache.empty() ? cli::Json() : cli::Json(o.cache);
  return j;
}

}  // namespace

void run_corpus(cli::Context& ctx, const Options& o, const Settings& settings) {
  Output json(o.json), csv(o.csv);   // fail on an unwritable path before any work
  Categories categories(o.categories);
  const std::vector<std::string> files = corpus_files(o.meshes);

  const reference::ExactCache cache(o.cache);
  const BenchConfig config = bench_config(o, settings, cache);

  CorpusReport report;
  for (const MethodInfo& m : settings.methods) report.methods.push_back(m.name);

  // Progress per (mesh, method, source): a mesh's share of the bar is split between its steps.
  const auto progress = ctx.progress("corpus");
  std::size_t mesh_index = 0, steps = 0, mesh_steps = 1;
  const StepFn step = [&] {
    progress->update((double(mesh_index) + double(++steps) / double(mesh_steps)) / double(files.size()));
  };
  const NoteFn note = [&](const std::string& line) {
    if (progress->enabled() && !ctx.quiet()) std::fputs("\r\033[K", stderr);
    ctx.note(line);
  };
  {
    auto timed = ctx.timer().scope("compute");
    for (; mesh_index < files.size(); ++mesh_index) {
      const std::string& path = files[mesh_index];
      const std::string category = categories.of(path);
      std::size_t vertices = 0, faces = 0;
      std::string failure;
      // One mesh at a time: loaded here, gone when its row is made.
      try {
        cli::LoadOptions load = o.load;
        load.require_faces = false;   // a point cloud is skipped, not failed
        const BenchMesh mesh = load_bench_mesh(path, load, o.sources, o.seed, o.subdivide, o.subdivision == "midpoint");
        vertices = mesh.mesh.num_vertices(), faces = mesh.mesh.num_faces();
        if (faces == 0) {
          report.point_clouds.push_back(path);
          note(mesh.name + ": a point cloud (no faces), skipped");
          continue;
        }
        if (mesh.sources.empty()) throw InvalidInput("no non-degenerate face to put a source on");
        steps = 0, mesh_steps = mesh.sources.size() * settings.methods.size();
        report.rows.push_back(corpus_row(bench_mesh(mesh, mesh.sources, config, step, note), category));
      } catch (const std::bad_alloc&) {
        failure = "out of memory";
      } catch (const std::exception& e) {   // gsp::Error (IoError, InvalidInput, ...) and the rest
        failure = *e.what() ? e.what() : "unknown error";
      }
      if (!failure.empty()) {
        CorpusRow row = failed_row(path, category, failure);
        row.vertices = vertices, row.faces = faces;   // known when it failed after loading
        note(row.name + ": failed: " + row.reason);
        report.rows.push_back(std::move(row));
      }
      progress->update(double(mesh_index + 1) / double(files.size()));
    }
  }
  progress->finish();

  ctx.input()["files"] = files.size();
  ctx.settings() = corpus_settings(o, settings);
  ctx.operations()["meshes_run"] = report.rows.size();

  ctx.timer().time("write", [&] {
    if (!o.json.empty()) {
      cli::Json doc = corpus_json(report);
      cli::Json full;
      full["app"] = "gsp-bench";
      full["mode"] = "corpus";
      full["version"] = cli::version();
      full["settings"] = corpus_settings(o, settings);
      full["cpu"] = cpu_model();
      for (const char* key : {"meshes", "point_clouds_skipped", "aggregate"}) full[key] = *doc.find(key);
      json.write(full.dump() + "\n");
    }
    if (!o.csv.empty()) csv.write(corpus_csv(report));
  });
  if (settings.table) {
    const std::string table = corpus_table(report);
    std::fwrite(table.data(), 1, table.size(), stdout);
  }
}

}  // namespace gsp::bench
