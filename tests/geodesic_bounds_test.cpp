// The two bounds every distance field must respect, whatever the method: at least the straight
// line to the source (no curve is shorter) and at most the shortest path along the mesh edges
// (it is a path on the surface). Checked on built meshes that break them for a specific cause
// (coincident vertices, needles, big faces round a non-manifold vertex), then on every mesh of
// the shared development set and of the corpus beside it (docs/benchmarks.md, "Corpus").
#include "helpers/mesh_builders.hpp"
#include "test_data.hpp"

#include <gsp/cli/load.hpp>
#include <gsp/dijkstra.hpp>
#include <gsp/geodesics.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace gsp;

struct Bounds {
  double below_line = 0;   // largest (line - d) / line over the vertices
  double above_edges = 0;  // largest (d - edge path) / edge path
  std::size_t nan = 0, unreached = 0;
};

Bounds bounds(const TriangleMesh& m, Index source, const std::vector<double>& d) {
  const std::vector<double> edge = DijkstraSolver(m).compute({Source::at_vertex(source)}).vertex_distance;
  Bounds b;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    if (std::isnan(d[v])) {
      ++b.nan;
      continue;
    }
    if (std::isfinite(edge[v]) && !std::isfinite(d[v])) ++b.unreached;
    if (!std::isfinite(d[v])) continue;
    const double line = distance(m.positions[v], m.positions[source]);
    if (line > 0) b.below_line = std::max(b.below_line, (line - d[v]) / line);
    if (edge[v] > 0) b.above_edges = std::max(b.above_edges, (d[v] - edge[v]) / edge[v]);
  }
  return b;
}

// A planar square grid whose centre vertex is split in two copies at one point, each used by
// half of the centre's fan, the halves joined by two zero-area faces over the zero-length edge
// between the copies. `offset` moves the second copy by that much (1e-16: not bit-identical,
// so no weld merges them, as in CAD exports).
TriangleMesh split_centre_grid(double offset) {
  TriangleMesh m = test::grid(6);   // 7 x 7 vertices on [0, 6]^2
  const Index centre = 3 * 7 + 3;
  const Index copy = Index(m.positions.size());
  m.positions.push_back(m.positions[centre] + Vec3{offset, 0, 0});
  for (Triangle& t : m.triangles) {
    bool upper = false;   // faces above the centre's row take the copy
    for (Index v : t) upper |= v / 7 > 3;
    if (upper)
      for (Index& v : t)
        if (v == centre) v = copy;
  }
  m.triangles.push_back({centre, copy, centre - 1});
  m.triangles.push_back({copy, centre, centre + 1});
  return m;
}

TEST(GeodesicBounds, CoincidentVerticesAreOnePoint) {
  // The zero-length edge has no direction: unfolded across it (or through the intrinsic flips
  // next to it) the source landed anywhere, down to distance 0 far from it.
  for (double offset : {0.0, 1e-16}) {
    const TriangleMesh m = split_centre_grid(offset);
    for (Index source : {Index(0), Index(6), Index(45), Index(24)}) {
      const GeodesicResult r = geodesic_distances(m, {Source::at_vertex(source)});
      for (std::size_t v = 0; v < m.num_vertices(); ++v)
        EXPECT_NEAR(r.vertex_distance[v], distance(m.positions[v], m.positions[source]), 1e-5)
            << "offset " << offset << " source " << source << " vertex " << v;
    }
  }
}

// A planar fan of needles: n thin triangles round vertex 0 spanning a few degrees, each about
// 1e5 times longer than wide; then a regular cap so the fan is entered over its short edges.
TriangleMesh needle_fan(int n) {
  TriangleMesh m;
  m.positions.push_back({0, 0, 0});
  for (int i = 0; i <= n; ++i) {
    const double a = 1e-5 * i;
    m.positions.push_back({std::cos(a), std::sin(a), 0});
  }
  for (int i = 0; i < n; ++i) m.triangles.push_back({0, Index(i + 1), Index(i + 2)});
  // The far side: a regular triangle on the fan's outer edge.
  m.positions.push_back({1.5, 1e-5 * n / 2, 0});
  m.triangles.push_back({1, Index(m.positions.size() - 1), Index(n + 1)});
  return m;
}

