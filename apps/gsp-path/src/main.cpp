// gsp-path: geodesic shortest paths on a triangle mesh (paper Section 5.8, Fig. 12a,b). A GSP
// field from --from (in A* order towards the --to points by default, stopped once they are
// settled), traced back from every --to through the per-face virtual sources and pulled taut
// in the faces it crosses. Exit code 3 when some --to cannot be reached (another component).
#include "endpoints.hpp"
#include "write_paths.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/cli/load.hpp>
#include <gsp/cli/parse.hpp>
#include <gsp/pathfinding/path_tracer.hpp>
#include <gsp/pathfinding/shortest_path.hpp>
#include <gsp/render/preview_cli.hpp>
#include <gsp/render/render.hpp>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace {

using namespace gsp;

struct Options {
  std::string input, output, from, method = "windows", precision = "auto";
  std::vector<std::string> to;
  bool one_end = false;
  render::PreviewRequest preview;
  cli::LoadOptions load;
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("INPUT", o.input, "input mesh (.ply .obj .off .stl .gltf .glb)")->required();
  app.add_option("--from", o.from, "start: a vertex index, a point x,y,z (snapped onto the surface) or F:u,v "
                 "(a point in face F)")->required()->type_name("V|x,y,z|F:u,v");
  app.add_option("--to", o.to, "end point(s), same forms as --from; repeat for several paths from one field")
      ->required()->type_name("V|x,y,z|F:u,v");
  app.add_option("-o,--output", o.output, "paths: .obj (l elements), .ply (edge element), .glb/.gltf "
                 "(LINE_STRIP), .json (points with face and barycentric weights)")->required();
  app.add_option("--method", o.method, "windows (default: a few windows per face, goal-directed, near exact), "
                 "astar (GSP, goal-directed: about 7x faster, can take a corridor up to a few % longer), "
                 "settle (GSP in Dijkstra order), full (GSP over the whole mesh), dijkstra-edges (along edges)")
      ->check(CLI::IsMember({"windows", "astar", "settle", "full", "dijkstra-edges"}));
  app.add_flag("--one-end", o.one_end, "trace from --from's field only (half the cost; by default every "
               "--to also propagates back towards --from and the shorter of the two paths is kept)");
  app.add_option("--precision", o.precision, "auto (default: double where faces are too thin for float), single or double")
      ->check(CLI::IsMember({"auto", "single", "double"}));
  render::add_preview_options(app, o.preview, "the mesh with the paths");
  cli::add_load_options(app, o.load);
}

pathfinding::PathMethod method_of(const std::string& m) {
  if (m == "settle") return pathfinding::PathMethod::settle;
  if (m == "full") return pathfinding::PathMethod::full;
  if (m == "dijkstra-edges") return pathfinding::PathMethod::dijkstra_edges;
  if (m == "windows") return pathfinding::PathMethod::windows;
  return pathfinding::PathMethod::astar;
}

