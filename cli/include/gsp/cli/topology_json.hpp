#pragma once
// A mesh's topology report as the apps' --stats write it (gsp-cvt, gsp-cvt-compare): counts,
// Euler characteristic, boundary loops, components and the manifold checks.
#include <gsp/cli/json.hpp>
#include <gsp/topology.hpp>

namespace gsp::cli {

cli::Json topology_json(const TopologyReport& t);

}  // namespace gsp::cli
