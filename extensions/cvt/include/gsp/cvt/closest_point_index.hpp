#pragma once
// Closest points on a triangle mesh for many queries: Embree's BVH point query (rtcPointQuery)
// narrows the candidates, the distance to each candidate triangle is computed in double
// precision by gsp::closest_point_on_triangle. Thread-safe queries after construction.
#include <gsp/closest_point.hpp>
#include <gsp/mesh.hpp>

#include <memory>

namespace gsp::cvt {

class ClosestPointIndex {
 public:
  // Keeps a reference to `mesh`. Faces that repeat a vertex are left out; throws InvalidInput
  // when no face is left, gsp::Error when Embree fails.
  explicit ClosestPointIndex(const TriangleMesh& mesh);
  ~ClosestPointIndex();
  ClosestPointIndex(const ClosestPointIndex&) = delete;
  ClosestPointIndex& operator=(const ClosestPointIndex&) = delete;

  ClosestPoint closest(Vec3 p) const;
  // Whether a triangle lies within distance r of p (closest(p).distance <= r, decided in the
  // same double precision), found faster: the search is bounded by r and stops at the first.
  bool within(Vec3 p, double r) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gsp::cvt
