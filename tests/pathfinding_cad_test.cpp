// Paths on what CAD exports and 3D-printing STLs are made of: edges of three faces (a wall and
// a ledge), T-junctions joined by faces without area (docs/pathfinding.md, "Needles, fins and
// T-junctions").
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

// Both path methods, from a to b, on one mesh.
std::vector<pathfinding::PathQueryResult> both_methods(const TriangleMesh& m, Index a, Index b) {
  const pathfinding::PathTracer tracer(m);
  std::vector<pathfinding::PathQueryResult> out;
  for (const PathMethod method : {PathMethod::windows, PathMethod::astar}) {
    pathfinding::PathQueryOptions o;
    o.method = method;
    o.both_ends = false;   // the walk from one end: what is tested here
    out.push_back(pathfinding::shortest_paths(tracer, Endpoint::at_vertex(a), {Endpoint::at_vertex(b)}, o));
  }
  return out;
}

// Two wall squares in one plane and a ledge on the edge between them (three faces at that
// edge). A straight path across the wall meets the edge where the ledge's unfolded source
// gives the same distance as the wall's: the walk took the first face of the edge, the
// ledge's when its faces come first in the file, and the path fell back to the edges (3 for
// sqrt 5). Every order of the faces, both directions, both methods.
TEST(PathCad, AWallPathCrossesTheEdgeALedgeStandsOn) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {2, 0, 0}, {2, 0, 1}, {1, 1, 0}, {1, 1, 1}};
  const std::vector<Triangle> wall1 = {{0, 1, 2}, {0, 2, 3}}, wall2 = {{1, 4, 5}, {1, 5, 2}},
                              ledge = {{1, 6, 7}, {1, 7, 2}};
  for (const auto& parts : {std::vector{ledge, wall1, wall2}, std::vector{wall1, ledge, wall2},
                            std::vector{wall2, ledge, wall1}}) {
    m.triangles.clear();
    for (const auto& part : parts) m.triangles.insert(m.triangles.end(), part.begin(), part.end());
    for (const auto& [a, b] : {std::pair<Index, Index>{3, 4}, {4, 3}, {0, 5}, {5, 0}})
      for (const auto& r : both_methods(m, a, b)) {
        ASSERT_TRUE(r.paths[0].found());
        expect_valid_path(m, r.paths[0]);
        EXPECT_NEAR(r.paths[0].length, std::sqrt(5.0), 1e-9) << a << " -> " << b;
        EXPECT_EQ(r.edge_fallbacks, 0u);
      }
  }
}

// A square whose diagonal passes a T-junction: the middle of the square's inner edge is a
// vertex of the upper half only, joined to the lower half by a face without area along that
// edge. The geodesic between opposite corners runs straight through the junction (2 sqrt 2);
// the walk stopped at the flat face (3.24 along the edges) or ended at the junction as if at
// the source.
TEST(PathCad, ADiagonalThroughATJunction) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {1, 1, 0}, {0, 2, 0}, {2, 2, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {3, 2, 4}, {3, 4, 5}, {4, 6, 5}, {4, 2, 6}};
  for (const auto& [a, b] : {std::pair<Index, Index>{5, 1}, {1, 5}, {0, 6}, {6, 0}}) {
    const auto r = both_methods(m, a, b);
    for (const auto& q : r) {
      ASSERT_TRUE(q.paths[0].found());
      expect_valid_path(m, q.paths[0]);
    }
    // GSP's field crosses the flat face and its walk follows it now.
    EXPECT_NEAR(r[1].paths[0].length, 2 * std::sqrt(2.0), 1e-9) << a << " -> " << b;
    EXPECT_EQ(r[1].edge_fallbacks, 0u);
  }
}

}  // namespace
}  // namespace gsp::test
