// gsp-train-heuristic: trains the 20 parameters of GSP's visibility heuristic (paper Section
// 3.2: four thresholds and a 16-entry lambda table) against exact geodesics with a (1+1)
// evolution strategy, or (--evaluate) compares heuristics mesh by mesh.
//
//   gsp-train-heuristic --cache exact-cache --sources 8 --iterations 400
//       fertility.off camelhead.off adis16480_sensor.stl --validate armadillo.obj --out trained.txt
//   gsp-train-heuristic --cache exact-cache --evaluate --heuristics centroid,published,trained.txt
//       fertility.off armadillo.obj
//
// Meshes CGAL cannot take (non-manifold, degenerate faces) are skipped with a note. Progress
// goes to stderr (--quiet silences it); the result (the 20 numbers, or a Markdown table of
// mean relative errors) to stdout.
#include "evolution.hpp"
#include "objective.hpp"
#include "training_set.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/errors.hpp>
#include <gsp/heuristic.hpp>
#include <gsp/io/atomic_file.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using gsp::VisibilityHeuristic;
using gsp::train::TrainingMesh;

struct Options {
  std::vector<std::string> meshes, validate;
  int sources = 8;
  std::uint64_t seed = 1;
  int iterations = 300;
  double sigma = 0.1;
  std::string cache, start = "published", out;
  std::string aggregate = "mean";
  bool evaluate = false;
  std::string heuristics = "dijkstra,centroid,corner,published,trained";
};

// A heuristic by name, or the 20 numbers read from a file.
VisibilityHeuristic named_heuristic(const std::string& name) {
  if (name == "published") return VisibilityHeuristic::published();
  if (name == "centroid") return VisibilityHeuristic::centroid();
  if (name == "corner") return VisibilityHeuristic::opposite_corner();
  if (name == "trained") return VisibilityHeuristic::trained();
  std::ifstream in(name);
  if (!in) throw gsp::IoError(name, "", "cannot open (expected published, centroid, corner, trained or a file)");
  std::stringstream text;
  text << in.rdbuf();
  try {
    return VisibilityHeuristic::from_string(text.str());
  } catch (const gsp::InvalidInput& e) {
    throw gsp::IoError(name, "", e.what());
  }
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

std::vector<TrainingMesh> prepare(gsp::cli::Context& ctx, const std::vector<std::string>& paths,
                                  const Options& opt, const gsp::reference::ExactCache& cache) {
  std::vector<TrainingMesh> out;
  for (const std::string& path : paths) {
    try {
      out.push_back(gsp::train::prepare_mesh(path, opt.sources, opt.seed, cache,
                                             [&](const std::string& m) { ctx.note(m); }));
    } catch (const gsp::TopologyError& e) {
      ctx.note("skipping " + path + ": " + e.what());
    }
  }
  return out;
}

std::string percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f%%", 100 * fraction);
  return buf;
}

// One Markdown row per mesh and a mean row per group; cells are MRE (signed mean in brackets).
void print_table(std::ostream& os, const std::vector<std::pair<std::string, const std::vector<TrainingMesh>*>>& groups,
                 const std::vector<std::string>& names) {
  // Resolve every name first: a typo must fail before anything is printed.
  std::vector<VisibilityHeuristic> heuristics;
  for (const std::string& n : names) heuristics.push_back(n == "dijkstra" ? VisibilityHeuristic{} : named_heuristic(n));
  os << "| mesh | set | vertices | sources |";
  for (const std::string& n : names) os << ' ' << n << " |";
  os << "\n|---|---|---:|---:|";
  for (std::size_t i = 0; i < names.size(); ++i) os << "---:|";
  os << '\n';
  for (const auto& [label, meshes] : groups) {
    if (meshes->empty()) continue;
    std::vector<double> sum(names.size(), 0.0);
    for (const TrainingMesh& m : *meshes) {
      os << "| " << m.name << " | " << label << " | " << m.mesh.num_vertices() << " | " << m.sources.size() << " |";
      for (std::size_t i = 0; i < names.size(); ++i) {
        const gsp::train::ErrorStats s = names[i] == "dijkstra" ? gsp::train::evaluate_dijkstra(m)
                                                                : gsp::train::evaluate_gsp(m, heuristics[i]);
        sum[i] += s.mre;
        os << ' ' << percent(s.mre) << " (" << (s.signed_mre >= 0 ? "+" : "") << percent(s.signed_mre) << ") |";
      }
      os << '\n' << std::flush;
    }
    os << "| **mean** | " << label << " | | |";
    for (double s : sum) os << " **" << percent(s / double(meshes->size())) << "** |";
    os << '\n';
  }
}

