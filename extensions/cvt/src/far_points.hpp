#pragma once
// Input points farther than a bound from the mesh: where the pulls and the far-point insertions
// start, both to bring the input-to-mesh half of the Hausdorff distance down.
#include <gsp/cvt/closest_point_index.hpp>
#include <gsp/mesh.hpp>

#include <vector>

namespace gsp::cvt::detail {

// How far point w is from the mesh, and the mesh face nearest to it.
struct FarPoint {
  double d;
  Index w, face;
};

// Appends point w of `points` when it lies farther than `bound` from the mesh `mesh_index` is over.
// Most points are near: the bounded search answers them without finding their nearest face.
inline void add_if_far(const ClosestPointIndex& mesh_index, const std::vector<Vec3>& points, Index w, double bound,
                       std::vector<FarPoint>& far) {
  if (mesh_index.within(points[w], bound)) return;
  const ClosestPoint c = mesh_index.closest(points[w]);
  if (c.point.element != kInvalidIndex && c.distance > bound) far.push_back({c.distance, w, c.point.element});
}

}  // namespace gsp::cvt::detail
