#pragma once
// gsp-geodesic --method windows: gsp::WindowGeodesics (three windows per face) for one field,
// --separate fields or a --matrix, from vertex sources, or from points in faces on the input's
// triangles (docs/apps/gsp-geodesic.md, "Windows").
#include "options.hpp"
#include "sources.hpp"

#include <gsp/cli/load.hpp>
#include <gsp/geodesics.hpp>

namespace gsp::cli {
class Context;
}

namespace gsp::geodesic_app {

// One field (GeodesicResult's vertex distances and labels), or, with --separate / --matrix,
// the fields or the matrix written here (the result then empty). UsageError for a source with
// an offset or --metric. --max-distance cuts the whole field afterwards (the windows'
// propagation is not bounded): farther vertices are unreached, as with GSP.
GeodesicResult run_windows(cli::Context& ctx, const Options& options, const cli::LoadedMesh& in,
                           const ResolvedSources& sources, double max_distance);

}  // namespace gsp::geodesic_app
