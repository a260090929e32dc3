#pragma once
// Turning the --source-* options into gsp::Source values on the loaded mesh.
#include "options.hpp"

#include <gsp/cli/load.hpp>
#include <gsp/geodesics.hpp>

#include <vector>

namespace gsp::geodesic_app {

struct ResolvedSources {
  std::vector<Source> sources;    // on the loaded (possibly welded) mesh
  std::vector<Vec3> positions;    // 3D position of each source (for previews and stats)
  double max_snap_distance = 0;   // how far --source-point had to move a point onto the surface
};

// Throws UsageError when no source is given or an option is malformed, InvalidInput when a
// vertex or face does not exist.
ResolvedSources resolve_sources(const Options& options, const cli::LoadedMesh& in);

}  // namespace gsp::geodesic_app
