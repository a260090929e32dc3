#pragma once
// The checks a smoothing move or pull of vertex v must pass at its new point: the angles of v's
// triangles and their folds, and the surface's distance from them both ways, so that the mesh's
// minimum angle never falls and no tip or crease of the surface is cut off.
#include "smoothing_context.hpp"

#include <cstdint>
#include <vector>

namespace gsp::cvt::detail {

// The worst angle of v's triangles with v at x (`nx`: the surface's normal there), signed:
// negative for a triangle that faces against the surface (its normal against the sum of the
// surface normals at its corners, where these agree: not across a slit or a thin wall; the
// dual folds so where a site lies beyond the edge of its neighbours, and its angles say
// nothing then). -10 if the move folds a triangle: turns its normal by more than 40
// degrees, unless it then faces the surface at all three corners. A sliver's normal turns
// that much under any move (on falconstatue's base at 2,000 sites a 171-degree cap across
// the bottom rim could not open towards the bottom), and a folded triangle must turn over
// to unfold.
double signed_quality(const SmoothingContext& c, Index v, Vec3 x, bool check_fold, Vec3 nx);

// The plain (unsigned) worst angle of v's triangles with v at x: what the quality figures
// measure. A move never lowers it, whatever the signs.
double plain_quality(const SmoothingContext& c, Index v, Vec3 x);

// Distance from point z to v's triangles with v at y.
double ring_distance(const SmoothingContext& c, Index v, Vec3 z, Vec3 y);

// The surface checks of moves of v from its position x0, both ways, with `bound` as the limit:
// the centroids of v's triangles and the midpoints of their edges at v within max(bound, before)
// of the surface, and the points of the surface under the old triangles (see watched_points in
// move_checks.cpp) within max(bound, before) of the moved ones, or a tip or a crease the vertex
// sat on would be cut off. The figures at x0 are taken when a first point needs them: most
// points fail the angle checks first. `normal`: the side v's sheet faces.
class SurfaceGuard {
 public:
  SurfaceGuard(const SmoothingContext& c, Index v, Vec3 normal, double bound)
      : c_(c), v_(v), x0_(c.m.positions[v]), normal_(normal), bound_(bound) {}
  bool keeps(Vec3 y);
  Vec3 normal() const { return normal_; }

 private:
  const SmoothingContext& c_;
  Index v_;
  Vec3 x0_, normal_;
  double bound_;
  bool has_deviation_ = false, has_watched_ = false;
  double deviation0_ = 0;
  std::vector<Vec3> watched_;
  std::vector<double> watched_before_;
  std::vector<Index> hint_;   // per watched point, the ring slot that kept it last time
  std::vector<Index> chord_hint_;   // per chord point, the surface face that kept it last time
};

}  // namespace gsp::cvt::detail
