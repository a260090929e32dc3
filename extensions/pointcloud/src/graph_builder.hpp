#pragma once
// Builds the neighbour graph from an existing k-d tree (the solver keeps its tree for source
// queries, so it is not built twice).
#include <gsp/pointcloud/neighbour_graph.hpp>

#include "kd_tree.hpp"

namespace gsp::pointcloud::detail {

NeighbourGraph build_graph(const std::vector<Vec3>& points, const PointTree& tree, const NeighbourOptions& options);
void check_options(const NeighbourOptions& options);

}  // namespace gsp::pointcloud::detail
