// The remeshing passes' smallest-angle measure (triangle_geometry.hpp: one atan2, at the
// corner opposite the shortest edge) against the three angles measured one by one, and the
// moves' `movable` mask (smoothing.hpp): a vertex outside it never moves.
#include "boundary_curves.hpp"
#include "cvt_meshes.hpp"
#include "smoothing.hpp"
#include "triangle_geometry.hpp"

#include <gsp/sampling/random.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using namespace gsp;
using cvt::detail::angle_at;
using cvt::detail::min_angle;

double three_angles(Vec3 a, Vec3 b, Vec3 c) { return std::min({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)}); }

TEST(CvtTriangleGeometry, SmallestAngleIsTheOneOppositeTheShortestEdge) {
  sampling::Random random(3);
  auto point = [&] { return Vec3{random.uniform(), random.uniform(), random.uniform()}; };
  for (int i = 0; i < 20000; ++i) {
    const Vec3 a = point(), b = point(), c = point();
    EXPECT_EQ(min_angle(a, b, c), three_angles(a, b, c)) << "triangle " << i;
  }
  // Needles, caps, ties of two and three edges, a repeated corner, and each corner first.
  const double s3 = std::sqrt(3.0) / 2;
  const std::vector<std::array<Vec3, 3>> shapes = {
      {{{0, 0, 0}, {1, 0, 0}, {0.5, s3, 0}}},        // equilateral: all three tie
      {{{0, 0, 0}, {1, 0, 0}, {0.5, 3, 0}}},         // isosceles needle: the two long edges tie
      {{{0, 0, 0}, {1, 0, 0}, {0.5, 1e-7, 0}}},      // isosceles cap: the two short edges tie
      {{{0, 0, 0}, {1, 0, 0}, {0.3, 1e-9, 0}}},      // a cap whose small angles differ
      {{{0, 0, 0}, {1e-8, 0, 0}, {0.5, 1, 0}}},      // a needle
      {{{0, 0, 0}, {0, 0, 0}, {1, 1, 0}}},           // a repeated corner: 0
      {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}},           // collinear: 0
  };
  for (const auto& t : shapes)
    for (int r = 0; r < 3; ++r) {
      const Vec3 a = t[r], b = t[(r + 1) % 3], c = t[(r + 2) % 3];
      EXPECT_EQ(min_angle(a, b, c), three_angles(a, b, c));
      EXPECT_EQ(min_angle(a, c, b), three_angles(a, c, b));
    }
  EXPECT_NEAR(min_angle({0, 0, 0}, {1, 0, 0}, {0.5, s3, 0}), M_PI / 3, 1e-15);
  EXPECT_EQ(min_angle({0, 0, 0}, {0, 0, 0}, {1, 1, 0}), 0.0);
}

// A grid with its interior vertices jittered in the plane: the moves raise angles, but only
// where the mask lets them.
TEST(CvtTriangleGeometry, MovesKeepToTheMovableVertices) {
  TriangleMesh m = test::square_grid(10);
  sampling::Random random(5);
  std::vector<bool> interior(m.num_vertices(), false);
  for (Index v = 0; v < m.num_vertices(); ++v) {
    const Vec3 p = m.positions[v];
    if (p.x <= 0 || p.x >= 1 || p.y <= 0 || p.y >= 1) continue;
    interior[v] = true;
    m.positions[v] = p + Vec3{0.035 * (random.uniform() - 0.5), 0.035 * (random.uniform() - 0.5), 0};
  }
  const TriangleMesh surface = test::square_grid(40);
  const cvt::detail::BoundaryCurves curves(surface);
  std::vector<bool> movable(m.num_vertices(), false);
  for (Index v = 0; v < m.num_vertices(); ++v) movable[v] = m.positions[v].x < 0.5;
  TriangleMesh moved = m;
  cvt::detail::SmoothParams p;
  p.max_deviation = 1e-3;
  p.flip_max_normal_angle = -1;   // positions only
  p.cap_flips = false;
  p.movable = &movable;
  const cvt::detail::SmoothCounts c = cvt::detail::smooth_vertices(moved, surface, surface, curves, p);
  EXPECT_GT(c.moves, 0u);
  std::size_t changed_inside = 0;
  for (Index v = 0; v < m.num_vertices(); ++v) {
    if (!movable[v]) EXPECT_EQ(moved.positions[v], m.positions[v]) << "vertex " << v;
    changed_inside += movable[v] && interior[v] && moved.positions[v] != m.positions[v];
  }
  EXPECT_GT(changed_inside, 0u);
  EXPECT_GE(cvt::detail::mesh_min_angle(moved), cvt::detail::mesh_min_angle(m));
}

}  // namespace
