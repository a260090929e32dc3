#pragma once
// --from / --to values: a vertex index ("42", the file's numbering), a 3D point snapped onto
// the surface ("x,y,z"), or a point inside a face ("F:u,v", weights of corners 1 and 2).
#include <gsp/cli/load.hpp>
#include <gsp/pathfinding/path.hpp>

#include <string>

namespace gsp::path_app {

struct ResolvedEndpoint {
  pathfinding::Endpoint endpoint;   // on the loaded (possibly welded) mesh
  Vec3 position;
  double snap_distance = 0;         // how far an "x,y,z" point was moved onto the surface
};

// Throws cli::UsageError for malformed text, InvalidInput for a missing vertex or face.
ResolvedEndpoint resolve_endpoint(const std::string& text, const std::string& option, const cli::LoadedMesh& in);

}  // namespace gsp::path_app
