// gsp-sample: geodesic blue-noise sampling of a triangle mesh (paper Section 5.8): Poisson-disk
// sampling by dart throwing with propagations bounded by the radius, or farthest-point
// sampling; points written with their face, barycentric weights and face normal.
#include "write_samples.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/cli/load.hpp>
#include <gsp/cli/parse.hpp>
#include <gsp/closest_point.hpp>
#include <gsp/errors.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/render/preview_cli.hpp>
#include <gsp/render/render.hpp>
#include <gsp/sampling/quality.hpp>
#include <gsp/sampling/sampler.hpp>
#include <gsp/sampling/surface_points.hpp>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace {

using namespace gsp;

struct Options {
  std::string input, output, radius, mode = "poisson", evaluate;
  std::size_t count = 0;
  std::uint64_t seed = 1;
  std::size_t max_rejections = 500;
  std::size_t quality_samples = 0;
  bool no_fill = false, ascii = false, exact_count = false;
  render::PreviewRequest preview;   // --png, --view, --png-size
  cli::LoadOptions load;
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("INPUT", o.input, "input mesh (.ply .obj .off .stl .gltf .glb)")->required();
  app.add_option("-o,--output", o.output,
                 "samples: .ply (normals, int face, float u, v), .glb/.gltf (_FACE, _U, _V), .obj "
                 "(points and normals), .txt (x y z nx ny nz face u v per line)");
  app.add_option("--evaluate", o.evaluate, "instead of sampling: read these points (any mesh or point-cloud file, "
                 "e.g. MeshLab's Poisson-disk output), snap them onto the surface and report the quality figures "
                 "for --radius in --stats")->type_name("POINTS");
  app.add_option("--count", o.count, "number of samples (poisson: the radius is searched to meet it within 1%)")
      ->check(CLI::PositiveNumber);
  app.add_option("--radius", o.radius, "minimum geodesic distance between samples: model units, or \"2%\" "
                 "of the bounding-box diagonal")->type_name("R");
  app.add_option("--mode", o.mode, "poisson (default: dart throwing) or farthest (farthest-point sampling)")
      ->check(CLI::IsMember({"poisson", "farthest"}));
  app.add_option("--seed", o.seed, "random seed (same seed, same samples on every platform)");
  app.add_option("--max-rejections", o.max_rejections,
                 "poisson: stop after this many rejected candidates in a row (default 500)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--exact-count", o.exact_count,
               "poisson + --count: exactly COUNT samples (the surplus of the closest run above it is dropped)");
  app.add_flag("--no-fill", o.no_fill, "poisson: skip the final pass that adds samples at uncovered vertices");
  app.add_option("--quality-samples", o.quality_samples,
                 "with --stats: measure the nearest-neighbour distance from this many samples (default all)");
  app.add_flag("--ascii", o.ascii, "ASCII PLY instead of binary");
  render::add_preview_options(app, o.preview, "the mesh with the samples as spheres");
  cli::add_load_options(app, o.load);
}

// "0.5" (model units) or "2%" (of the bounding-box diagonal); returns the percentage as a
// negative number so the caller can scale it once the mesh is read.
double parse_radius(std::string text) {
  const bool percent = !text.empty() && text.back() == '%';
  if (percent) text.pop_back();
  const double value = cli::parse_number(text, "--radius");
  if (!(value > 0)) throw cli::UsageError("--radius: must be > 0");
  return percent ? -value : value;
}

void report(cli::Context& ctx, const sampling::Sampler& sampler, const sampling::SamplingResult& result,
            double compute_seconds) {
  cli::Json& res = ctx.stats()["result"];
  res["count"] = result.samples.size();
  res["radius"] = result.radius;
  res["radius_over_diagonal"] = result.radius / sampler.diagonal();
  res["area"] = sampler.area();
  res["seconds_per_sample"] = result.samples.empty() ? 0.0 : compute_seconds / double(result.samples.size());
  if (result.stats.search_iterations) {
    res["count_met"] = result.stats.count_met;
    res["search_iterations"] = result.stats.search_iterations;
  }
  cli::Json& ops = ctx.operations();
  ops["candidates"] = result.stats.candidates;
  ops["rejected"] = result.stats.rejected;
  ops["fill_samples"] = result.stats.fill_samples;
  ops["propagations"] = result.stats.propagations;
  ops["update_steps"] = result.stats.update_steps;
  ops["faces_reached"] = result.stats.faces_reached;
}

// The quality figures of `result` into --stats (section "quality"), with a progress line.
void report_quality(cli::Context& ctx, const Options& o, const sampling::Sampler& sampler,
                    const sampling::SamplingResult& result) {
  sampling::QualityOptions qo;
  qo.max_checked = o.quality_samples;
  qo.seed = o.seed;
  auto progress = ctx.progress("quality");
  qo.progress = progress->callback();
  const sampling::SamplingQuality q =
      ctx.timer().time("quality", [&] { return sampling::measure_quality(sampler, result, qo); });
  cli::Json& j = ctx.stats()["quality"];
  j["samples_checked"] = q.samples_checked;
  j["min_distance"] = q.min_distance;
  j["min_distance_over_radius"] = q.min_distance_ratio;
  j["coverage_radius"] = q.coverage_radius;
  j["coverage_over_radius"] = q.coverage_ratio;
  j["packing_radius"] = q.packing_radius;
  j["normalized_radius"] = q.normalized_radius;
}

