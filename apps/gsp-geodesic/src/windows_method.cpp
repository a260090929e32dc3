#include "windows_method.hpp"

#include "batch_output.hpp"
#include "output.hpp"

#include <gsp/available_memory.hpp>
#include <gsp/batch.hpp>
#include <gsp/cli/app.hpp>
#include <gsp/window_geodesics.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace gsp::geodesic_app {

namespace {

// Values beyond the limit unreached, as GSP's bounded queries leave them.
void cut(std::vector<double>& distance, std::vector<Index>& label, double max_distance) {
  if (!std::isfinite(max_distance)) return;
  for (std::size_t v = 0; v < distance.size(); ++v)
    if (!(distance[v] <= max_distance)) distance[v] = std::numeric_limits<double>::infinity(), label[v] = kInvalidIndex;
}

}  // namespace

GeodesicResult run_windows(cli::Context& ctx, const Options& o, const cli::LoadedMesh& in,
                           const ResolvedSources& src, double max_distance) {
  bool face_points = false;
  for (const Source& s : src.sources) {
    if (s.offset != 0) throw cli::UsageError("--method windows: sources with an offset are not supported");
    face_points = face_points || !s.is_vertex();
  }
  // Points in faces name the input's triangles: the windows then propagate on them.
  const bool intrinsic = !o.input_faces && !face_points;
  WindowOptions wo;
  wo.windows = 3;
  ctx.settings()["windows_per_face"] = wo.windows;
  ctx.settings()["intrinsic_delaunay"] = intrinsic;
  const WindowGeodesics solver = ctx.timer().time("build", [&] { return WindowGeodesics(in.mesh, intrinsic); });
  GeodesicResult r;
  if (!(o.separate || o.matrix)) {
    WindowStats stats;
    WindowField field = ctx.timer().time("compute", [&] { return solver.field(src.sources, wo, &stats); });
    r.vertex_distance = std::move(field.vertex_distance);
    r.vertex_source = std::move(field.vertex_source);
    cut(r.vertex_distance, r.vertex_source, max_distance);
    ctx.operations()["window_updates"] = stats.window_updates;
    r.stats.relaxed_vertices = stats.relaxed;   // report_result writes the stats
    r.stats.faces_reached = stats.faces_reached;
    return r;
  }
  // A field per source, in parallel (WindowGeodesics::field is const: each call has its own
  // state), as GSP's compute_many.
  const std::size_t n = src.sources.size();
  // Every field is held until written (a distance and a label per vertex), as compute_many's.
  require_memory(std::to_string(n) + " fields", 12.0 * double(in.mesh.num_vertices()) * double(n));
  const unsigned threads = resolve_threads(o.threads, n);
  ctx.settings()["threads"] = threads;
  std::vector<std::vector<double>> distance(n);
  std::vector<std::vector<Index>> label(n);
  ctx.timer().time("compute", [&] {
    parallel_for(n, threads, [&](std::size_t i) {
      WindowField f = solver.field({src.sources[i]}, wo);
      distance[i] = std::move(f.vertex_distance);
      label[i] = std::move(f.vertex_source);
      cut(distance[i], label[i], max_distance);
    });
  });
  if (o.matrix) {
    std::vector<double> m(n * n);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) m[i * n + j] = distance[i][src.sources[j].element];
    ctx.stats()["result"]["matrix_size"] = n;
    ctx.timer().time("write", [&] { write_matrix(o.output, m, n); });
    return r;
  }
  ctx.stats()["result"]["fields"] = n;
  ctx.timer().time("write", [&] {
    for (std::size_t i = 0; i < n; ++i)
      write_field(numbered_path(o.output, i), in, distance[i], label[i], false, o.ascii);
  });
  return r;
}

}  // namespace gsp::geodesic_app
