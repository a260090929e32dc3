// Paths through a window field (PathMethod::windows, gsp/window_geodesics.hpp WindowField):
// the field's per-point sources, its early stop at the end points, point sources in faces, and
// paths against CGAL's exact lengths where GSP's one source per face picks the wrong corridor.
#include "helpers/geodesic_fixtures.hpp"
#include "helpers/mesh_builders.hpp"
#include "pathfinding_support.hpp"
#include "test_data.hpp"

#include <gsp/errors.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/pathfinding/path_tracer.hpp>
#include <gsp/pathfinding/shortest_path.hpp>
#include <gsp/reference/exact_geodesics.hpp>
#include <gsp/weld.hpp>
#include <gsp/window_geodesics.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <type_traits>

namespace gsp::test {
namespace {

using pathfinding::Endpoint;

// The tracer builds its window propagation on first use and stays movable (it is kept in
// containers and returned from functions).
static_assert(std::is_move_constructible_v<pathfinding::PathTracer>);

// On a plane every window value is the straight line: the field's per-point source explains
// the point's value (sigma + |x - S|), and a source inside a face gives Euclidean distances.
TEST(WindowField, PointSourceOnPlaneIsEuclidean) {
  const TriangleMesh m = jittered_grid(12, 0.3, 3);
  const WindowGeodesics windows(m, false);
  const Index f = 40;
  const std::array<double, 3> b{0.2, 0.5, 0.3};
  const Vec3 p = SurfacePoint::in_face(f, b).position(m);
  const WindowField field = windows.field({Source::in_face(f, b)});
  for (Index v = 0; v < m.num_vertices(); ++v)
    EXPECT_NEAR(field.vertex_distance[v], distance(m.positions[v], p), 1e-9) << "vertex " << v;
  SplitMix rng{7};
  for (int k = 0; k < 200; ++k) {
    const Index g = Index(rng.next() % m.num_faces());
    double w0 = double(rng.next() % 1000) + 1, w1 = double(rng.next() % 1000) + 1, w2 = double(rng.next() % 1000) + 1;
    const double sum = w0 + w1 + w2;
    const std::array<double, 3> q{w0 / sum, w1 / sum, w2 / sum};
    const Vec3 x = SurfacePoint::in_face(g, q).position(m);
    const VirtualSource s = field.source_at(g, x);
    ASSERT_TRUE(s.reached());
    EXPECT_NEAR(s.sigma + distance(x, s.position), distance(x, p), 1e-9);
    EXPECT_NEAR(field.distance_at(g, q), distance(x, p), 1e-9);
  }
}

// Stopped once the targets are settled: their values are those of the whole field up to the
// order effects of keeping K windows per face (the A* order offers windows in another order;
// measured up to 1.1e-4 relative on these 6 targets).
TEST(WindowField, TargetsStopEarlyWithFinalValues) {
  if (!have_shared_data()) GTEST_SKIP() << "shared data folder missing";
  const TriangleMesh m = io::read_mesh(shared_mesh("camelhead.off")).mesh;
  const WindowGeodesics windows(m, false);
  WindowOptions all;
  all.windows = 3;
  const WindowField full = windows.field({Source::at_vertex(0)}, all);
  SplitMix rng{5};
  for (int k = 0; k < 6; ++k) {
    WindowOptions o = all;
    o.targets = {Index(rng.next() % m.num_vertices())};
    WindowStats stats;
    const WindowField part = windows.field({Source::at_vertex(0)}, o, &stats);
    const Index t = o.targets[0];
    EXPECT_NEAR(part.vertex_distance[t], full.vertex_distance[t], 1e-3 * full.vertex_distance[t]) << "target " << t;
    std::printf("target %u: stopped %.9g whole %.9g\n", t, part.vertex_distance[t], full.vertex_distance[t]);
    EXPECT_LE(stats.faces_reached, m.num_faces());
  }
}

TEST(WindowField, IntrinsicFacesCannotBeQueried) {
  const TriangleMesh m = jittered_grid(6, 0.3, 1);
  const WindowGeodesics windows(m);   // intrinsic Delaunay faces
  const WindowField field = windows.field({Source::at_vertex(0)});
  EXPECT_THROW(field.source_at(3, m.positions[m.triangles[3][0]]), InvalidInput);
  EXPECT_THROW(windows.field({Source::in_face(2, {0.3, 0.3, 0.4})}), std::invalid_argument);
  EXPECT_THROW(windows.field({Source::at_vertex(0, 1.0)}), std::invalid_argument);
}

// A remeshed scan with 73 handles (many nearly equal corridors) from the corpus: A* paths
// from both ends were measured 0.5-1.0% over exact at 5 of 100 end points; through the
// windows every path of these 24 pairs is within 0.1% of CGAL's exact length (measured: worst
// 0.052% here, 0.059% over the 20 corpus pairs, docs/pathfinding.md "Windows").
TEST(PathWindows, PizzaAgainstExact) {
  const std::string path = data_dir() + "/../corpus/pizza.obj";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "corpus mesh missing";
  const TriangleMesh m = io::read_mesh(path).mesh;
  reference::ExactGeodesicSolver exact(m);
  const GeodesicSolver solver(m);
  const pathfinding::PathTracer tracer(m);
  pathfinding::PathQueryOptions o;
  o.method = pathfinding::PathMethod::windows;
  SplitMix rng{11};
  double sum = 0;
  int n = 0;
  for (int trial = 0; trial < 2; ++trial) {
    const Index s = Index(rng.next() % m.num_vertices());
    const std::vector<double> ex = exact.distances_from_vertex(s);
    std::vector<Endpoint> ends;
    for (int k = 0; k < 12; ++k) ends.push_back(Endpoint::at_vertex(Index(rng.next() % m.num_vertices())));
    for (const Endpoint& e : ends) {
      SCOPED_TRACE("source " + std::to_string(s) + " target " + std::to_string(e.element));
      const auto r = pathfinding::shortest_paths(solver, tracer, Endpoint::at_vertex(s), {e}, o);
      const pathfinding::GeodesicPath& p = r.paths[0];
      expect_valid_path(m, p);
      if (!(ex[e.element] > 0)) continue;
      const double rel = (p.length - ex[e.element]) / ex[e.element];
      EXPECT_GT(rel, -1e-6) << "a surface path cannot be shorter than the geodesic";
      EXPECT_LT(rel, 1e-3);
      EXPECT_EQ(r.edge_fallbacks, 0u);
      sum += rel, ++n;
    }
  }
  ASSERT_GT(n, 20);
  EXPECT_LT(sum / n, 1e-4);
}

// A thin CAD plate whose faces reach aspect ratio 8e6: the walk used to count such needles as
// degenerate and stopped at them ("ran off the mesh boundary" on a closed mesh), and the edge
// path (up to 47% long) replaced the path. Through the windows every path is near exact.
TEST(PathWindows, NeedlePlateAgainstExact) {
  const std::string path = data_dir() + "/../corpus/trimesh_testplate.glb";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "corpus mesh missing";
  const TriangleMesh m = weld_vertices(io::read_mesh(path).mesh).mesh;   // as the apps read glTF
  ASSERT_EQ(m.num_vertices(), 130u);
  reference::ExactGeodesicSolver exact(m);
  const GeodesicSolver solver(m);
  const pathfinding::PathTracer tracer(m);
  const std::vector<double> ex = exact.distances_from_vertex(0);
  pathfinding::PathQueryOptions o;
  o.method = pathfinding::PathMethod::windows;
  int n = 0;
  for (Index t = 1; t < m.num_vertices(); t += 3) {
    if (!(ex[t] > 0)) continue;
    SCOPED_TRACE("target " + std::to_string(t));
    const auto r = pathfinding::shortest_paths(solver, tracer, Endpoint::at_vertex(0), {Endpoint::at_vertex(t)}, o);
    expect_valid_path(m, r.paths[0]);
    EXPECT_LT((r.paths[0].length - ex[t]) / ex[t], 5e-3);
    EXPECT_GT((r.paths[0].length - ex[t]) / ex[t], -1e-6);
    ++n;
  }
  EXPECT_GT(n, 30);
}

// A path through a vertex where two squares only touch (the window field's corner windows
// there): straight to the joint and on, traced through the windows, with no fallback to GSP's
// A* or the edges.
TEST(PathWindows, ThroughAVertexWhereFacesOnlyTouch) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}};
  m.triangles = {{0, 1, 3}, {1, 2, 3}, {2, 4, 6}, {4, 5, 6}};
  const pathfinding::PathTracer tracer(m);
  const auto r = pathfinding::shortest_paths(tracer, Endpoint::at_vertex(0), {Endpoint::at_vertex(5)});
  ASSERT_EQ(r.paths.size(), 1u);
  ASSERT_TRUE(r.paths[0].found());
  EXPECT_NEAR(r.paths[0].length, 2 * std::sqrt(2.0), 1e-9);
  EXPECT_EQ(r.astar_fallbacks, 0u);
  EXPECT_EQ(r.edge_fallbacks, 0u);
}

// Four collinear vertices and two faces without area: no field reaches past the start (no
// face has a plane), but the edges join them, so the path is the edge path (gsp-geodesic gives
// 0 1 2 3 there), by either method; a vertex of another component still has none.
TEST(PathWindows, EdgesWithoutAreaStillJoin) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {10, 0, 0}, {11, 0, 0}, {10, 1, 0}};
  m.triangles = {{0, 1, 2}, {1, 2, 3}, {4, 5, 6}};
  const pathfinding::PathTracer tracer(m);
  for (const auto method : {pathfinding::PathMethod::windows, pathfinding::PathMethod::astar}) {
    pathfinding::PathQueryOptions o;
    o.method = method;
    const auto r = pathfinding::shortest_paths(tracer, Endpoint::at_vertex(0), {Endpoint::at_vertex(3), Endpoint::at_vertex(5)}, o);
    ASSERT_EQ(r.paths.size(), 2u);
    ASSERT_TRUE(r.paths[0].found());
    EXPECT_NEAR(r.paths[0].length, 3.0, 1e-12);
    EXPECT_GE(r.edge_fallbacks, 1u);
    EXPECT_FALSE(r.paths[1].found());
  }
}

}  // namespace
}  // namespace gsp::test
