#pragma once
// The propagation kernels over the neighbour graph of the unique points: GSP with virtual
// sources in tangent planes (dual queue with speed limiter, label correcting) and Dijkstra
// on the links (binary heap), both filling the same per-point state.
#include <gsp/pointcloud/point_cloud_geodesics.hpp>

#include "tangent_frames.hpp"

#include <vector>

namespace gsp::pointcloud::detail {

struct Domain {
  const NeighbourGraph& graph;
  const std::vector<Vec3>& position;   // unique points, centred (see Impl)
  const TangentFrames& frames;
  double mean_link = 0;
};

// A seeded point: distance `sigma + |offset|`, virtual source at position + offset (offset
// lies in the point's tangent plane).
struct Seed {
  Index point;
  double sigma;
  Vec3 offset;
  Index label;
};

struct PointState {
  std::vector<double> distance;   // sigma + |source|
  std::vector<double> sigma;
  std::vector<double> sx, sy;     // virtual source relative to the point, tangent coordinates
  std::vector<Index> label;
  void reset(std::size_t n);
};

void propagate_gsp(const Domain& domain, const std::vector<Seed>& seeds, const PointGeodesicOptions& options,
                   PointState& state, PointPropagationStats& stats);
void propagate_dijkstra(const Domain& domain, const std::vector<Seed>& seeds, double max_distance,
                        PointState& state, PointPropagationStats& stats);

}  // namespace gsp::pointcloud::detail
