// gsp-geodesic: geodesic distances on a triangle mesh from vertices, surface points or points
// inside faces, by Geodesic Source Propagation (or Dijkstra on edges, for comparison).
#include "batch_output.hpp"
#include "layout_choice.hpp"
#include "line_sources.hpp"
#include "metric_option.hpp"
#include "options.hpp"
#include "points.hpp"
#include "output.hpp"
#include "sources.hpp"
#include "windows_method.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/batch.hpp>
#include <gsp/cli/parse.hpp>
#include <gsp/dijkstra.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/render/render.hpp>

#include <CLI/CLI.hpp>

#include <cmath>
#include <limits>
#include <memory>

namespace {

using namespace gsp;
using namespace gsp::geodesic_app;

void report_result(cli::Context& ctx, const GeodesicResult& r, std::size_t faces) {
  report_distances(ctx, r.vertex_distance);
  cli::Json& ops = ctx.operations();
  ops["update_steps"] = r.stats.update_steps;
  ops["face_updates"] = r.stats.face_updates;
  ops["enqueued"] = r.stats.enqueued;
  ops["stale_skipped"] = r.stats.stale_skipped;
  ops["postponed"] = r.stats.postponed;
  ops["iterations"] = r.stats.iterations;
  ops["faces_reached"] = r.stats.faces_reached;
  ops["update_steps_per_face"] = faces ? double(r.stats.update_steps) / double(faces) : 0.0;
  ops["double_precision"] = r.stats.double_precision;
  ops["switched_to_postpone"] = r.stats.switched_to_postpone;
  ops["relaxed_vertices"] = r.stats.relaxed_vertices;
  ops["pseudo_sources"] = r.stats.pseudo_sources;
  ops["relaxation_rounds"] = r.stats.relaxation_rounds;
  ops["straight_line_bends"] = r.stats.straight_line_bends;
  ops["window_bends"] = r.stats.window_bends;
  ops["raised_to_line"] = r.stats.raised_to_line;
}

// --separate: a field per source, written next to each other; --matrix: the distances between
// the source vertices. Both run the queries in parallel (gsp::compute_many).
void run_many(cli::Context& ctx, const Options& o, const cli::LoadedMesh& in, const ResolvedSources& src,
              const GeodesicSolver& solver, const GeodesicOptions& go) {
  const unsigned threads = resolve_threads(o.threads, src.sources.size());
  ctx.settings()["threads"] = threads;
  if (o.matrix) {
    std::vector<Index> vertices;
    for (const Source& s : src.sources) vertices.push_back(s.element);
    const std::vector<double> m =
        ctx.timer().time("compute", [&] { return distance_matrix(solver, vertices, go, threads); });
    ctx.stats()["result"]["matrix_size"] = vertices.size();
    ctx.timer().time("write", [&] { write_matrix(o.output, m, vertices.size()); });
    return;
  }
  std::vector<std::vector<Source>> queries;
  for (const Source& s : src.sources) queries.push_back({s});
  const std::vector<GeodesicResult> fields =
      ctx.timer().time("compute", [&] { return compute_many(solver, queries, go, threads); });
  ctx.stats()["result"]["fields"] = fields.size();
  ctx.timer().time("write", [&] {
    for (std::size_t i = 0; i < fields.size(); ++i)
      write_field(numbered_path(o.output, i), in, fields[i].vertex_distance, fields[i].vertex_source, false, o.ascii);
  });
}

void run(cli::Context& ctx, const Options& o) {
  const render::RenderOptions preview = render::preview_options(o.preview);
  // Checked before any work, so a typo in the extension costs nothing.
  if (o.separate && o.matrix) throw cli::UsageError("--separate and --matrix exclude each other");
  if ((o.separate || o.matrix) && o.method != "gsp" && o.method != "windows")
    throw cli::UsageError("--separate and --matrix need --method gsp or windows");
  if ((o.separate || o.matrix) && o.preview.wanted()) throw cli::UsageError("--png draws one field: not with --separate or --matrix");
  if (o.matrix) {
    const bool csv = o.output.size() >= 4 && o.output.compare(o.output.size() - 4, 4, ".csv") == 0;
    if (!csv && io::format_from_path(o.output) != io::Format::txt)
      throw cli::UsageError("--matrix writes .txt or .csv, not \"" + o.output + "\"");
    if (!o.source_points.empty() || !o.source_faces.empty())
      throw cli::UsageError("--matrix takes --source-vertex only");
  } else {
    cli::output_format(o.output, {io::Format::ply, io::Format::obj, io::Format::off, io::Format::gltf,
                                  io::Format::glb, io::Format::txt});
  }
  const Strategy strategy = parse_strategy(o.strategy);
  const Precision precision = parse_precision(o.precision);
  const VisibilityHeuristic heuristic = parse_heuristic(o.heuristic);
  const MetricRequest metric = parse_metric(o.metric);
  if (metric.wanted() && o.method != "gsp") throw cli::UsageError("--metric needs --method gsp");
  double max_distance = std::numeric_limits<double>::infinity();
  if (!o.max_distance.empty()) {
    max_distance = cli::parse_number(o.max_distance, "--max-distance");
    if (max_distance < 0) throw cli::UsageError("--max-distance: must be >= 0");
  }

  cli::LoadOptions load = o.load;
  load.require_faces = o.domain == "mesh";   // auto and points accept a cloud
  load.read_threads = o.threads == 1 ? 1 : 0;   // --threads 1: one thread for everything
  cli::LoadedMesh in = cli::load_input(ctx, o.input, load);
  if (wants_line_sources(o)) {
    if (metric.wanted()) throw cli::UsageError("--metric does not apply to line sources");
    run_line_sources(ctx, o, in, max_distance, preview);
    return;
  }
  if (o.domain == "points" || (o.domain == "auto" && in.mesh.is_point_cloud())) {
    if (metric.wanted()) throw cli::UsageError("--metric needs a mesh: not with a point cloud");
    run_points(ctx, o, in, max_distance, preview);
    return;
  }
  if (o.method == "graph-gsp") throw cli::UsageError("--method graph-gsp is for point clouds (--domain points)");
  const ResolvedSources src = resolve_sources(o, in);
  ctx.settings()["method"] = o.method;
  ctx.settings()["sources"] = src.sources.size();
  if (std::isfinite(max_distance)) ctx.settings()["max_distance"] = max_distance;
  if (!o.source_points.empty()) ctx.stats()["result"]["max_snap_distance"] = src.max_snap_distance;

  GeodesicResult result;
  if (o.method == "windows") {
    result = run_windows(ctx, o, in, src, max_distance);
    if (o.separate || o.matrix) return;   // written
  } else if (o.method == "dijkstra") {
    DijkstraSolver solver = ctx.timer().time("build", [&] { return DijkstraSolver(in.mesh); });
    result = ctx.timer().time("compute", [&] { return solver.compute(src.sources, max_distance); });
  } else {
    const LayoutChoice layout = choose_layout(o.no_layout ? "off" : o.layout, in.mesh, !(o.separate || o.matrix));
    SolverOptions so;
    so.optimize_layout = layout.optimize;
    so.spatial_layout = layout.spatial;
    so.faces_only_layout = layout.faces_only;
    so.intrinsic_delaunay = !o.input_faces;
    so.heuristic = heuristic;
    apply_metric(ctx, metric, in, so);
    so.threads = o.threads == 1 ? 1 : 0;   // the preparation: automatic unless one thread is asked for
    // One field: the solver takes the mesh (a layout reorders it in place instead of copying
    // it) and gives it back for the output. Several: `in` outlives the solver and keeps the
    // mesh for the outputs written meanwhile; the solver shares it (no copy when the file keeps
    // its order).
    const bool one_field = !(o.separate || o.matrix);
    GeodesicSolver solver =
        one_field ? GeodesicSolver(std::move(in.mesh), so)
                  : GeodesicSolver(std::shared_ptr<const TriangleMesh>(&in.mesh, [](const TriangleMesh*) {}), so);
    ctx.timer().add("layout", solver.timings().layout);
    ctx.timer().add("build", solver.timings().build);
    const SolverTimings& bt = solver.timings();
    cli::Json& phases = ctx.stats()["build_phases"];
    phases["connectivity"] = bt.connectivity;
    phases["input_tables"] = bt.input_tables;
    phases["vertex_analysis"] = bt.vertex_analysis;
    phases["delaunay"] = bt.delaunay;
    GeodesicOptions go;
    go.strategy = strategy;
    go.precision = precision;
    go.f = o.f;
    go.max_distance = max_distance;
    go.want_face_distances = false;   // the outputs are per vertex: 12 bytes per face less
    // One field: the propagation's own threads (0 = automatic); --separate / --matrix spread
    // the queries instead, each on one thread.
    if (!(o.separate || o.matrix)) go.threads = o.threads;
    ctx.settings()["strategy"] = o.strategy;
    ctx.settings()["precision"] = o.precision;
    ctx.settings()["precision_used"] = solver.resolved_precision(precision) == Precision::single ? "single" : "double";
    ctx.settings()["heuristic"] = o.heuristic;
    ctx.settings()["step"] = o.f;
    ctx.settings()["layout"] = !so.optimize_layout      ? "input order"
                               : so.faces_only_layout ? "faces by smallest vertex"
                               : so.spatial_layout    ? "z-order"
                                                      : "bottom-up clustering";
    ctx.settings()["layout_reason"] = layout.reason;
    if (layout.order.random_log_gap > 0) {
      ctx.operations()["file_order_log_gap"] = layout.order.file_log_gap;
      ctx.operations()["random_order_log_gap"] = layout.order.random_log_gap;
      ctx.operations()["file_face_spread"] = layout.order.face_spread;
      ctx.operations()["random_face_spread"] = layout.order.random_face_spread;
    }
    ctx.settings()["intrinsic_delaunay"] = so.intrinsic_delaunay;
    ctx.operations()["intrinsic_flips"] = solver.intrinsic_flips();
    ctx.operations()["window_corners"] = solver.window_corners();
    ctx.operations()["duplicate_faces_skipped"] = solver.duplicate_faces();
    if (solver.duplicate_faces())
      ctx.note(std::to_string(solver.duplicate_faces()) +
               " faces repeat another face's three vertices and were left out (each face counts once)");
    ctx.stats()["memory"]["state_bytes_per_vertex"] =
        solver.num_vertices() ? double(solver.state_bytes(precision)) / double(solver.num_vertices()) : 0.0;
    if (o.separate || o.matrix) {
      run_many(ctx, o, in, src, solver, go);
      return;
    }
    result = ctx.timer().time("compute", [&] { return solver.compute(src.sources, go); });
    in.mesh = ctx.timer().time("write", [&] { return std::move(solver).release_mesh(); });
  }
  report_result(ctx, result, in.mesh.num_faces());
  const bool labels = o.labels || src.sources.size() > 1;
  ctx.timer().time("write", [&] {
    write_field(o.output, in, result.vertex_distance, result.vertex_source, labels, o.ascii);
  });
  if (o.preview.wanted())
    ctx.timer().time("preview", [&] {
      render::render_field_preview(o.preview.png, in.mesh, result.vertex_distance, src.positions, preview);
    });
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  return gsp::cli::run_app(
      argc, argv, "gsp-geodesic",
      "Geodesic distances on a triangle mesh by Geodesic Source Propagation.",
      [&](CLI::App& app) { add_options(app, options); },
      [&](gsp::cli::Context& ctx) { run(ctx, options); });
}