TEST(GeodesicBounds, NeedlesRunInDouble) {
  const TriangleMesh fan = needle_fan(20);
  SolverOptions input_faces;
  input_faces.intrinsic_delaunay = false;   // keep the needles
  const GeodesicSolver solver(fan, input_faces);
  EXPECT_TRUE(solver.needs_double());
  EXPECT_EQ(solver.resolved_precision(Precision::automatic), Precision::double_precision);
  EXPECT_EQ(solver.resolved_precision(Precision::single), Precision::single);
  const Index far = Index(fan.num_vertices() - 1);
  const GeodesicResult r = solver.compute({Source::at_vertex(far)});
  EXPECT_TRUE(r.stats.double_precision);
  const Bounds b = bounds(fan, far, r.vertex_distance);
  EXPECT_LE(b.below_line, 1e-12);   // planar: a line in the plane is the shortest path
  EXPECT_LE(b.above_edges, 1e-12);

  const GeodesicSolver regular(test::grid(8));
  EXPECT_FALSE(regular.needs_double());
  EXPECT_FALSE(regular.compute({Source::at_vertex(0)}).stats.double_precision);
}

TEST(GeodesicBounds, BuiltMeshesKeepBothBounds) {
  const std::vector<TriangleMesh> meshes = {test::icosphere(3), test::cylinder(24, 8), test::bowtie(),
                                            test::book(), test::duplicate_and_degenerate(),
                                            split_centre_grid(0.0), needle_fan(20)};
  for (std::size_t k = 0; k < meshes.size(); ++k)
    for (Index s = 0; s < 3; ++s) {
      const Bounds b = bounds(meshes[k], s, geodesic_distances(meshes[k], {Source::at_vertex(s)}).vertex_distance);
      EXPECT_LE(b.below_line, 1e-5) << "mesh " << k << " source " << s;
      EXPECT_LE(b.above_edges, 1e-5) << "mesh " << k << " source " << s;
      EXPECT_EQ(b.nan, 0u);
      EXPECT_EQ(b.unreached, 0u);
    }
}

// Where the two bounds meet, a vertex one edge from a vertex source, the value is the edge's
// length in double (as Dijkstra's), not the float propagation's rounding of it (about 1e-7
// relative): a single triangle, a tetrahedron and a soup of triangles, where every vertex is
// such a vertex, give Dijkstra's values; on a grid the source's ring does, in full and
// bounded queries alike, and a second source next to the first keeps its own 0.
TEST(GeodesicBounds, SourceEdgesAreExact) {
  TriangleMesh scaled = test::single_triangle();   // lengths no float holds
  for (Vec3& p : scaled.positions) p = p * 0.7310585786300049 + Vec3{0.1, 0.2, 0.3};
  const std::vector<TriangleMesh> meshes = {scaled, test::tetrahedron(), test::explode(test::icosphere(1))};
  for (std::size_t k = 0; k < meshes.size(); ++k)
    for (Index s = 0; s < 3; ++s) {
      const std::vector<double> edge = DijkstraSolver(meshes[k]).compute({Source::at_vertex(s)}).vertex_distance;
      const std::vector<double> d = geodesic_distances(meshes[k], {Source::at_vertex(s)}).vertex_distance;
      for (std::size_t v = 0; v < edge.size(); ++v)
        if (std::isfinite(edge[v])) EXPECT_DOUBLE_EQ(d[v], edge[v]) << "mesh " << k << " source " << s << " vertex " << v;
    }

  const TriangleMesh g = test::grid(8);   // 9 x 9 vertices, cells of 1
  const GeodesicSolver solver(g);
  const Index centre = 4 * 9 + 4, right = centre + 1;
  const GeodesicResult r = solver.compute({Source::at_vertex(centre)});
  EXPECT_EQ(r.vertex_distance[centre + 9], 1.0);
  EXPECT_EQ(r.vertex_distance[right], 1.0);
  EXPECT_EQ(r.vertex_distance[centre + 10], std::sqrt(2.0));   // the cell's diagonal a-c
  LocalWorkspace ws = solver.make_workspace();
  GeodesicOptions within;
  within.max_distance = 3;
  const LocalField local = solver.compute_local({Source::at_vertex(centre)}, within, ws);
  std::size_t ring = 0;
  for (std::size_t k = 0; k < local.vertices.size(); ++k) {
    const Index v = local.vertices[k];
    if (v != right && v != centre + 9 && v != centre + 10) continue;
    ++ring;
    EXPECT_EQ(local.vertex_distance[k], v == centre + 10 ? std::sqrt(2.0) : 1.0) << "vertex " << v;
  }
  EXPECT_EQ(ring, 3u);
  const GeodesicResult two = solver.compute({Source::at_vertex(centre), Source::at_vertex(right)});
  EXPECT_EQ(two.vertex_distance[right], 0.0);
  EXPECT_EQ(two.vertex_source[right], 1u);
  EXPECT_EQ(two.vertex_distance[centre], 0.0);
}

