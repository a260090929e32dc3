// improve_by_flips with `touched` (extensions/cvt/src/flips.hpp): after a converged call and
// moves of a few vertices, examining only the quads the moves changed makes the same flips in
// the same order as examining every edge: the same triangles, the same count, over rounds of
// random moves on a jittered, slightly curved grid (many edges not Delaunay).
#include "flips.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace gsp;

TriangleMesh jittered_grid(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  TriangleMesh m;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double px = x + jitter(rng), py = y + jitter(rng);
      m.positions.push_back({px, py, 0.02 * (px * px + py * py) / n});
    }
  for (int y = 0; y + 1 < n; ++y)
    for (int x = 0; x + 1 < n; ++x) {
      const Index a = Index(y * n + x), b = a + 1, c = a + Index(n), d = c + 1;
      m.triangles.push_back({a, b, d});
      m.triangles.push_back({a, d, c});
    }
  return m;
}

TEST(CvtIncrementalFlips, TouchedVerticesGiveTheSameFlipsAsAFullPass) {
  std::mt19937 rng(5);
  TriangleMesh full = jittered_grid(40, rng);
  bool converged = false;
  const std::size_t first = cvt::detail::improve_by_flips(full, 30, 20, nullptr, nullptr, &converged);
  ASSERT_TRUE(converged);
  ASSERT_GT(first, 100u);   // the jitter leaves many edges to flip
  TriangleMesh partial = full;
  std::uniform_int_distribution<Index> pick(0, Index(full.num_vertices() - 1));
  std::uniform_real_distribution<double> step(-0.3, 0.3);
  std::size_t flips_after_moves = 0;
  for (int round = 0; round < 20; ++round) {
    std::vector<bool> touched(full.num_vertices(), false);
    for (int k = 0; k < 25; ++k) {
      const Index v = pick(rng);
      const Vec3 d{step(rng), step(rng), 0};
      full.positions[v] = full.positions[v] + d;
      partial.positions[v] = partial.positions[v] + d;
      touched[v] = true;
    }
    const std::size_t a = cvt::detail::improve_by_flips(full, 30, 20);
    const std::size_t b = cvt::detail::improve_by_flips(partial, 30, 20, nullptr, &touched, &converged);
    ASSERT_TRUE(converged);
    EXPECT_EQ(a, b) << "round " << round;
    ASSERT_EQ(full.triangles, partial.triangles) << "round " << round;
    flips_after_moves += a;
  }
  EXPECT_GT(flips_after_moves, 20u);   // the moves did call for flips
  // Nothing touched after a converged call: nothing to flip, and a full pass agrees.
  const std::vector<bool> none(full.num_vertices(), false);
  EXPECT_EQ(cvt::detail::improve_by_flips(partial, 30, 20, nullptr, &none), 0u);
  EXPECT_EQ(cvt::detail::improve_by_flips(full, 30, 20), 0u);
}

}  // namespace
