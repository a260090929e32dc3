// The Dijkstra baseline on the edge graph: exact where paths run along edges, never shorter
// than the straight line, and consistent with its own max-distance cut.
#include "helpers/geodesic_fixtures.hpp"

#include <gsp/dijkstra.hpp>
#include <gsp/errors.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gsp::test {
namespace {

TEST(Dijkstra, GridDistancesAreEdgePathLengths) {
  const TriangleMesh m = grid(8);   // unit squares split along the (i,j)-(i+1,j+1) diagonal
  const auto r = dijkstra_distances(m, {Source::at_vertex(0)});
  for (int j = 0; j <= 8; ++j)
    for (int i = 0; i <= 8; ++i) {
      // Diagonal steps of sqrt(2) then straight steps along the remaining axis.
      const double diag = std::min(i, j), straight = std::abs(i - j);
      EXPECT_NEAR(r.vertex_distance[j * 9 + i], diag * std::sqrt(2.0) + straight, 1e-12);
    }
}

TEST(Dijkstra, NeverShorterThanTheStraightLineAndLabelsSources) {
  const TriangleMesh m = jittered_grid(12, 0.25, 3);
  const auto r = dijkstra_distances(m, {Source::at_vertex(0), Source::at_vertex(168)});
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const double d0 = distance(m.positions[v], m.positions[0]);
    const double d1 = distance(m.positions[v], m.positions[168]);
    EXPECT_GE(r.vertex_distance[v], std::min(d0, d1) - 1e-12);
    ASSERT_LT(r.vertex_source[v], 2u);
  }
  EXPECT_EQ(r.vertex_source[0], 0u);
  EXPECT_EQ(r.vertex_source[168], 1u);
}

TEST(Dijkstra, FacePointSeedsItsCornersAndMaxDistanceCuts) {
  const TriangleMesh m = grid(6);
  const auto r = dijkstra_distances(m, {Source::in_face(0, {1.0 / 3, 1.0 / 3, 1.0 / 3})});
  const Triangle& t = m.triangles[0];
  const Vec3 c = (1.0 / 3) * (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]);
  for (Index v : t) EXPECT_NEAR(r.vertex_distance[v], distance(c, m.positions[v]), 1e-12);
  const auto cut = dijkstra_distances(m, {Source::at_vertex(0)}, 3.0);
  const auto full = dijkstra_distances(m, {Source::at_vertex(0)});
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    if (full.vertex_distance[v] <= 3.0) EXPECT_EQ(cut.vertex_distance[v], full.vertex_distance[v]);
    else EXPECT_TRUE(std::isinf(cut.vertex_distance[v]));
  }
  EXPECT_THROW(dijkstra_distances(m, {Source::at_vertex(1000)}), InvalidInput);
}

}  // namespace
}  // namespace gsp::test