// Over the shared meshes and the corpus: no NaN, nothing the edge graph reaches left
// unreached, never above the edge path (vertices relaxed along the input's edges become
// pseudo-sources) and never below the straight line (the bound raises what the propagation
// left below it). Without the bound the propagation alone stays within 1% of it: the update
// step bends where a straight path would go below it (rule 8 of docs/gsp-core.md).
TEST(GeodesicBounds, SharedMeshesAndCorpus) {
  if (!test::have_shared_data()) GTEST_SKIP() << "shared meshes not found at " << test::data_dir();
  const std::vector<std::string> files = test::shared_and_corpus_files();
  std::size_t checked = 0, below = 0, below_untested = 0, raised = 0;
  GeodesicOptions raw;
  raw.straight_line_bound = false;
  GeodesicOptions untested = raw;   // nor the update step's test (rule 8)
  untested.straight_line_test = false;
  for (const std::string& path : files) {
    cli::LoadedMesh in;
    try {
      in = cli::load_mesh(path, {});
    } catch (const Error&) {
      continue;   // a point cloud, or a file the readers reject (tested in io_broken_files)
    }
    const TriangleMesh& m = in.mesh;
    if (m.num_faces() == 0) continue;
    const GeodesicSolver solver(m);
    std::mt19937_64 rng(m.num_vertices());
    for (int k = 0; k < 2; ++k) {
      const Index s = Index(m.triangles[rng() % m.num_faces()][0]);
      const GeodesicResult r = solver.compute({Source::at_vertex(s)});
      const Bounds b = bounds(m, s, r.vertex_distance);
      EXPECT_LE(b.above_edges, 1e-5) << path << " source " << s;
      EXPECT_LE(b.below_line, 1e-9) << path << " source " << s;
      EXPECT_EQ(b.nan, 0u) << path;
      EXPECT_EQ(b.unreached, 0u) << path;
      raised += r.stats.raised_to_line > 0;
      const Bounds b_raw = bounds(m, s, solver.compute({Source::at_vertex(s)}, raw).vertex_distance);
      EXPECT_LE(b_raw.above_edges, 1e-5) << path << " source " << s;
      below += b_raw.below_line > 0.01;
      below_untested += bounds(m, s, solver.compute({Source::at_vertex(s)}, untested).vertex_distance).below_line > 0.01;
      ++checked;
    }
  }
  EXPECT_GT(checked, 0u);
  // With the update step's straight-line test no field of the propagation alone is more than
  // 1% below the line; without it 6 of 188 fields are (94 meshes, 2 sources each; 13 before
  // the corner rules were revised; the meshes are listed in docs/benchmarks.md, "Corpus").
  EXPECT_EQ(below, 0u) << below << " of " << checked << " fields more than 1% below the straight line";
  EXPECT_GE(below_untested, 3u) << "the test must be what keeps them above it";
  RecordProperty("fields_below_line_without_test", int(below_untested));
  RecordProperty("fields_below_line_without_bound", int(below));
  RecordProperty("fields_raised_to_line", int(raised));
}

}  // namespace
