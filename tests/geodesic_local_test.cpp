// Bounded queries (GeodesicSolver::compute_local): the same numbers as compute() for everything
// within max_distance, only the neighbourhood in the result, and a workspace that is put back
// exactly after every query (so query order never matters).
#include "helpers/geodesic_fixtures.hpp"

#include <gsp/errors.hpp>
#include <gsp/dijkstra.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace gsp::test {
namespace {

TriangleMesh fertility() {
  return io::read_mesh(std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off").mesh;
}

// compute_local against compute on the same (input) faces (`on_input`: a solver of the same
// mesh without the intrinsic Delaunay flips): identical vertex distances and labels within
// max_distance, nothing beyond, identical face records for the faces reached.
void expect_same(const GeodesicSolver& solver, const GeodesicSolver& on_input, LocalWorkspace& ws,
                 const std::vector<Source>& sources, const GeodesicOptions& o) {
  GeodesicOptions full_options = o;
  // The propagation alone: the relaxation runs in model units in a bounded query (the same
  // bounds, other rounding), see RelaxedWithinTheRadius.
  full_options.vertex_relaxation = false;
  GeodesicOptions local_options = o;
  local_options.vertex_relaxation = false;
  const GeodesicResult full = on_input.compute(sources, full_options);
  const LocalField local = solver.compute_local(sources, local_options, ws);
  std::size_t within = 0;
  for (double d : full.vertex_distance) within += std::isfinite(d);
  ASSERT_EQ(local.vertices.size(), within);
  for (std::size_t k = 0; k < local.vertices.size(); ++k) {
    const Index v = local.vertices[k];
    EXPECT_EQ(local.vertex_distance[k], full.vertex_distance[v]) << "vertex " << v;
    EXPECT_EQ(local.vertex_source[k], full.vertex_source[v]);
    EXPECT_LE(local.vertex_distance[k], o.max_distance);
  }
  // The faces listed: those that can hold a point within the radius, among them every face
  // whose centroid is within it.
  std::size_t centroid_within = 0, listed_within = 0;
  for (double d : full.face_distance) centroid_within += d <= o.max_distance;
  for (double d : local.face_distance) listed_within += d <= o.max_distance;
  EXPECT_EQ(listed_within, centroid_within);
  EXPECT_EQ(local.stats.faces_reached, full.stats.faces_reached);
  EXPECT_EQ(local.stats.update_steps, full.stats.update_steps);
  for (std::size_t k = 0; k < local.faces.size(); ++k) {
    const Index f = local.faces[k];
    EXPECT_EQ(local.face_distance[k], full.face_distance[f]);
    EXPECT_EQ(local.face_source[k], full.face_source[f]);
    if (!o.want_face_sources) continue;
    EXPECT_EQ(local.face_sources[k].sigma, full.face_sources[f].sigma);
    EXPECT_EQ(distance(local.face_sources[k].position, full.face_sources[f].position), 0.0);
  }
}

TEST(LocalQuery, SameNumbersAsComputeWithinTheRadius) {
  const TriangleMesh m = fertility();
  const GeodesicSolver solver(m);
  SolverOptions no_flips;
  no_flips.intrinsic_delaunay = false;
  const GeodesicSolver on_input(m, no_flips);
  LocalWorkspace ws = solver.make_workspace();
  const double r = 0.08 * bbox_diagonal(m);
  GeodesicOptions o;
  o.max_distance = r;
  SplitMix rng{11};
  for (int trial = 0; trial < 6; ++trial) {
    SCOPED_TRACE(trial);
    o.want_face_sources = trial % 2 == 0;
    o.precision = trial % 3 == 2 ? Precision::double_precision : Precision::single;
    const Index f = Index(rng.next() % m.num_faces());
    const Index v = Index(rng.next() % m.num_vertices());
    expect_same(solver, on_input, ws, {Source::in_face(f, {0.2, 0.5, 0.3})}, o);
    expect_same(solver, on_input, ws, {Source::in_face(f, {0.6, 0.2, 0.2}), Source::at_vertex(v, 0.01 * r)}, o);
  }
}

// With the vertex relaxation (the default) a bounded query is never above the edge path either,
// and never above its own unrelaxed values.
TEST(LocalQuery, RelaxedWithinTheRadius) {
  const TriangleMesh m = fertility();
  const GeodesicSolver solver(m);
  const DijkstraSolver edges(m);
  LocalWorkspace ws = solver.make_workspace();
  GeodesicOptions o, plain;
  o.max_distance = plain.max_distance = 0.1 * bbox_diagonal(m);
  plain.vertex_relaxation = false;
  for (Index v : {Index(0), Index(1234), Index(4000)}) {
    const std::vector<double> edge = edges.compute({Source::at_vertex(v)}).vertex_distance;
    const LocalField relaxed = solver.compute_local({Source::at_vertex(v)}, o, ws);
    const LocalField alone = solver.compute_local({Source::at_vertex(v)}, plain, ws);
    std::vector<double> before(m.num_vertices(), std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < alone.vertices.size(); ++k) before[alone.vertices[k]] = alone.vertex_distance[k];
    ASSERT_GE(relaxed.vertices.size(), alone.vertices.size());
    for (std::size_t k = 0; k < relaxed.vertices.size(); ++k) {
      const Index u = relaxed.vertices[k];
      EXPECT_LE(relaxed.vertex_distance[k], edge[u] * (1 + 1e-6)) << "vertex " << u;
      EXPECT_LE(relaxed.vertex_distance[k], before[u]) << "vertex " << u;
    }
  }
}

// The result follows the neighbourhood: a small radius reaches a small part of the mesh.
TEST(LocalQuery, CostFollowsTheNeighbourhood) {
  const TriangleMesh m = fertility();
  const GeodesicSolver solver(m);
  LocalWorkspace ws = solver.make_workspace();
  GeodesicOptions o;
  o.max_distance = 0.02 * bbox_diagonal(m);
  const LocalField small = solver.compute_local({Source::at_vertex(10)}, o, ws);
  EXPECT_GT(small.vertices.size(), 3u);
  EXPECT_LT(small.faces.size(), m.num_faces() / 50);
  o.max_distance = std::numeric_limits<double>::infinity();
  const LocalField all = solver.compute_local({Source::at_vertex(10)}, o, ws);
  EXPECT_EQ(all.vertices.size(), m.num_vertices());   // fertility is one component
}

// Queries interleaved on one workspace give what each gives on a fresh one: the state is put
// back exactly, also after a query that threw.
TEST(LocalQuery, WorkspaceIsRestoredBetweenQueries) {
  const TriangleMesh m = fertility();
  const GeodesicSolver solver(m);
  GeodesicOptions o;
  o.max_distance = 0.1 * bbox_diagonal(m);
  LocalWorkspace fresh_a = solver.make_workspace(), fresh_b = solver.make_workspace(), ws = solver.make_workspace();
  const std::vector<Source> a{Source::in_face(100, {0.3, 0.3, 0.4})}, b{Source::at_vertex(3000)};
  const LocalField ra = solver.compute_local(a, o, fresh_a), rb = solver.compute_local(b, o, fresh_b);
  (void)solver.compute_local(b, o, ws);
  EXPECT_THROW(solver.compute_local({Source::at_vertex(5), Source::at_vertex(99999999)}, o, ws), InvalidInput);
  const LocalField again = solver.compute_local(a, o, ws);
  EXPECT_EQ(again.vertices, ra.vertices);
  EXPECT_EQ(again.vertex_distance, ra.vertex_distance);
  EXPECT_EQ(again.faces, ra.faces);
  const LocalField again_b = solver.compute_local(b, o, ws);
  EXPECT_EQ(again_b.vertex_distance, rb.vertex_distance);
}

// Both queries check their options in one place (validate_options): the same bad option gives
// the same message from compute() and compute_local().
TEST(LocalQuery, BadOptionsSameMessageAsCompute) {
  const TriangleMesh m = grid(4);
  const GeodesicSolver solver(m);
  LocalWorkspace ws = solver.make_workspace();
  auto message = [](auto&& run) -> std::string {
    try {
      run();
    } catch (const InvalidInput& e) {
      return e.what();
    }
    return "no error";
  };
  std::vector<GeodesicOptions> bad(4);
  bad[0].f = 0;
  bad[1].f1 = -1;
  bad[2].max_distance = -1;
  bad[3].max_distance = std::nan("");
  for (const GeodesicOptions& o : bad) {
    const std::string full = message([&] { solver.compute({Source::at_vertex(0)}, o); });
    const std::string local = message([&] { solver.compute_local({Source::at_vertex(0)}, o, ws); });
    EXPECT_NE(full, "no error");
    EXPECT_EQ(full, local);
  }
  GeodesicOptions far;
  far.targets = {1000};
  EXPECT_NE(message([&] { solver.compute({Source::at_vertex(0)}, far); }).find("target vertex 1000 does not exist"),
            std::string::npos);
}

TEST(LocalQuery, Errors) {
  const TriangleMesh m = grid(4);
  const GeodesicSolver solver(m), other(m);
  LocalWorkspace ws = other.make_workspace();
  EXPECT_THROW(solver.compute_local({Source::at_vertex(0)}, {}, ws), InvalidInput);
  LocalWorkspace mine = solver.make_workspace();
  GeodesicOptions o;
  o.targets = {3};
  EXPECT_THROW(solver.compute_local({Source::at_vertex(0)}, o, mine), InvalidInput);
  o.targets.clear();
  o.max_distance = -1;
  EXPECT_THROW(solver.compute_local({Source::at_vertex(0)}, o, mine), InvalidInput);
  // On a plane the local field is exact like the full one.
  o.max_distance = 2.5;
  const LocalField f = solver.compute_local({Source::at_vertex(0)}, o, mine);
  for (std::size_t k = 0; k < f.vertices.size(); ++k)
    EXPECT_NEAR(f.vertex_distance[k], distance(m.positions[f.vertices[k]], m.positions[0]), 1e-5);
}

}  // namespace
}  // namespace gsp::test
