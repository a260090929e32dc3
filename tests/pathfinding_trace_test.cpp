// Path tracing through GSP's virtual sources: straight segments on flat meshes, surface
// polylines whose length matches the field, corners at vertices, non-manifold edges, failures.
#include "helpers/geodesic_fixtures.hpp"
#include "helpers/mesh_builders.hpp"
#include "pathfinding_support.hpp"
#include "test_data.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/pathfinding/path_tracer.hpp>
#include <gsp/pathfinding/shortest_path.hpp>

#include <gtest/gtest.h>

namespace gsp::test {
namespace {

using pathfinding::Endpoint;
using pathfinding::PathTracer;

GeodesicResult field_from(const TriangleMesh& m, const Source& s) {
  GeodesicOptions o;
  o.want_face_sources = true;
  return geodesic_distances(m, {s}, o);
}

// On a plane every geodesic is the straight segment.
TEST(PathTrace, FlatGridsGiveStraightSegments) {
  for (int variant = 0; variant < 2; ++variant) {
    const TriangleMesh m = variant == 0 ? grid(20) : jittered_grid(20, 0.25, 7);
    const PathTracer tracer(m);
    SplitMix rng{99};
    for (int trial = 0; trial < 10; ++trial) {
      const Index s = Index(rng.next() % m.num_vertices());
      const GeodesicResult field = field_from(m, Source::at_vertex(s));
      // A vertex end and a point inside a face.
      const Index t = Index(rng.next() % m.num_vertices());
      const Index f = Index(rng.next() % m.num_faces());
      for (const Endpoint& e : {Endpoint::at_vertex(t), Endpoint::in_face(f, {0.2, 0.3, 0.5})}) {
        const auto path = tracer.trace(field, e);
        expect_valid_path(m, path);
        const Vec3 end = e.position(m);
        const double straight = distance(m.positions[s], end);
        EXPECT_NEAR(path.length, straight, 1e-5) << "variant " << variant << " trial " << trial;
        EXPECT_LT(distance(path.points.front().position, m.positions[s]), 1e-6);
        EXPECT_LT(distance(path.points.back().position, end), 1e-12);
        // Every point lies on the segment.
        for (const auto& q : path.points) {
          const Vec3 d = end - m.positions[s];
          const Vec3 r = q.position - m.positions[s];
          EXPECT_LT(norm(cross(d, r)) / (norm(d) + 1e-300), 1e-5);
        }
        EXPECT_EQ(path.source, 0u);
      }
    }
  }
}

TEST(PathTrace, SourceInsideAFace) {
  const TriangleMesh m = jittered_grid(12, 0.2, 3);
  const Source s = Source::in_face(40, {0.1, 0.6, 0.3});
  const Vec3 sp = Endpoint::in_face(40, {0.1, 0.6, 0.3}).position(m);
  const GeodesicResult field = field_from(m, s);
  const auto path = PathTracer(m).trace(field, Endpoint::at_vertex(0));
  expect_valid_path(m, path);
  EXPECT_NEAR(path.length, distance(sp, m.positions[0]), 1e-5);
  EXPECT_LT(distance(path.points.front().position, sp), 1e-6);
}

TEST(PathTrace, EndAtTheSourceIsOnePoint) {
  const TriangleMesh m = grid(4);
  const GeodesicResult field = field_from(m, Source::at_vertex(7));
  const auto path = PathTracer(m).trace(field, Endpoint::at_vertex(7));
  ASSERT_TRUE(path.found());
  EXPECT_EQ(path.points.size(), 1u);
  EXPECT_EQ(path.length, 0.0);
}

// An L-shaped (non-convex) domain: the geodesic bends at the reflex corner, a mesh vertex.
TEST(PathTrace, BendsAtAReflexCorner) {
  TriangleMesh m;
  // Unit squares of a 4 x 4 grid without the top-right 2 x 2 block.
  const int n = 4;
  auto id = [&](int i, int j) { return Index(j * (n + 1) + i); };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back({double(i), double(j), 0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (i >= 2 && j >= 2) continue;
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  const Index from = id(4, 0), to = id(0, 4), corner = id(2, 2);
  const GeodesicResult field = field_from(m, Source::at_vertex(from));
  const auto path = PathTracer(m).trace(field, Endpoint::at_vertex(to));
  expect_valid_path(m, path);
  const double expected = distance(m.positions[from], m.positions[corner]) + distance(m.positions[corner], m.positions[to]);
  EXPECT_NEAR(path.length, expected, 1e-5);
  bool through_corner = false;
  for (const auto& q : path.points) through_corner |= distance(q.position, m.positions[corner]) < 1e-6;
  EXPECT_TRUE(through_corner);
  EXPECT_NEAR(path.field_distance, expected, 1e-5);
}

// Three pages on one spine: the path from page 1 to page 2 crosses the non-manifold edge.
TEST(PathTrace, CrossesANonManifoldEdge) {
  const TriangleMesh m = book();
  const GeodesicResult field = field_from(m, Source::at_vertex(2));
  const auto path = PathTracer(m).trace(field, Endpoint::at_vertex(4));
  expect_valid_path(m, path);
  // Unfolded, vertices 2 and 4 lie on either side of the spine at unit distance, level with
  // spine vertex 0: the geodesic runs straight through vertex 0, length 2.
  EXPECT_NEAR(path.length, 2.0, 1e-5);
  EXPECT_NEAR(path.length, path.field_distance, 1e-5);
}

TEST(PathTrace, UnreachedEndAndBadInput) {
  TriangleMesh m = grid(2);
  TriangleMesh two = m;   // a second, disconnected copy
  const Index off = Index(m.num_vertices());
  for (Vec3 p : m.positions) two.positions.push_back(p + Vec3{5, 0, 0});
  for (Triangle t : m.triangles) two.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
  const GeodesicResult field = field_from(two, Source::at_vertex(0));
  const PathTracer tracer(two);
  EXPECT_THROW(tracer.trace(field, Endpoint::at_vertex(off + 1)), pathfinding::NoPath);
  EXPECT_THROW(tracer.trace(field, Endpoint::at_vertex(9999)), InvalidInput);
  EXPECT_THROW(tracer.trace(field, Endpoint::in_face(0, {0.5, 0.6, 0.1})), InvalidInput);
  const auto all = tracer.trace_all(field, {Endpoint::at_vertex(off + 1), Endpoint::at_vertex(4)});
  ASSERT_EQ(all.size(), 2u);
  EXPECT_FALSE(all[0].found());
  EXPECT_TRUE(all[1].found());
  GeodesicResult no_sources = geodesic_distances(two, {Source::at_vertex(0)});
  EXPECT_THROW(tracer.trace(no_sources, Endpoint::at_vertex(1)), InvalidInput);
}

// A field whose virtual sources cycle (two faces pointing at each other): the walk gives up
// after max_steps and the route down the (intact) vertex distances is the path; with the
// vertex distances broken too, a clear error, not a hang.
TEST(PathTrace, InconsistentFieldFailsClearly) {
  const TriangleMesh m = quad();
  GeodesicResult field = field_from(m, Source::at_vertex(0));
  // Make each face's source the far corner of the other face, with sigma > 0.
  field.face_sources[0].position = Vec3{-5, 5, 0};
  field.face_sources[0].sigma = 1;
  field.face_sources[1].position = Vec3{5, -5, 0};
  field.face_sources[1].sigma = 1;
  pathfinding::TraceOptions o;
  o.max_steps = 50;
  const Endpoint end = Endpoint::in_face(0, {0.2, 0.4, 0.4});
  const auto path = PathTracer(m, o).trace(field, end);
  expect_valid_path(m, path);
  EXPECT_NEAR(path.length, distance(m.positions[0], end.position(m)), 1e-12);
  for (double& d : field.vertex_distance) d = 1;   // no vertex is a source any more
  EXPECT_THROW(PathTracer(m, o).trace(field, end), Error);
}

// One field, many ends: every path from the same source, each consistent with the field.
TEST(PathTrace, FertilityPathsMatchTheField) {
  const TriangleMesh m = io::read_mesh(std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off").mesh;
  const PathTracer tracer(m);
  SplitMix rng{5};
  double sum = 0;
  int n = 0;
  for (int trial = 0; trial < 4; ++trial) {
    const Index s = Index(rng.next() % m.num_vertices());
    const GeodesicResult field = field_from(m, Source::at_vertex(s));
    std::vector<Endpoint> ends;
    for (int k = 0; k < 10; ++k) ends.push_back(Endpoint::at_vertex(Index(rng.next() % m.num_vertices())));
    ends.push_back(Endpoint::in_face(Index(rng.next() % m.num_faces()), {0.3, 0.3, 0.4}));
    const auto paths = tracer.trace_all(field, ends);
    for (std::size_t k = 0; k < paths.size(); ++k) {
      SCOPED_TRACE("trial " + std::to_string(trial) + " end " + std::to_string(k));
      expect_valid_path(m, paths[k]);
      // The taut path is within 0.1% of the exact geodesic (pathfinding_exact_test); the field
      // itself is off by its own error (0.2-0.3% mean, 1.5% at worst on these paths), so the
      // two agree to that, in either direction.
      const double rel = std::abs(paths[k].length - paths[k].field_distance) / paths[k].field_distance;
      EXPECT_LT(rel, 0.02);
      sum += rel, ++n;
      EXPECT_LT(distance(paths[k].points.front().position, m.positions[s]), 1e-6);
    }
  }
  EXPECT_LT(sum / n, 0.005);
}

// shortest_paths(): A*, settle and full propagation give the same taut paths (within 0.1%),
// A* and settle expand fewer faces than the whole mesh, and the Dijkstra-on-edges baseline
// walks along edges (every point a vertex) and is never shorter.
TEST(PathQuery, MethodsAgreeAndEdgePathsAreLonger) {
  const TriangleMesh m = io::read_mesh(std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off").mesh;
  const GeodesicSolver solver(m);
  const PathTracer tracer(m);
  const Endpoint from = Endpoint::at_vertex(100);
  const std::vector<Endpoint> to{Endpoint::at_vertex(2000), Endpoint::in_face(4000, {0.2, 0.3, 0.5})};
  pathfinding::PathQueryOptions o;
  o.method = pathfinding::PathMethod::full;
  const auto full = pathfinding::shortest_paths(solver, tracer, from, to, o);
  o.method = pathfinding::PathMethod::settle;
  const auto settle = pathfinding::shortest_paths(solver, tracer, from, to, o);
  o.method = pathfinding::PathMethod::astar;
  const auto astar = pathfinding::shortest_paths(solver, tracer, from, to, o);
  const auto edges = pathfinding::edge_paths(m, tracer, from, to);
  for (std::size_t k = 0; k < to.size(); ++k) {
    SCOPED_TRACE(k);
    for (const auto* r : {&full, &settle, &astar, &edges}) expect_valid_path(m, r->paths[k]);
    EXPECT_NEAR(astar.paths[k].length, full.paths[k].length, 1e-3 * full.paths[k].length);
    EXPECT_NEAR(settle.paths[k].length, full.paths[k].length, 1e-3 * full.paths[k].length);
    EXPECT_GT(edges.paths[k].length, full.paths[k].length);
    for (std::size_t i = 1; i + 1 < edges.paths[k].points.size(); ++i) {
      const auto& b = edges.paths[k].points[i].point.barycentric;
      EXPECT_NEAR(std::max({b[0], b[1], b[2]}), 1.0, 1e-12) << "edge-path point " << i << " is not a vertex";
    }
  }
  EXPECT_EQ(full.stats.faces_reached, m.num_faces());
  EXPECT_LT(astar.stats.faces_reached, settle.stats.faces_reached);
  EXPECT_LT(settle.stats.faces_reached, full.stats.faces_reached);
}

}  // namespace
}  // namespace gsp::test
