#pragma once
// gsp-geodesic on a point cloud (--domain points): gsp::pointcloud over k nearest neighbours;
// the preview picture is drawn on the cloud's local triangles.
#include "options.hpp"

#include <gsp/cli/app.hpp>
#include <gsp/cli/load.hpp>
#include <gsp/render/render.hpp>

namespace gsp::geodesic_app {

void run_points(cli::Context& ctx, const Options& options, const cli::LoadedMesh& in, double max_distance,
                const render::RenderOptions& preview);

}  // namespace gsp::geodesic_app
