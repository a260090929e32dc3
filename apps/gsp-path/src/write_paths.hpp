#pragma once
// Writing the paths: .obj/.ply/.gltf/.glb as polylines (gsp::io::write_polylines), .json with
// every point's face, barycentric weights and position.
#include <gsp/pathfinding/path.hpp>

#include <string>
#include <vector>

namespace gsp::path_app {

void write_paths(const std::string& path, const std::vector<pathfinding::GeodesicPath>& paths);

}  // namespace gsp::path_app