// Returns how many end points have no path.
std::size_t run(cli::Context& ctx, const Options& o) {
  const render::RenderOptions preview = render::preview_options(o.preview);
  const std::string lower = [&] {
    std::string s = o.output;
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
  }();
  if (!(lower.size() >= 5 && lower.compare(lower.size() - 5, 5, ".json") == 0))
    cli::output_format(o.output, {io::Format::obj, io::Format::ply, io::Format::gltf, io::Format::glb});

  const cli::LoadedMesh in = cli::load_input(ctx, o.input, o.load);
  const path_app::ResolvedEndpoint from = path_app::resolve_endpoint(o.from, "--from", in);
  std::vector<pathfinding::Endpoint> ends;
  double snapped = from.snap_distance;
  for (const std::string& t : o.to) {
    const path_app::ResolvedEndpoint e = path_app::resolve_endpoint(t, "--to", in);
    ends.push_back(e.endpoint);
    snapped = std::max(snapped, e.snap_distance);
  }
  ctx.settings()["method"] = o.method;
  ctx.settings()["precision"] = o.precision;
  ctx.settings()["targets"] = ends.size();
  ctx.settings()["both_ends"] = !o.one_end && o.method != "dijkstra-edges";

  auto build = ctx.timer().scope("build");
  const pathfinding::PathTracer tracer(in.mesh);
  const bool edges = o.method == "dijkstra-edges";
  // The windows need no GSP solver (one is built only if an end point needs GSP's A* path).
  std::unique_ptr<GeodesicSolver> solver;
  if (!edges && o.method != "windows") solver = std::make_unique<GeodesicSolver>(in.mesh);
  if (o.method == "windows") tracer.windows();   // its preparation, timed as the build
  build.stop();

  pathfinding::PathQueryResult r;
  if (edges) {
    r = pathfinding::edge_paths(in.mesh, tracer, from.endpoint, ends);
  } else {
    pathfinding::PathQueryOptions po;
    po.method = method_of(o.method);
    po.precision = o.precision == "double"   ? Precision::double_precision
                   : o.precision == "single" ? Precision::single
                                             : Precision::automatic;
    po.both_ends = !o.one_end;
    r = solver ? pathfinding::shortest_paths(*solver, tracer, from.endpoint, ends, po)
               : pathfinding::shortest_paths(tracer, from.endpoint, ends, po);
  }
  ctx.timer().add("compute", r.compute_seconds);
  ctx.timer().add("trace", r.trace_seconds);

  std::size_t missing = 0;
  cli::Json& list = ctx.stats()["result"]["paths"] = cli::Json::array();
  for (std::size_t k = 0; k < r.paths.size(); ++k) {
    const pathfinding::GeodesicPath& p = r.paths[k];
    cli::Json j = cli::Json::object();
    j["to"] = o.to[k];
    j["found"] = p.found();
    if (p.found()) {
      j["length"] = p.length;
      j["field_distance"] = p.field_distance;
      j["points"] = p.points.size();
    } else {
      ++missing;
    }
    list.push_back(std::move(j));
  }
  ctx.stats()["result"]["found"] = r.paths.size() - missing;
  ctx.stats()["result"]["reversed"] = r.reversed;
  ctx.stats()["result"]["edge_fallbacks"] = r.edge_fallbacks;
  ctx.stats()["result"]["astar_fallbacks"] = r.astar_fallbacks;
  ctx.stats()["result"]["astar_shorter"] = r.astar_shorter;
  ctx.stats()["result"]["max_snap_distance"] = snapped;
  cli::Json& ops = ctx.operations();
  ops["faces_expanded"] = r.stats.faces_reached;
  ops["faces"] = in.mesh.num_faces();
  ops["faces_expanded_fraction"] = in.mesh.num_faces() ? double(r.stats.faces_reached) / double(in.mesh.num_faces()) : 0.0;
  ops["update_steps"] = r.stats.update_steps;
  ops["iterations"] = r.stats.iterations;
  ops["reverse_faces_expanded"] = r.reverse_stats.faces_reached;

  if (missing == r.paths.size()) return missing;   // nothing to write
  ctx.timer().time("write", [&] { path_app::write_paths(o.output, r.paths); });
  if (o.preview.wanted())
    ctx.timer().time("preview", [&] {
      render::Scene scene;
      scene.mesh = in.mesh;
      for (const pathfinding::GeodesicPath& p : r.paths) {
        if (!p.found()) continue;
        std::vector<Vec3> line;
        for (const pathfinding::PathPoint& q : p.points) line.push_back(q.position);
        scene.polylines.push_back(std::move(line));
        scene.points.push_back(p.points.back().position);
      }
      scene.sources.push_back(from.position);
      render::write_png(o.preview.png, render::render(scene, preview));
    });
  return missing;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  std::size_t missing = 0;
  const int rc = gsp::cli::run_app(
      argc, argv, "gsp-path",
      "Geodesic shortest paths between surface points (GSP field, A* order, traced and pulled taut).",
      [&](CLI::App& app) { add_options(app, options); },
      [&](gsp::cli::Context& ctx) { missing = run(ctx, options); });
  if (rc != 0 || missing == 0) return rc;
  // Not an error of the input: the end points lie on parts of the mesh the start cannot reach.
  std::fprintf(stderr, "gsp-path: no path to %zu of %zu end point(s): not connected to --from%s\n", missing,
               options.to.size(), missing < options.to.size() ? " (the others were written)" : "");
  return 3;
}
