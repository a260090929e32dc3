#pragma once
// Checks every traced path must pass: points on the surface, consecutive points in a common
// face, reported length equal to the polyline's.
#include <gsp/closest_point.hpp>
#include <gsp/pathfinding/path.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace gsp::test {

// Whether x lies on face f: within tol (relative to the face's longest edge) of its closest
// point on the triangle. (Barycentric coordinates from the normal equations lose about
// eps * aspect^2 on needles: at aspect 8e6, 1e-2; the closest point does not.)
inline bool on_face(const TriangleMesh& m, Index f, Vec3 x, double tol) {
  const Triangle& t = m.triangles[f];
  const Vec3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
  const double longest = std::max({distance(a, b), distance(b, c), distance(c, a)});
  if (!(longest > 0)) return false;
  const auto w = closest_point_on_triangle(x, a, b, c);
  return distance(x, w[0] * a + w[1] * b + w[2] * c) <= tol * longest;
}

inline void expect_valid_path(const TriangleMesh& m, const pathfinding::GeodesicPath& p) {
  ASSERT_TRUE(p.found());
  double length = 0;
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    const pathfinding::PathPoint& q = p.points[i];
    ASSERT_FALSE(q.point.is_vertex());
    ASSERT_LT(q.point.element, m.num_faces());
    EXPECT_LT(distance(q.point.position(m), q.position), 1e-5) << "point " << i << " is not where its barycentrics say";
    // On its face: barycentrics inside the triangle (their position is the point's, above).
    const auto& b = q.point.barycentric;
    EXPECT_TRUE(b[0] >= -1e-9 && b[1] >= -1e-9 && b[2] >= -1e-9 && std::abs(b[0] + b[1] + b[2] - 1) <= 1e-9)
        << "point " << i << " is off its face";
    if (i == 0) continue;
    const pathfinding::PathPoint& r = p.points[i - 1];
    const bool shared = on_face(m, q.point.element, r.position, 1e-5) || on_face(m, r.point.element, q.position, 1e-5);
    EXPECT_TRUE(shared) << "points " << i - 1 << " and " << i << " share no face";
    length += distance(q.position, r.position);
  }
  EXPECT_NEAR(p.length, length, 1e-12 * (1 + length));
}

}  // namespace gsp::test
