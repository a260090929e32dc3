// Paths from a point in a zero-area face at an unwelded pole (a UV sphere or capsule written
// with one copy of the pole vertex per segment, as trimesh's capsule OBJ is): the walk back
// from that point ends at a corner that is a copy of the other end, and the edge path reaches
// the other end over zero-length edges. Both crashed or failed before (a walker without a face
// in the shortening; "edge path: no predecessor").
#include "pathfinding_support.hpp"

#include <gsp/pathfinding/path_tracer.hpp>
#include <gsp/pathfinding/shortest_path.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace gsp::test {
namespace {

using pathfinding::Endpoint;
using pathfinding::PathMethod;

// k copies of the pole at the origin (vertices 0..k-1), a ring of k vertices at radius 1 and
// depth 0.2 (k..2k-1) and one at radius 2 and depth 0.5 (2k..3k-1). At the pole, segment i
// has a zero-area face (P_i, P_i+1, R_i+1) and a proper one (P_i, R_i+1, R_i), as trimesh
// writes them; quads between the rings.
TriangleMesh unwelded_cap(Index k) {
  TriangleMesh m;
  for (Index i = 0; i < k; ++i) m.positions.push_back({0, 0, 0});
  for (double r : {1.0, 2.0})
    for (Index i = 0; i < k; ++i) {
      const double a = 2 * M_PI * double(i) / double(k);
      m.positions.push_back({r * std::cos(a), r * std::sin(a), r == 1.0 ? -0.2 : -0.5});
    }
  auto ring = [&](int level, Index i) { return Index(level * k + i % k); };
  for (Index i = 0; i < k; ++i) {
    m.triangles.push_back({ring(0, i), ring(0, i + 1), ring(1, i + 1)});   // zero area
    m.triangles.push_back({ring(0, i), ring(1, i + 1), ring(1, i)});
    m.triangles.push_back({ring(1, i), ring(1, i + 1), ring(2, i + 1)});
    m.triangles.push_back({ring(1, i), ring(2, i + 1), ring(2, i)});
  }
  return m;
}

TEST(PathPole, FromAZeroAreaFaceToACopyOfThePoleAndBeyond) {
  const Index k = 12;
  const TriangleMesh m = unwelded_cap(k);
  const pathfinding::PathTracer tracer(m);
  const Endpoint from = Endpoint::in_face(0, {0.6, 0.2, 0.2});   // face 0: zero area
  const Vec3 p = from.position(m);
  const Index pole_copy = 3, far_ring = 2 * k + k / 2;
  for (PathMethod method : {PathMethod::windows, PathMethod::astar, PathMethod::settle, PathMethod::full,
                            PathMethod::dijkstra_edges}) {
    pathfinding::PathQueryOptions o;
    o.method = method;
    const std::vector<Endpoint> to{Endpoint::at_vertex(pole_copy), Endpoint::at_vertex(far_ring)};
    const auto r = method == PathMethod::dijkstra_edges ? pathfinding::edge_paths(m, tracer, from, to)
                                                        : pathfinding::shortest_paths(tracer, from, to, o);
    ASSERT_EQ(r.paths.size(), 2u);
    for (const auto& path : r.paths) expect_valid_path(m, path);
    // To the pole: the straight segment from the point (on the face's only edge with length).
    EXPECT_NEAR(r.paths[0].length, norm(p), 1e-9) << "method " << int(method);
    EXPECT_LT(distance(r.paths[0].points.front().position, p), 1e-12);
    EXPECT_LT(norm(r.paths[0].points.back().position), 1e-12);
    // Across the cap: at least the straight line, at most the way over the pole and down a
    // meridian (p to the pole, the pole to the ring below, out to the far vertex).
    const Vec3 end = m.positions[far_ring];
    const double meridian = norm(p) + norm(m.positions[k + k / 2]) + distance(m.positions[k + k / 2], end);
    EXPECT_GE(r.paths[1].length, distance(p, end) * (1 - 1e-9)) << "method " << int(method);
    EXPECT_LE(r.paths[1].length, meridian * (1 + 1e-9)) << "method " << int(method);
  }
}

}  // namespace
}  // namespace gsp::test
