#include "endpoints.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/cli/parse.hpp>
#include <gsp/closest_point.hpp>
#include <gsp/errors.hpp>

#include <string>
#include <vector>

namespace gsp::path_app {

ResolvedEndpoint resolve_endpoint(const std::string& text, const std::string& option, const cli::LoadedMesh& in) {
  const TriangleMesh& mesh = in.mesh;
  ResolvedEndpoint r;
  if (text.find(':') != std::string::npos) {
    r.endpoint = cli::parse_face_point(text, option);
    if (!r.endpoint.exists_in(mesh)) throw InvalidInput(option + ": " + r.endpoint.missing_from(mesh));
  } else if (text.find(',') != std::string::npos) {
    const ClosestPoint s = closest_surface_point(mesh, cli::parse_vec3(text, option));
    r.endpoint = s.point;
    r.snap_distance = s.distance;
  } else {
    const std::vector<Index> v = cli::parse_index_list(text, option);
    if (v.size() != 1) throw cli::UsageError(option + ": \"" + text + "\": one vertex index, x,y,z or F:u,v");
    r.endpoint = pathfinding::Endpoint::at_vertex(in.mesh_vertex(v[0]));
  }
  pathfinding::check_endpoint(mesh, r.endpoint);
  r.position = r.endpoint.position(mesh);
  return r;
}

}  // namespace gsp::path_app
