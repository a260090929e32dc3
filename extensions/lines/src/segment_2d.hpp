#pragma once
// Distances to a straight source segment in a face frame (internal): the segment source is
// what the line propagation carries from face to face.
#include <gsp/intrinsic/face_frame.hpp>

#include <algorithm>

namespace gsp::lines::detail {

using intrinsic::Vec2;

// The point of segment [a, b] nearest to p (a == b: a point source).
inline Vec2 nearest_on_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double l2 = intrinsic::dot(ab, ab);
  if (!(l2 > 0)) return a;
  const double t = std::clamp(intrinsic::dot(p - a, ab) / l2, 0.0, 1.0);
  return a + t * ab;
}
inline double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  return intrinsic::length(p - nearest_on_segment(p, a, b));
}

}  // namespace gsp::lines::detail