// --evaluate: the quality figures of someone else's point set at radius r.
void evaluate(cli::Context& ctx, const Options& o, double radius_arg) {
  const cli::LoadedMesh in = cli::load_input(ctx, o.input, o.load);
  const io::ReadResult points = io::read_mesh(o.evaluate);
  if (points.mesh.positions.empty()) throw InvalidInput(o.evaluate + ": no points");
  const sampling::Sampler sampler(in.mesh);
  sampling::SamplingResult result;
  result.radius = radius_arg < 0 ? -radius_arg / 100.0 * sampler.diagonal() : radius_arg;
  double snapped = 0;
  ctx.timer().time("snap", [&] {
    for (const Vec3& p : points.mesh.positions) {
      const ClosestPoint s = closest_surface_point(in.mesh, p);
      result.samples.push_back(sampling::make_sample(in.mesh, s.point.element, s.point.barycentric));
      snapped = std::max(snapped, s.distance);
    }
  });
  cli::Json& res = ctx.stats()["result"];
  res["count"] = result.samples.size();
  res["radius"] = result.radius;
  res["radius_over_diagonal"] = result.radius / sampler.diagonal();
  res["area"] = sampler.area();
  res["max_snap_distance"] = snapped;
  report_quality(ctx, o, sampler, result);
}

void run(cli::Context& ctx, const Options& o) {
  if (!o.evaluate.empty()) {
    if (o.radius.empty() || o.count) throw cli::UsageError("--evaluate needs --radius (and no --count)");
    if (!o.output.empty()) throw cli::UsageError("--evaluate writes no samples: drop -o (the figures go to --stats)");
    return evaluate(ctx, o, parse_radius(o.radius));
  }
  if (o.output.empty()) throw cli::UsageError("-o is required (or --evaluate POINTS)");
  if ((o.count > 0) == !o.radius.empty()) throw cli::UsageError("give exactly one of --count and --radius");
  const double radius_arg = o.radius.empty() ? 0.0 : parse_radius(o.radius);
  const render::RenderOptions preview = render::preview_options(o.preview);

  cli::output_format(o.output, {io::Format::ply, io::Format::obj, io::Format::gltf, io::Format::glb, io::Format::txt});

  const cli::LoadedMesh in = cli::load_input(ctx, o.input, o.load);
  auto build = ctx.timer().scope("build");
  const sampling::Sampler sampler(in.mesh);
  build.stop();
  ctx.timer().add("layout", sampler.solver().timings().layout);

  sampling::SamplingOptions so;
  so.mode = o.mode == "farthest" ? sampling::Mode::farthest : sampling::Mode::poisson;
  so.count = o.count;
  so.radius = radius_arg < 0 ? -radius_arg / 100.0 * sampler.diagonal() : radius_arg;
  so.seed = o.seed;
  so.max_rejections = o.max_rejections;
  so.fill_vertices = !o.no_fill;
  so.exact_count = o.exact_count;
  ctx.settings()["mode"] = o.mode;
  ctx.settings()["seed"] = o.seed;
  if (o.count) ctx.settings()["count"] = o.count;
  else ctx.settings()["radius"] = so.radius;
  if (so.mode == sampling::Mode::poisson) {
    ctx.settings()["max_rejections"] = o.max_rejections;
    ctx.settings()["fill_vertices"] = so.fill_vertices;
    if (o.count) ctx.settings()["exact_count"] = so.exact_count;
  }

  sampling::SamplingResult result;
  {
    auto progress = ctx.progress("sampling");
    so.progress = progress->callback();
    result = ctx.timer().time("compute", [&] { return sampler.sample(so); });
  }
  report(ctx, sampler, result, ctx.timer().seconds("compute"));
  if (result.stats.search_iterations && !result.stats.count_met)
    ctx.note("--count " + std::to_string(o.count) + ": got " + std::to_string(result.samples.size()) +
             " samples, the closest the radius search reached");

  if (ctx.stats_requested()) report_quality(ctx, o, sampler, result);

  ctx.timer().time("write", [&] { sample_app::write_samples(o.output, result.samples, o.ascii); });
  if (o.preview.wanted())
    ctx.timer().time("preview", [&] {
      render::Scene scene;
      scene.mesh = in.mesh;
      for (const sampling::Sample& s : result.samples) scene.points.push_back(s.position);
      scene.point_radius = 0.2 * result.radius;
      if (!(scene.point_radius > 0) || !std::isfinite(scene.point_radius)) scene.point_radius = 0;
      render::write_png(o.preview.png, render::render(scene, preview));
    });
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  return gsp::cli::run_app(
      argc, argv, "gsp-sample",
      "Geodesic blue-noise (Poisson-disk) or farthest-point sampling of a triangle mesh.",
      [&](CLI::App& app) { add_options(app, options); },
      [&](gsp::cli::Context& ctx) { run(ctx, options); });
}