void run(gsp::cli::Context& ctx, const Options& opt) {
  const gsp::reference::ExactCache cache(opt.cache);
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<TrainingMesh> train = prepare(ctx, opt.meshes, opt, cache);
  const std::vector<TrainingMesh> held_out = prepare(ctx, opt.validate, opt, cache);
  ctx.timer().add("exact", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  if (train.empty()) throw gsp::InvalidInput("no usable mesh: every input was skipped");
  ctx.input()["meshes"] = train.size();
  ctx.input()["held_out"] = held_out.size();
  ctx.settings()["sources_per_mesh"] = opt.sources;
  ctx.settings()["seed"] = opt.seed;

  if (opt.evaluate) {
    auto t = ctx.timer().scope("evaluate");
    // With "--stats -" stdout carries only the JSON: the table then goes to stderr.
    print_table(ctx.stats_to_stdout() ? std::cerr : std::cout, {{"train", &train}, {"held-out", &held_out}},
                split_list(opt.heuristics));
    return;
  }

  const VisibilityHeuristic start = named_heuristic(opt.start);
  gsp::train::EvolutionOptions es;
  es.iterations = opt.iterations;
  es.seed = opt.seed;
  es.sigma = opt.sigma;
  ctx.settings()["iterations"] = opt.iterations;
  ctx.settings()["sigma"] = opt.sigma;
  ctx.settings()["start"] = opt.start;
  const auto train_start = std::chrono::steady_clock::now();
  const auto aggregate = opt.aggregate == "geomean" ? gsp::train::Aggregate::geomean : gsp::train::Aggregate::mean;
  ctx.settings()["objective"] = opt.aggregate;
  auto objective = [&](const VisibilityHeuristic& h) { return gsp::train::objective(train, h, aggregate); };
  auto on_step = [&](const gsp::train::EvolutionStep& s) {
    if (!s.improved && s.iteration % 25 != 0) return;
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - train_start).count();
    char line[200];
    std::snprintf(line, sizeof line, "iteration %d/%d: child %s, best %s, sigma %.4f, %.0f s%s", s.iteration,
                  opt.iterations, percent(s.child).c_str(), percent(s.best).c_str(), s.sigma, secs,
                  s.improved ? " (improved)" : "");
    ctx.note(line);
  };
  gsp::train::EvolutionResult r;
  {
    auto t = ctx.timer().scope("train");
    r = gsp::train::evolve(start, objective, es, on_step);
  }
  const double val_start = gsp::train::objective(held_out, start, aggregate);
  const double val_best = gsp::train::objective(held_out, r.best, aggregate);
  const std::string numbers = r.best.to_string();
  if (!opt.out.empty()) {
    gsp::io::AtomicFile f(opt.out);
    const std::string text = numbers + "\n";
    f.write(text.data(), text.size());
    f.commit();
  }
  if (!ctx.stats_to_stdout()) std::cout << numbers << '\n';   // else it is in the JSON's "result"
  ctx.note("training objective (" + opt.aggregate + " MRE) " + percent(r.start_value) + " -> " + percent(r.best_value) + " (" +
           std::to_string(r.improvements) + " improvements)");
  if (!held_out.empty()) ctx.note("held-out objective " + percent(val_start) + " -> " + percent(val_best));
  gsp::cli::Json& result = ctx.stats()["result"];
  result["heuristic"] = numbers;
  result["train_mre_start"] = r.start_value;
  result["train_mre"] = r.best_value;
  result["improvements"] = r.improvements;
  if (!held_out.empty()) result["held_out_mre_start"] = val_start, result["held_out_mre"] = val_best;
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  return gsp::cli::run_app(
      argc, argv, "gsp-train-heuristic",
      "Trains the visibility heuristic of GSP (paper Section 3.2) against exact geodesics (CGAL), "
      "or compares heuristics by their mean relative error per mesh (--evaluate).",
      [&](CLI::App& app) {
        app.add_option("MESHES", opt.meshes, "training meshes (meshes CGAL refuses are skipped)")->required();
        app.add_option("--validate", opt.validate, "held-out meshes: reported, never trained on");
        app.add_option("--sources", opt.sources, "random source vertices per mesh")->check(CLI::Range(1, 1000))->capture_default_str();
        app.add_option("--seed", opt.seed, "seed for the sources and the evolution strategy")->capture_default_str();
        app.add_option("--iterations", opt.iterations, "children the evolution strategy evaluates")->check(CLI::Range(0, 10000000))->capture_default_str();
        app.add_option("--sigma", opt.sigma, "initial mutation step (lambda units; log units for thresholds)")->check(CLI::Range(1e-6, 1.0))->capture_default_str();
        app.add_option("--cache", opt.cache, "folder for exact distances (keyed by mesh content and source)");
        app.add_option("--start", opt.start, "starting point: published, centroid, corner, trained or a file")->capture_default_str();
        app.add_option("--out", opt.out, "write the trained 20 numbers here (VisibilityHeuristic::to_string)");
        app.add_option("--objective", opt.aggregate, "combine per-mesh MREs by their mean or geometric mean")
            ->check(CLI::IsMember({"mean", "geomean"}))->capture_default_str();
        app.add_flag("--evaluate", opt.evaluate, "do not train: print a Markdown table of MRE per mesh");
        app.add_option("--heuristics", opt.heuristics,
                       "with --evaluate: comma-separated dijkstra, centroid, corner, published, trained or files")
            ->capture_default_str();
      },
      [&](gsp::cli::Context& ctx) { run(ctx, opt); });
}
