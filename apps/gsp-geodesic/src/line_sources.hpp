#pragma once
// gsp-geodesic's line sources (--source-polyline, --source-edges, --source-boundary): distances
// to polylines on the surface through gsp::lines (docs/lines.md).
#include "options.hpp"

#include <gsp/cli/load.hpp>
#include <gsp/render/options.hpp>

namespace gsp::cli {
class Context;
}

namespace gsp::geodesic_app {

// True when any line-source option is given.
bool wants_line_sources(const Options& options);

// The whole run for line sources: UsageError when they are mixed with point sources or with
// options that do not apply (--method dijkstra, --separate, --matrix, a point cloud), IoError
// naming the polyline file for a bad one, InvalidInput for an edge that is not a mesh edge or
// a mesh without boundary. Writes the field with a per-vertex `source` label = nearest segment.
void run_line_sources(cli::Context& ctx, const Options& options, const cli::LoadedMesh& in, double max_distance,
                      const render::RenderOptions& preview);

}  // namespace gsp::geodesic_app
