#pragma once
// Checks every traced path must pass: points on the surface, consecutive points in a common
// face, reported length equal to the polyline's.
#include <gsp/pathfinding/path.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gsp::test {

// Barycentric coordinates of x in face f if x lies on it (within tol of its plane and
// inside up to tol), else false.
inline bool on_face(const TriangleMesh& m, Index f, Vec3 x, double tol) {
  const Triangle& t = m.triangles[f];
  const Vec3 a = m.positions[t[0]], e0 = m.positions[t[1]] - a, e1 = m.positions[t[2]] - a, e2 = x - a;
  const double d00 = dot(e0, e0), d01 = dot(e0, e1), d11 = dot(e1, e1), d20 = dot(e2, e0), d21 = dot(e2, e1);
  const double den = d00 * d11 - d01 * d01;
  if (!(den > 0)) return false;
  const double v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den, u = 1 - v - w;
  const Vec3 proj = a + v * e0 + w * e1;
  const double scale = std::sqrt(std::max(d00, d11));
  return distance(proj, x) <= tol * scale && u >= -tol && v >= -tol && w >= -tol;
}

inline void expect_valid_path(const TriangleMesh& m, const pathfinding::GeodesicPath& p) {
  ASSERT_TRUE(p.found());
  double length = 0;
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    const pathfinding::PathPoint& q = p.points[i];
    ASSERT_FALSE(q.point.is_vertex());
    ASSERT_LT(q.point.element, m.num_faces());
    EXPECT_LT(distance(q.point.position(m), q.position), 1e-5) << "point " << i << " is not where its barycentrics say";
    EXPECT_TRUE(on_face(m, q.point.element, q.position, 1e-6)) << "point " << i << " is off its face";
    if (i == 0) continue;
    const pathfinding::PathPoint& r = p.points[i - 1];
    const bool shared = on_face(m, q.point.element, r.position, 1e-5) || on_face(m, r.point.element, q.position, 1e-5);
    EXPECT_TRUE(shared) << "points " << i - 1 << " and " << i << " share no face";
    length += distance(q.position, r.position);
  }
  EXPECT_NEAR(p.length, length, 1e-12 * (1 + length));
}

}  // namespace gsp::test
