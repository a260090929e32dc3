#include "line_sources.hpp"

#include "output.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/errors.hpp>
#include <gsp/lines/line_distances.hpp>
#include <gsp/lines/polyline_text.hpp>
#include <gsp/render/render.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace gsp::geodesic_app {

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path, "", "cannot open the polyline file");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// "a-b,b-c,..." in the file's vertex numbering.
std::vector<std::array<std::size_t, 2>> parse_edges(const std::string& text) {
  std::vector<std::array<std::size_t, 2>> out;
  std::stringstream list(text);
  for (std::string pair; std::getline(list, pair, ',');) {
    const std::size_t dash = pair.find('-');
    auto number = [&](const std::string& s) {
      if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos)
        throw cli::UsageError("--source-edges: \"" + pair + "\" is not a vertex pair a-b");
      return std::stoull(s);
    };
    if (dash == std::string::npos) throw cli::UsageError("--source-edges: \"" + pair + "\" is not a vertex pair a-b");
    out.push_back({number(pair.substr(0, dash)), number(pair.substr(dash + 1))});
  }
  if (out.empty()) throw cli::UsageError("--source-edges: no vertex pair given");
  return out;
}

lines::LineSource edges_source(const Options& o, const cli::LoadedMesh& in) {
  const auto pairs = parse_edges(o.source_edges);
  std::vector<std::array<Index, 2>> edges;
  for (const auto& [a, b] : pairs) edges.push_back({in.mesh_vertex(a), in.mesh_vertex(b)});
  try {
    return lines::edge_source(in.mesh, edges);
  } catch (const InvalidInput&) {
    // Found again pair by pair, so the message names the pair as the user wrote it (the
    // library speaks of the welded mesh's vertices).
    for (std::size_t i = 0; i < edges.size(); ++i) {
      try {
        lines::edge_source(in.mesh, {edges[i]});
      } catch (const InvalidInput&) {
        const std::string name = std::to_string(pairs[i][0]) + "-" + std::to_string(pairs[i][1]);
        throw InvalidInput("--source-edges: " + name +
                           (edges[i][0] == edges[i][1] ? " repeats a vertex" : " is not an edge of the mesh"));
      }
    }
    throw;
  }
}

lines::LineSource polyline_file_source(const std::string& path, const TriangleMesh& mesh) {
  const std::vector<lines::Polyline> polylines = lines::parse_polylines(read_text(path), path);
  try {
    return lines::polyline_source(mesh, polylines);
  } catch (const InvalidInput& e) {   // name the polyline file, not the mesh
    throw IoError(path, "", e.what());
  }
}

void report(cli::Context& ctx, const lines::LineSource& src, const lines::LineResult& r) {
  report_distances(ctx, r.vertex_distance);
  cli::Json& res = ctx.stats()["result"];
  res["segments"] = r.stats.segments;
  res["pieces"] = r.stats.pieces;
  res["faces_seeded"] = r.stats.faces_seeded;
  res["max_snap_distance"] = src.max_snap_distance;
  cli::Json& ops = ctx.operations();
  ops["candidates"] = r.stats.candidates;
  ops["waves_accepted"] = r.stats.waves_accepted;
  ops["bends"] = r.stats.bends;
  ops["expansions"] = r.stats.expansions;
  ops["stale_skipped"] = r.stats.stale_skipped;
  ops["faces_reached"] = r.stats.faces_reached;
  ops["max_waves_per_face"] = r.stats.max_waves_per_face;
  ops["raised_to_line"] = r.stats.raised_to_line;
  ops["relaxed_vertices"] = r.stats.relaxed_vertices;
  ops["relaxation_rounds"] = r.stats.relaxation_rounds;
  ops["pseudo_sources"] = r.stats.pseudo_sources;
}

}  // namespace

bool wants_line_sources(const Options& o) {
  return !o.source_polyline.empty() || !o.source_edges.empty() || o.source_boundary;
}

void run_line_sources(cli::Context& ctx, const Options& o, const cli::LoadedMesh& in, double max_distance,
                      const render::RenderOptions& preview) {
  if (!o.source_vertices.empty() || !o.source_points.empty() || !o.source_faces.empty())
    throw cli::UsageError("line sources (--source-polyline, --source-edges, --source-boundary) do not mix with "
                          "--source-vertex, --source-point or --source-face");
  if (o.method != "gsp") throw cli::UsageError("line sources need --method gsp");
  if (o.separate || o.matrix) throw cli::UsageError("line sources give one field: not with --separate or --matrix");
  if (in.mesh.is_point_cloud()) throw cli::UsageError("line sources need a mesh with faces, not a point cloud");

  lines::LineSource src;
  ctx.timer().time("sources", [&] {
    if (!o.source_polyline.empty()) lines::append(src, polyline_file_source(o.source_polyline, in.mesh));
    if (!o.source_edges.empty()) lines::append(src, edges_source(o, in));
    if (o.source_boundary) lines::append(src, lines::boundary_source(in.mesh));
  });
  lines::LineOptions lo;
  lo.max_distance = max_distance;
  lo.heuristic = parse_heuristic(o.heuristic);
  ctx.settings()["method"] = "gsp-lines";
  ctx.settings()["precision"] = "double";
  ctx.settings()["heuristic"] = o.heuristic;
  ctx.settings()["sources"] = src.num_segments();
  if (std::isfinite(max_distance)) ctx.settings()["max_distance"] = max_distance;
  const lines::LineResult r = ctx.timer().time("compute", [&] { return lines::line_distances(in.mesh, src, lo); });
  report(ctx, src, r);
  ctx.timer().time("write", [&] { write_field(o.output, in, r.vertex_distance, r.vertex_segment, true, o.ascii); });
  if (o.preview.wanted()) {
    std::vector<Vec3> ends;
    for (const auto& s : src.segments) ends.push_back(s[0]), ends.push_back(s[1]);
    ctx.timer().time("preview", [&] { render::render_field_preview(o.preview.png, in.mesh, r.vertex_distance, ends, preview); });
  }
}

}  // namespace gsp::geodesic_app
