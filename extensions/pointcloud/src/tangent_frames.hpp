#pragma once
// Per-point tangent frames: a unit normal (the input's, or the direction of least variance of
// the point's k nearest neighbours) and two unit tangents completing a right-handed frame.
// Estimated normals are unoriented; propagation aligns them per link (see docs). Each point
// also gets the sign of its Gaussian curvature, from a quadric fitted to its neighbours.
#include <gsp/types.hpp>

#include "kd_tree.hpp"

#include <cstdint>
#include <vector>

namespace gsp::pointcloud::detail {

struct TangentFrames {
  std::vector<Vec3> normal, t1, t2;
  std::vector<std::uint8_t> elliptic;   // 1 where the fitted Gaussian curvature is positive
  std::size_t from_input = 0, estimated = 0;
};

// input_normals: empty or one per point; entries that are zero or not finite are estimated.
TangentFrames tangent_frames(const std::vector<Vec3>& points, const std::vector<Vec3>& input_normals,
                             const PointTree& tree, unsigned k);

}  // namespace gsp::pointcloud::detail
