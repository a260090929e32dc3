#include <gsp/cli/topology_json.hpp>

namespace gsp::cli {

cli::Json topology_json(const TopologyReport& t) {
  cli::Json j = cli::Json::object();
  j["vertices"] = t.vertices;
  j["faces"] = t.faces;
  j["euler_characteristic"] = static_cast<long long>(t.euler_characteristic);
  j["boundary_loops"] = t.boundary_loops;
  j["components"] = t.components;
  j["manifold"] = t.is_manifold();
  j["nonmanifold_edges"] = t.nonmanifold_edges;
  j["nonmanifold_vertices"] = t.nonmanifold_vertices;
  j["inconsistent_edges"] = t.inconsistent_edges;
  return j;
}

}  // namespace gsp::cli
