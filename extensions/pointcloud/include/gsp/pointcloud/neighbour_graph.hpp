#pragma once
// The neighbourhood graph of a point cloud: every point linked to its k nearest neighbours
// (or to all points within a radius), made symmetric so that a point that nobody lists as a
// neighbour (an outlier) is still linked to its own nearest points. Stored as CSR arrays.
#include <gsp/types.hpp>

#include <cstdint>
#include <vector>

namespace gsp::pointcloud {

enum class Neighbourhood : std::uint8_t {
  knn,      // the k nearest other points (paper Section 5.1: k = 10)
  radius,   // every other point closer than `radius`
};

struct NeighbourOptions {
  Neighbourhood rule = Neighbourhood::knn;
  unsigned k = 10;       // knn: neighbours per point; also the points seeded around a position source
  double radius = 0;     // radius: model units, > 0
};

struct NeighbourGraph {
  std::vector<Index> begin;        // CSR offsets, num_points() + 1 entries
  std::vector<Index> neighbour;    // sorted by index within each point's range, no self loops
  std::vector<double> length;      // Euclidean distance of each link
  std::size_t num_points() const { return begin.empty() ? 0 : begin.size() - 1; }
  std::size_t num_links() const { return neighbour.size() / 2; }   // undirected
};

// Throws InvalidInput for non-finite positions, k = 0 or a non-positive radius. Coincident
// points are neighbours at distance 0 (the solver merges them before it builds its graph).
NeighbourGraph build_neighbour_graph(const std::vector<Vec3>& points, const NeighbourOptions& options = {});

// Connected components of the graph: per point a component id in 0..count-1, ids in order
// of each component's smallest point index.
struct Components {
  std::vector<Index> id;
  std::size_t count = 0;
};
Components connected_components(const NeighbourGraph& graph);

}  // namespace gsp::pointcloud
