#include "options.hpp"

#include <gsp/strategy_names.hpp>
#include "metric_option.hpp"

#include <gsp/cli/app.hpp>

#include <CLI/CLI.hpp>

#include <fstream>
#include <sstream>

namespace gsp::geodesic_app {

void add_options(CLI::App& app, Options& o) {
  app.add_option("INPUT", o.input, "input mesh or point cloud (.ply .obj .off .stl .gltf .glb .xyz)")->required();
  app.add_option("-o,--output", o.output,
                 "output: .ply (float distance + quality + colours), .glb/.gltf (_DISTANCE + COLOR_0), "
                 ".obj/.off (colours), .txt (one distance per input vertex)")
      ->required();
  app.add_option("--source-vertex", o.source_vertices, "source vertices (input vertex indices)")
      ->type_name("I[,J,...]");
  app.add_option("--source-point", o.source_points, "source at the surface point closest to x,y,z")
      ->type_name("X,Y,Z");
  app.add_option("--source-face", o.source_faces,
                 "source inside face F at barycentric weights u, v of its corners 1 and 2")
      ->type_name("F:U,V");
  app.add_option("--source-polyline", o.source_polyline,
                 "source: the polylines of FILE (OBJ `l` elements, or one \"x y z\" per line) laid onto the "
                 "surface; distance to the segments, label = nearest segment (docs/lines.md)")
      ->type_name("FILE");
  app.add_option("--source-edges", o.source_edges, "source: these mesh edges (input vertex pairs)")
      ->type_name("A-B[,B-C,...]");
  app.add_flag("--source-boundary", o.source_boundary, "source: every boundary edge of the mesh");
  app.add_option("--max-distance", o.max_distance,
                 "stop at this distance (model units); farther vertices are unreached")
      ->type_name("D");
  app.add_option("--method", o.method,
                 "gsp (default), windows (three windows per face instead of one virtual source: about 8x as "
                 "accurate on the corpus, 13-26x slower; vertex and face sources, --separate, --matrix; "
                 "docs/benchmarks.md), "
                 "dijkstra (edge graph, for "
                 "comparison), or graph-gsp (point clouds: virtual sources over the k-NN links instead of GSP "
                 "on the local triangles)")
      ->check(CLI::IsMember({"gsp", "windows", "dijkstra", "graph-gsp"}));
  app.add_option("--strategy", o.strategy,
                 "queue strategy: speed-limiter (default), speed-limiter-postpone, static-postpone, dynamic-postpone, "
                 "hybrid-postpone, bfs, priority-queue");
  app.add_option("--precision", o.precision,
                 "auto (default: double where a face is too thin for float lengths), single or double")
      ->check(CLI::IsMember({"auto", "single", "double"}));
  app.add_option("--heuristic", o.heuristic,
                 "visibility heuristic: published (default), centroid, opposite-corner, or a file "
                 "with 20 numbers");
  app.add_option("--step", o.f, "dual-queue step f in mean edge lengths (default 1)")
      ->check(CLI::PositiveNumber);
  app.add_option("--layout", o.layout,
                 "cache reordering: auto (default: on, except for one field on a file whose order is already "
                 "coherent; one field on a file of 524,288 faces or more whose vertices are coherent and faces are not: "
                 "the faces sorted), on, off")
      ->check(CLI::IsMember({"auto", "on", "off"}));
  app.add_flag("--no-layout", o.no_layout, "the same as --layout off");
  app.add_flag("--input-faces", o.input_faces,
               "propagate on the input's triangles, not on their intrinsic Delaunay flip");
  app.add_flag("--labels", o.labels, "also write the index of the nearest source per vertex");
  app.add_flag("--ascii", o.ascii, "ASCII PLY instead of binary");
  app.add_option("--domain", o.domain,
                 "mesh, points (the vertices as a point cloud, k nearest neighbours), or auto (default: "
                 "points when the file has no faces)")
      ->check(CLI::IsMember({"mesh", "points", "auto"}));
  app.add_option("--neighbours", o.neighbours, "--domain points: neighbours per point (default 10)")
      ->check(CLI::Range(2u, 200u));
  app.add_flag("--separate", o.separate,
               "one field per source (written to OUT-0.ext, OUT-1.ext, ...), computed in parallel");
  app.add_flag("--matrix", o.matrix,
               "the matrix of distances between the --source-vertex vertices (.txt: spaces, .csv: commas)");
  app.add_option("--threads", o.threads, "threads: for --separate / --matrix the queries in parallel (default: all); "
                 "for one field the query's own (default: automatic, all on meshes of 200k+ faces, one source "
                 "included); the preparation uses two on meshes of 200k+ faces, and a text file of 1 MB+ is parsed on all "
                 "cores, unless this is 1");
  add_metric_option(app, o.metric);
  render::add_preview_options(app, o.preview, "the field with iso-lines, sources in red");
  cli::add_load_options(app, o.load);
}

Strategy parse_strategy(const std::string& name) {
  if (const auto s = strategy_from_name(name)) return *s;
  throw cli::UsageError("--strategy: \"" + name + "\" is not one of " + strategy_names());
}

Precision parse_precision(const std::string& name) {
  if (name == "double") return Precision::double_precision;
  return name == "single" ? Precision::single : Precision::automatic;
}

VisibilityHeuristic parse_heuristic(const std::string& name) {
  if (name == "published") return VisibilityHeuristic::published();
  if (name == "centroid") return VisibilityHeuristic::centroid();
  if (name == "opposite-corner") return VisibilityHeuristic::opposite_corner();
  std::ifstream in(name);
  if (!in) throw cli::UsageError("--heuristic: \"" + name +
                                 "\" is neither published, centroid, opposite-corner nor a readable file");
  std::stringstream text;
  text << in.rdbuf();
  try {
    return VisibilityHeuristic::from_string(text.str());
  } catch (const InvalidInput& e) {
    throw cli::UsageError("--heuristic " + name + ": " + e.what());
  }
}

}  // namespace gsp::geodesic_app
