#include "report.hpp"

#include <gsp/cli/topology_json.hpp>
#include <gsp/errors.hpp>
#include <gsp/io/mesh_io.hpp>

#include <cstdint>

namespace gsp::cvt_app {

namespace {

// A colour per region that neighbours are unlikely to share: the label hashed to a hue.
std::array<std::uint8_t, 4> region_colour(Index label) {
  if (label == kInvalidIndex) return {128, 128, 128, 255};
  std::uint32_t x = label * 2654435761u;
  x ^= x >> 15;
  const double h = double(x % 3600) / 600.0;   // hue in [0, 6)
  const double s = 0.55 + 0.4 * double((x >> 12) % 100) / 100.0, v = 0.95;
  const double c = v * s, m = v - c, xx = c * (1 - std::abs(std::fmod(h, 2.0) - 1));
  double r = 0, g = 0, b = 0;
  switch (int(h)) {
    case 0: r = c, g = xx; break;
    case 1: r = xx, g = c; break;
    case 2: g = c, b = xx; break;
    case 3: g = xx, b = c; break;
    case 4: r = xx, b = c; break;
    default: r = c, b = xx; break;
  }
  auto byte = [&](double t) { return std::uint8_t(std::lround(255 * (t + m))); };
  return {byte(r), byte(g), byte(b), 255};
}

}  // namespace

void report_cvt(cli::Context& ctx, const cvt::SurfaceRemeshResult& cvt) {
  const cvt::CvtStats& s = cvt.cvt_stats;
  cli::Json& res = ctx.stats()["result"];
  res["sites"] = cvt.sites;
  res["iterations"] = s.iterations;
  res["converged"] = s.converged;
  res["energy"] = cvt.energy;
  res["energy_curve"] = cli::Json::array_of(cvt.energy_curve);
  res["area"] = cvt.area;
  cli::Json& ops = ctx.operations();
  ops["initial_sites"] = s.initial_sites;
  ops["feature_sites"] = s.feature_sites;
  ops["feature_curves"] = s.feature_curves;
  ops["short_feature_curves"] = s.short_feature_curves;
  ops["cone_sites"] = s.cone_sites;
  ops["sites_added"] = s.sites_added;
  ops["sites_relocated"] = s.sites_relocated;
  ops["split_regions"] = s.split_regions;
  ops["nondisk_regions"] = s.nondisk_regions;
  ops["junction_fixes"] = s.junction_fixes;
  ops["closing_sites"] = s.closing_sites;
  ops["closing_rounds"] = s.closing_rounds;
  ops["closing_steps"] = s.closing_steps;
  ops["rejected_steps"] = s.rejected_steps;
  ops["propagations"] = s.propagations;
  ops["update_steps"] = s.update_steps;
  ops["working_faces"] = s.working_faces;
  ops["subdivisions"] = s.subdivisions;
  ops["bisections"] = s.bisections;
  ops["planar_flips"] = s.planar_flips;
  cli::PhaseTimer& t = ctx.timer();
  t.add("subdivide", s.timings.subdivide);
  t.add("build", s.timings.prepare);
  t.add("initial_sites", s.timings.initial);
  t.add("compute", s.timings.propagate);
  t.add("centroids", s.timings.centroids);
  t.add("fix_regions", s.timings.fix);
}

void report_remesh(cli::Context& ctx, const cvt::SurfaceRemeshResult& remesh, const TopologyReport& input,
                   const TopologyReport& output) {
  cli::Json& res = ctx.stats()["remesh"];
  res["vertices"] = remesh.mesh.num_vertices();
  res["triangles"] = remesh.mesh.num_faces();
  res["components_remeshed"] = remesh.remeshed();
  res["components_kept"] = remesh.components.size() - remesh.remeshed();
  res["vertices_split"] = remesh.vertices_split;
  res["boundary_vertices_stitched"] = remesh.boundary_vertices_stitched;
  res["duplicate_faces_removed"] = remesh.duplicate_faces_removed;
  res["repeated_vertex_faces_removed"] = remesh.repeated_vertex_faces_removed;
  res["junctions"] = remesh.remesh_stats.junctions;
  res["junctions_over_three"] = remesh.remesh_stats.junctions_over_three;
  res["duplicate_triangles"] = remesh.remesh_stats.duplicate_triangles;
  res["skipped_junctions"] = remesh.remesh_stats.skipped_junctions;
  res["unused_sites"] = remesh.remesh_stats.unused_sites;
  res["flips"] = remesh.remesh_stats.flips;
  res["smoothing_moves"] = remesh.remesh_stats.smoothing_moves;
  res["smoothing_boundary_moves"] = remesh.remesh_stats.smoothing_boundary_moves;
  res["boundary_collapses"] = remesh.remesh_stats.boundary_collapses;
  res["boundary_splits"] = remesh.remesh_stats.boundary_splits;
  res["boundary_snaps"] = remesh.remesh_stats.boundary_snaps;
  res["pulls"] = remesh.remesh_stats.pulls;
  res["far_point_insertions"] = remesh.remesh_stats.far_point_insertions;
  res["far_point_attempts"] = remesh.remesh_stats.far_point_attempts;
  res["fold_refinements"] = remesh.remesh_stats.fold_refinements;
  ctx.stats()["topology"]["input"] = cli::topology_json(input);
  ctx.stats()["topology"]["output"] = cli::topology_json(output);
  cli::Json& list = ctx.stats()["components"] = cli::Json::array();
  for (const cvt::ComponentReport& c : remesh.components) {
    cli::Json j = cli::Json::object();
    j["input_vertices"] = c.input_vertices;
    j["input_faces"] = c.input_faces;
    j["area"] = c.area;
    j["euler_characteristic"] = static_cast<long long>(c.euler_characteristic);
    j["boundary_loops"] = c.boundary_loops;
    j["sites"] = c.sites;
    j["faces_flipped"] = c.faces_flipped;
    j["features_dropped"] = c.features_dropped;
    j["retries"] = c.retries;
    j["grown"] = c.grown;
    j["output_vertices"] = c.output_vertices;
    j["output_faces"] = c.output_faces;
    j["outcome"] = cvt::outcome_name(c.outcome);
    j["reason"] = c.reason;
    j["by_edge_operations"] = c.by_edge_operations;
    j["cvt_failure"] = c.cvt_failure;
    j["edge_failure"] = c.edge_failure;
    list.push_back(std::move(j));
  }
}

void note_kept_components(cli::Context& ctx, const cvt::SurfaceRemeshResult& r) {
  const std::vector<std::string> kept = cvt::kept_components(r);
  if (!kept.empty() && kept.size() == r.components.size())
    throw Error("no component could be remeshed; " + kept.front() + (kept.size() > 1 ? "; ..." : ""));
  for (std::size_t i = 0; i < kept.size() && i < 20; ++i) ctx.note("kept as it is: " + kept[i]);
  std::size_t retried = 0;
  for (const cvt::ComponentReport& c : r.components) retried += c.retries && c.outcome == cvt::ComponentOutcome::remeshed;
  if (retried)
    ctx.note(std::to_string(retried) + " components remeshed from other initial sites (the first remesh did not have the "
                                       "component's topology)");
  // With --method edges the edge operations come first: said only where the CVT was tried
  // before them (cvt_failure), and the other way round (edge_failure).
  std::size_t by_edges = 0, by_cvt = 0;
  for (const cvt::ComponentReport& c : r.components) {
    if (c.outcome != cvt::ComponentOutcome::remeshed) continue;
    by_edges += c.by_edge_operations && !c.cvt_failure.empty();
    by_cvt += !c.by_edge_operations && !c.edge_failure.empty();
  }
  if (by_edges)
    ctx.note(std::to_string(by_edges) + " components remeshed by edge operations after the CVT (cvt_failure in --stats "
                                        "says why: mostly no dual with the component's topology; their vertices belong "
                                        "to no region)");
  if (by_cvt)
    ctx.note(std::to_string(by_cvt) + " components remeshed by the CVT (their remesh by edge operations was not kept; "
                                      "edge_failure in --stats says why)");
  std::size_t dropped = 0;
  for (const cvt::ComponentReport& c : r.components) dropped += c.features_dropped && c.outcome == cvt::ComponentOutcome::remeshed;
  if (dropped)
    ctx.note(std::to_string(dropped) + " components remeshed without their feature curves (with them the remesh did not "
                                       "have the component's topology)");
  if (r.boundary_vertices_stitched)
    ctx.note(std::to_string(r.boundary_vertices_stitched) +
             " boundary vertices at the same position as another were joined (seams closed)");
  if (r.duplicate_faces_removed || r.repeated_vertex_faces_removed)
    ctx.note(std::to_string(r.duplicate_faces_removed) + " faces on the same three vertices as an earlier face and " +
             std::to_string(r.repeated_vertex_faces_removed) + " faces with a repeated vertex were left out");
  if (r.vertices_split)
    ctx.note(std::to_string(r.vertices_split) +
             " vertices where fans of faces only touched were split (one per fan) before remeshing");
  if (kept.size() > 20) ctx.note(std::to_string(kept.size() - 20) + " more components kept as they are (--stats lists them)");
}

void report_quality(cli::Context& ctx, const cvt::MeshQuality& q, const cvt::HausdorffDistance& h) {
  cli::Json& j = ctx.stats()["quality"];
  j["min_angle"] = q.min_angle;
  j["max_angle"] = q.max_angle;
  j["mean_min_angle"] = q.mean_min_angle;
  j["percent_below_30"] = 100.0 * q.below_30;
  j["mean_aspect_ratio"] = q.mean_aspect_ratio;
  j["max_aspect_ratio"] = q.max_aspect_ratio;
  j["degenerate_triangles"] = q.degenerate;
  j["mean_edge_length"] = q.mean_edge_length;
  cli::Json& hist = j["valence_histogram"] = cli::Json::object();
  for (std::size_t k = 0; k < q.valence_histogram.size(); ++k)
    if (q.valence_histogram[k]) hist[std::to_string(k)] = q.valence_histogram[k];
  cli::Json& hd = j["hausdorff"];
  hd["input_to_output"] = h.a_to_b;
  hd["output_to_input"] = h.b_to_a;
  hd["two_sided"] = h.two_sided;
  hd["mean"] = h.mean;
  hd["diagonal"] = h.diagonal;
  hd["percent_of_diagonal"] = 100.0 * h.relative;
}

void write_regions(const std::string& path, const cli::LoadedMesh& in, const std::vector<Index>& vertex_label) {
  const std::vector<Index> labels = in.to_file_order(vertex_label);
  io::VertexAttributes attributes;
  std::vector<std::int32_t> label(labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i) {
    label[i] = labels[i] == kInvalidIndex ? -1 : std::int32_t(labels[i]);
    attributes.colors.push_back(region_colour(labels[i]));
  }
  attributes.labels.emplace_back("label", std::move(label));
  io::write_mesh(path, in.file_mesh(), attributes);
}

}  // namespace gsp::cvt_app
