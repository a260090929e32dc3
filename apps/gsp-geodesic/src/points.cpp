#include "points.hpp"

#include "batch_output.hpp"
#include "output.hpp"

#include <gsp/batch.hpp>
#include <gsp/cli/parse.hpp>
#include <gsp/pointcloud/point_cloud_geodesics.hpp>

#include <cmath>

namespace gsp::geodesic_app {

namespace {

// --separate: a field per source, OUT-0.ext, OUT-1.ext, ...; --matrix: the distances between
// the source points (row i: from source i). The queries run in parallel (gsp::parallel_for),
// as the mesh modes' do.
void run_points_many(cli::Context& ctx, const Options& o, const cli::LoadedMesh& in,
                     const pointcloud::PointCloudGeodesics& cloud, const std::vector<pointcloud::PointSource>& sources,
                     const pointcloud::PointGeodesicOptions& go) {
  const std::size_t n = sources.size();
  const unsigned threads = resolve_threads(o.threads, n);
  ctx.settings()["threads"] = threads;
  if (o.matrix) {
    std::vector<Index> points;   // (--matrix takes point indices only)
    for (const pointcloud::PointSource& s : sources) points.push_back(s.point);
    const std::vector<double> matrix = ctx.timer().time(
        "compute", [&] { return pointcloud::distance_matrix(cloud, points, points, go, threads); });
    ctx.stats()["result"]["matrix_size"] = n;
    ctx.timer().time("write", [&] { write_matrix(o.output, matrix, n); });
    return;
  }
  std::vector<pointcloud::PointCloudResult> fields(n);
  ctx.timer().time("compute", [&] {
    parallel_for(n, threads, [&](std::size_t i) { fields[i] = cloud.compute({sources[i]}, go); });
  });
  ctx.stats()["result"]["fields"] = n;
  ctx.timer().time("write", [&] {
    for (std::size_t i = 0; i < n; ++i)
      write_field(numbered_path(o.output, i), in, fields[i].distance, fields[i].source, false, o.ascii);
  });
}

}  // namespace

void run_points(cli::Context& ctx, const Options& o, const cli::LoadedMesh& in, double max_distance,
                const render::RenderOptions& preview) {
  if (!o.source_faces.empty()) throw cli::UsageError("--source-face needs faces: not with --domain points");
  pointcloud::PointCloudOptions po;
  po.neighbours.k = o.neighbours;
  // The other methods run on the graph alone; the preview is drawn on the triangles.
  po.local_triangles = o.method == "gsp" || o.preview.wanted();
  const pointcloud::PointCloudGeodesics cloud =
      ctx.timer().time("build", [&] { return pointcloud::PointCloudGeodesics(in.mesh, po); });

  std::vector<pointcloud::PointSource> sources;
  std::vector<Vec3> marks;   // the sources' positions, for the preview
  for (const std::string& arg : o.source_vertices)
    for (Index file_point : cli::parse_index_list(arg, "--source-vertex")) {
      const Index point = in.mesh_vertex(file_point);
      sources.push_back(pointcloud::PointSource::at_point(point));
      marks.push_back(in.mesh.positions[point]);
    }
  for (const std::string& arg : o.source_points) {
    sources.push_back(pointcloud::PointSource::at_position(cli::parse_vec3(arg, "--source-point")));
    marks.push_back(sources.back().position);
  }
  if (sources.empty()) throw cli::UsageError("no source: give --source-vertex or --source-point");

  pointcloud::PointGeodesicOptions go;
  go.method = o.method == "dijkstra"    ? pointcloud::PointMethod::dijkstra
              : o.method == "graph-gsp" ? pointcloud::PointMethod::graph_gsp
                                        : pointcloud::PointMethod::gsp;
  go.max_distance = max_distance;
  go.f = o.f;
  go.strategy = parse_strategy(o.strategy);
  ctx.settings()["domain"] = "points";
  ctx.settings()["method"] = o.method;
  ctx.settings()["strategy"] = o.strategy;
  ctx.settings()["neighbours"] = o.neighbours;
  ctx.settings()["sources"] = sources.size();
  if (o.separate || o.matrix) {
    run_points_many(ctx, o, in, cloud, sources, go);
    return;
  }
  const pointcloud::PointCloudResult r = ctx.timer().time("compute", [&] { return cloud.compute(sources, go); });

  const pointcloud::PointCloudStats& s = cloud.stats();
  cli::Json& cs = ctx.stats()["cloud"];
  cs["points"] = s.points;
  cs["unique_points"] = s.unique_points;
  cs["duplicates"] = s.duplicates;
  cs["components"] = s.components;
  cs["largest_component"] = s.largest_component;
  cs["links"] = s.links;
  cs["normals_from_input"] = s.normals_from_input;
  cs["normals_estimated"] = s.normals_estimated;
  cs["elliptic_points"] = s.elliptic_points;
  cs["local_triangles"] = s.local_triangles;
  cs["triangle_components"] = s.triangle_components;
  cs["points_without_triangle"] = s.points_without_triangle;
  cli::Json& ops = ctx.operations();
  ops["update_steps"] = r.stats.update_steps;
  ops["updates"] = r.stats.updates;
  ops["bends"] = r.stats.bends;
  ops["iterations"] = r.stats.iterations;
  ops["steep_links_used"] = r.stats.steep_links_used;
  ops["points_reached_over_links"] = r.stats.points_reached_over_links;
  std::size_t reached = 0;
  double far = 0;
  for (double d : r.distance)
    if (std::isfinite(d)) ++reached, far = std::max(far, d);
  ctx.stats()["result"]["points_reached"] = reached;
  ctx.stats()["result"]["points_unreached"] = r.distance.size() - reached;
  ctx.stats()["result"]["max_distance"] = far;
  ctx.timer().time("write", [&] {
    write_field(o.output, in, r.distance, r.source, o.labels || sources.size() > 1, o.ascii);
  });
  if (o.preview.wanted())
    ctx.timer().time("preview", [&] {
      TriangleMesh surface;
      surface.positions = in.mesh.positions;
      surface.triangles = cloud.local_triangles();
      render::render_field_preview(o.preview.png, surface, r.distance, marks, preview);
    });
}

}  // namespace gsp::geodesic_app
