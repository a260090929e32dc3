#pragma once
// gsp-geodesic on a point cloud (--domain points): gsp::pointcloud over k nearest neighbours.
#include "options.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/cli/load.hpp>

namespace gsp::geodesic_app {

void run_points(cli::Context& ctx, const Options& options, const cli::LoadedMesh& in, double max_distance);

}  // namespace gsp::geodesic_app
