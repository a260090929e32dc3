#include "sources.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/cli/parse.hpp>
#include <gsp/closest_point.hpp>
#include <gsp/errors.hpp>

#include <algorithm>
#include <string>

namespace gsp::geodesic_app {

ResolvedSources resolve_sources(const Options& o, const cli::LoadedMesh& in) {
  ResolvedSources r;
  const TriangleMesh& mesh = in.mesh;
  for (const std::string& arg : o.source_vertices)
    for (Index file_vertex : cli::parse_index_list(arg, "--source-vertex")) {
      const Index v = in.mesh_vertex(file_vertex);   // the user counts the file's vertices
      r.sources.push_back(Source::at_vertex(v));
      r.positions.push_back(mesh.positions[v]);
    }
  for (const std::string& arg : o.source_points) {
    const Vec3 p = cli::parse_vec3(arg, "--source-point");
    const ClosestPoint s = closest_surface_point(mesh, p);
    r.sources.push_back(Source::at(s.point));
    r.positions.push_back(s.position);
    r.max_snap_distance = std::max(r.max_snap_distance, s.distance);
  }
  for (const std::string& arg : o.source_faces) {
    const SurfacePoint p = cli::parse_face_point(arg, "--source-face");
    if (!p.exists_in(mesh)) throw InvalidInput("--source-face: " + p.missing_from(mesh));
    r.sources.push_back(Source::at(p));
    r.positions.push_back(p.position(mesh));
  }
  if (r.sources.empty())
    throw cli::UsageError("no source: give --source-vertex, --source-point, --source-face, --source-polyline, "
                          "--source-edges or --source-boundary");
  return r;
}

}  // namespace gsp::geodesic_app
