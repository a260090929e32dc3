#pragma once
// The largest distance of a set of points from a surface (the gsp::cvt edge-remesh and sizing
// tests: a remesh's vertices from its input, or an input's vertices from its remesh).
#include <gsp/cvt/closest_point_index.hpp>
#include <gsp/mesh.hpp>

#include <algorithm>
#include <vector>

namespace gsp::test {

inline double farthest_point(const std::vector<Vec3>& points, const TriangleMesh& surface) {
  const cvt::ClosestPointIndex index(surface);
  double d = 0;
  for (const Vec3& p : points) d = std::max(d, index.closest(p).distance);
  return d;
}

}  // namespace gsp::test
