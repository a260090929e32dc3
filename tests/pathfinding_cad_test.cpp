// Paths on what CAD exports and 3D-printing STLs are made of: edges of three faces (a wall and
// a ledge), T-junctions joined by faces without area, needles; and on three corpus parts CGAL
// refuses, every vertex's path against the field (docs/pathfinding.md, "Needles, fins and
// T-junctions").
#include "pathfinding_support.hpp"
#include "test_data.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/pathfinding/path_tracer.hpp>
#include <gsp/pathfinding/shortest_path.hpp>
#include <gsp/weld.hpp>
#include <gsp/mesh.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
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
    // GSP's field crosses the flat face; the windows cross only edges with area beside them, so
    // the default method's walk falls back to the edges and GSP's A* path, shorter, replaces it.
    for (const auto& q : r) {
      ASSERT_TRUE(q.paths[0].found());
      expect_valid_path(m, q.paths[0]);
      EXPECT_NEAR(q.paths[0].length, 2 * std::sqrt(2.0), 1e-9) << a << " -> " << b;
    }
    EXPECT_EQ(r[1].edge_fallbacks, 0u);
  }
}

// The toilet-seat handle STL's path from vertex 0 to vertex 73 crosses needles of aspect 9e6
// and 7e7 (three of them nearly on one line). Whether the walk saw such a needle as a face
// hung on rounding noise (its barycentrics from the Gram determinant): scaled by 10 or 1e7 the
// walk could not enter it and the path went round, 3.5% / 2.3% over the field. Both methods,
// from one end, at several scales: within 0.002% of the field (the windows' path meets it, GSP's
// A* is 0.001% over).
TEST(PathCad, ANeedlePathAtEveryScale) {
  const std::string path = data_dir() + "/../corpus/thingi10k_49220_toilet_seat_handle.stl";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "corpus mesh missing: " << path;
  const TriangleMesh read = weld_vertices(io::read_mesh(path).mesh).mesh;
  ASSERT_EQ(read.num_vertices(), 75u);
  for (const double scale : {1.0, 3.0, 10.0, 3e6, 1e7}) {
    TriangleMesh m = read;
    for (Vec3& p : m.positions) p = scale * p;
    const double field = GeodesicSolver(m).compute({Source::at_vertex(0)}).vertex_distance[73];
    for (const auto& r : both_methods(m, 0, 73)) {
      ASSERT_TRUE(r.paths[0].found()) << scale;
      EXPECT_LT(r.paths[0].length / field - 1, 2e-5) << "scale " << scale;
      EXPECT_EQ(r.edge_fallbacks, 0u) << scale;
    }
  }
}

// The house wall STL: the default path from vertex 0 to vertex 94 was 13.2% over the field at
// 10x its size (the windows' path 13.91, GSP's A* walk from vertex 0 16.21, both on the
// surface; the A* walk back from vertex 94 finds 12.289) and 1.9% over at 1x and 3x (both
// paths 12.52, and so were the two fields they were traced in; GSP's full field 12.289). A
// path still more than 1% over the lowest of those fields and GSP's full field now gets GSP's
// walk from its end too.
TEST(PathCad, ASuspectPathIsWalkedFromItsEndToo) {
  const std::string path = data_dir() + "/../corpus/thingi10k_96582_house7_wall_balcony.stl";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "corpus mesh missing: " << path;
  const TriangleMesh input = weld_vertices(io::read_mesh(path).mesh).mesh;
  for (const double scale : {1.0, 3.0, 10.0}) {
    TriangleMesh m = input;
    for (Vec3& p : m.positions) p = scale * p;
    const GeodesicSolver solver(m);
    const pathfinding::PathTracer tracer(m);
    const double field = solver.compute({Source::at_vertex(0)}).vertex_distance[94];
    const auto r = pathfinding::shortest_paths(solver, tracer, Endpoint::at_vertex(0), {Endpoint::at_vertex(94)});
    ASSERT_TRUE(r.paths[0].found()) << scale;
    EXPECT_LT(r.paths[0].length / field - 1, 1e-4) << "scale " << scale;
    // The same end among every other vertex in one query (13.2% over at 1x before: the A*
    // field towards all the ends differs again at vertex 94).
    std::vector<Endpoint> ends;
    for (Index v = 1; v < m.num_vertices(); ++v) ends.push_back(Endpoint::at_vertex(v));
    const auto all = pathfinding::shortest_paths(solver, tracer, Endpoint::at_vertex(0), ends);
    ASSERT_TRUE(all.paths[93].found()) << scale;
    EXPECT_LT(all.paths[93].length / field - 1, 1e-4) << "one query, scale " << scale;
  }
}

// Corpus CAD parts that CGAL refuses (zero-area faces, needles of aspect up to 6e7, fins): the
// default path from vertex 0 to every vertex, one query per end (as gsp.GeodesicSolver.path
// runs them), against GSP's field there (no exact reference; where the path is more than 1%
// over, the default window field agrees with the path and GSP's field is short:
// docs/pathfinding.md). Before: the wall 2.4% over the field on average
// (34 of 108 ends more than 1%, up to 29%), the handle 6.5% (27 of 74, up to 31%), the log
// 0.11% (3 of 49, up to 6.8%).
struct CadPart {
  const char* file;
  double mean_excess, max_excess;   // bounds on path / field - 1 over the ends
};

class PathCadCorpus : public ::testing::TestWithParam<CadPart> {};

TEST_P(PathCadCorpus, EveryVertexPathAgainstTheField) {
  const std::string path = data_dir() + "/../corpus/" + GetParam().file;
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "corpus mesh missing: " << path;
  const TriangleMesh m = weld_vertices(io::read_mesh(path).mesh).mesh;
  const GeodesicSolver solver(m);
  const pathfinding::PathTracer tracer(m);
  const std::vector<double> field = solver.compute({Source::at_vertex(0)}).vertex_distance;
  const double slack = 1e-4 * bounding_box(m).diagonal();   // on_surface's: needles round
  double sum = 0, worst = -1;
  std::size_t n = 0;
  for (Index v = 1; v < m.num_vertices(); ++v) {
    const double d = field[v];
    if (!std::isfinite(d) || !(d > 0)) continue;
    const auto r = pathfinding::shortest_paths(solver, tracer, Endpoint::at_vertex(0), {Endpoint::at_vertex(v)});
    ASSERT_TRUE(r.paths[0].found()) << v;
    const auto& pts = r.paths[0].points;
    EXPECT_EQ(distance(pts.front().position, m.positions[0]), 0.0);
    EXPECT_EQ(distance(pts.back().position, m.positions[v]), 0.0);
    for (const auto& q : pts) EXPECT_LT(distance(q.point.position(m), q.position), slack) << v;
    const double excess = r.paths[0].length / d - 1;
    sum += excess, worst = std::max(worst, excess), ++n;
  }
  ASSERT_GT(n, 40u);
  EXPECT_LT(sum / double(n), GetParam().mean_excess);
  EXPECT_LT(worst, GetParam().max_excess);
}

INSTANTIATE_TEST_SUITE_P(Thingi10k, PathCadCorpus,
                         ::testing::Values(CadPart{"thingi10k_96582_house7_wall_balcony.stl", 0.001, 0.025},
                                           CadPart{"thingi10k_49220_toilet_seat_handle.stl", 0.001, 0.035},
                                           CadPart{"thingi10k_37863_log_cabin_log.stl", 0.0005, 0.001}));

}  // namespace
}  // namespace gsp::test
