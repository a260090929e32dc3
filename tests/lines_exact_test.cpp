// gsp::lines on curved meshes against exact geodesics (gsp::reference, CGAL; GPL, tests only):
// the exact distance to a polyline is approximated from above by the exact multi-source field
// of points sampled densely along it (16 per piece), and GSP's segment propagation must agree
// with it within 0.5% mean relative error over the vertices.
#include "test_data.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/lines/line_distances.hpp>
#include <gsp/reference/exact_geodesics.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace gsp::test {
namespace {

TriangleMesh fertility() { return io::read_mesh(std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off").mesh; }

// Per vertex, the number of edges from `center` (breadth first, up to `hops`; -1 beyond).
std::vector<int> hops_from(const TriangleMesh& m, Index center, int hops) {
  std::vector<std::set<Index>> adj(m.num_vertices());
  for (const Triangle& t : m.triangles)
    for (int i = 0; i < 3; ++i) adj[t[i]].insert(t[(i + 1) % 3]), adj[t[(i + 1) % 3]].insert(t[i]);
  std::vector<int> hop(m.num_vertices(), -1);
  std::vector<Index> front{center};
  hop[center] = 0;
  for (int h = 1; h <= hops; ++h) {
    std::vector<Index> next;
    for (Index v : front)
      for (Index w : adj[v])
        if (hop[w] < 0) hop[w] = h, next.push_back(w);
    front = next;
  }
  return hop;
}

// The boundary of the faces whose corners are all within `hops` edges of `center`: on a benign
// mesh a closed loop of mesh edges (checked: every loop vertex has two loop edges, one cycle).
std::vector<Index> edge_loop_around(const TriangleMesh& m, Index center, int hops) {
  const std::vector<int> hop = hops_from(m, center, hops);
  std::map<std::pair<Index, Index>, int> count;   // undirected edge -> faces of the region
  for (const Triangle& t : m.triangles) {
    if (hop[t[0]] < 0 || hop[t[1]] < 0 || hop[t[2]] < 0) continue;
    for (int i = 0; i < 3; ++i) ++count[std::minmax(t[i], t[(i + 1) % 3])];
  }
  std::map<Index, std::vector<Index>> loop;
  for (const auto& [e, n] : count)
    if (n == 1) loop[e.first].push_back(e.second), loop[e.second].push_back(e.first);
  for (const auto& [v, next] : loop)
    if (next.size() != 2) return {};
  std::vector<Index> chain{loop.begin()->first};
  Index prev = kInvalidIndex;
  while (true) {
    const std::vector<Index>& n = loop[chain.back()];
    const Index next = n[0] != prev ? n[0] : n[1];
    if (next == chain.front()) break;
    prev = chain.back();
    chain.push_back(next);
  }
  return chain.size() == loop.size() ? chain : std::vector<Index>{};
}

double mean_edge(const TriangleMesh& m) {
  double sum = 0;
  for (const Triangle& t : m.triangles)
    for (int i = 0; i < 3; ++i) sum += distance(m.positions[t[i]], m.positions[t[(i + 1) % 3]]);
  return sum / double(3 * m.num_faces());
}

// Exact distances from points sampled along every piece of the source. A point is sampled once:
// an edge source has a piece on each side of the edge, and CGAL 5.5's sequence tree returns
// distances far too large (4.28 where one of the sources alone gives 3.29) when sources nearly
// coincide in two faces.
std::vector<double> sampled_exact(const TriangleMesh& m, const lines::LineSource& src, int per_piece) {
  std::vector<reference::ExactSource> samples;
  std::vector<Vec3> placed;
  const double tiny = 1e-4 * mean_edge(m);
  for (const lines::SegmentPiece& p : src.pieces)
    for (int k = 0; k <= per_piece; ++k) {
      const double t = double(k) / per_piece;
      std::array<double, 3> w;
      for (int i = 0; i < 3; ++i) w[i] = std::max(0.0, (1 - t) * p.start[i] + t * p.end[i]);
      const double sum = w[0] + w[1] + w[2];
      // Nudged off the edges by 1e-6 of the face: CGAL 5.5 also returns distances below the
      // straight-line distance when sources lie exactly on edges, as the crossing points of a
      // snapped polyline do.
      for (double& x : w) x = (1 - 1e-6) * x / sum + 1e-6 / 3;
      const reference::ExactSource s = reference::ExactSource::in_face(p.face, w);
      const Vec3 q = s.position(m);
      bool seen = false;
      for (const Vec3& o : placed) seen = seen || distance(o, q) < tiny;
      if (seen) continue;
      placed.push_back(q);
      samples.push_back(s);
    }
  return reference::exact_geodesic_distances(m, samples);
}

struct Errors {
  double mean = 0, max = 0;
  std::size_t counted = 0;
};

Errors relative_errors(const std::vector<double>& got, const std::vector<double>& exact, double floor) {
  Errors e;
  for (std::size_t v = 0; v < got.size(); ++v) {
    if (!(exact[v] > floor)) continue;
    const double r = std::abs(got[v] - exact[v]) / exact[v];
    e.mean += r, e.max = std::max(e.max, r), ++e.counted;
  }
  if (e.counted) e.mean /= double(e.counted);
  return e;
}

// The first simple loop of at least `min_edges` edges around `center`.
std::vector<Index> some_loop(const TriangleMesh& m, Index center, std::size_t min_edges) {
  for (int hops = 2; hops < 20; ++hops) {
    std::vector<Index> loop = edge_loop_around(m, center, hops);
    if (loop.size() >= min_edges) return loop;
  }
  return {};
}

TEST(LinesExact, ClosedEdgeLoopOnFertility) {
  const TriangleMesh m = fertility();
  const std::vector<Index> loop = some_loop(m, 100, 30);
  ASSERT_FALSE(loop.empty()) << "no simple loop around vertex 100";
  const lines::LineSource src = lines::vertex_chain_source(m, loop, true);
  ASSERT_EQ(src.num_segments(), loop.size());
  const lines::LineResult r = lines::line_distances(m, src);
  for (Index v : loop) EXPECT_EQ(r.vertex_distance[v], 0.0);
  const std::vector<double> exact = sampled_exact(m, src, 16);
  const Errors e = relative_errors(r.vertex_distance, exact, 0.01 * mean_edge(m));
  std::printf("fertility, loop of %zu edges: MRE %.4f%%, max %.3f%% over %zu vertices\n", loop.size(),
              100 * e.mean, 100 * e.max, e.counted);
  EXPECT_GE(e.counted, m.num_vertices() - loop.size());
  EXPECT_LT(e.mean, 0.005);
}

TEST(LinesExact, SnappedPolylineOnFertility) {
  const TriangleMesh m = fertility();
  // A closed polyline through every fourth vertex of a loop, moved off the surface by a tenth
  // of an edge: snapped back and laid across the faces in between (chords cut across faces).
  const std::vector<Index> loop = some_loop(m, 2000, 30);
  ASSERT_FALSE(loop.empty());
  lines::Polyline line;
  const double lift = 0.1 * mean_edge(m);
  for (std::size_t i = 0; i < loop.size(); i += 4) line.push_back(m.positions[loop[i]] + Vec3{lift, 0, 0});
  line.push_back(line.front());
  const lines::LineSource src = lines::polyline_source(m, {line});
  ASSERT_EQ(src.num_segments(), line.size() - 1);
  EXPECT_GT(src.pieces.size(), 20u);
  // Chord midpoints lie farther off the curved surface than the lifted points themselves.
  EXPECT_GE(src.max_snap_distance, lift * (1 - 1e-9));
  EXPECT_LT(src.max_snap_distance, 10 * lift);
  const lines::LineResult r = lines::line_distances(m, src);
  const std::vector<double> exact = sampled_exact(m, src, 8);
  const Errors e = relative_errors(r.vertex_distance, exact, 0.01 * mean_edge(m));
  std::printf("fertility, snapped polyline (%zu pieces): MRE %.4f%%, max %.3f%%\n", src.pieces.size(),
              100 * e.mean, 100 * e.max);
  EXPECT_LT(e.mean, 0.005);
}

// The faces of m whose corners are all within `hops` edges of `center`, as a mesh of its own:
// an open, curved patch.
TriangleMesh patch(const TriangleMesh& m, Index center, int hops) {
  const std::vector<int> hop = hops_from(m, center, hops);
  TriangleMesh out;
  std::vector<Index> index(m.num_vertices(), kInvalidIndex);
  for (const Triangle& t : m.triangles) {
    if (hop[t[0]] < 0 || hop[t[1]] < 0 || hop[t[2]] < 0) continue;
    Triangle n;
    for (int i = 0; i < 3; ++i) {
      if (index[t[i]] == kInvalidIndex) index[t[i]] = Index(out.positions.size()), out.positions.push_back(m.positions[t[i]]);
      n[i] = index[t[i]];
    }
    out.triangles.push_back(n);
  }
  return out;
}

TEST(LinesExact, BoundaryOfACurvedPatch) {
  const TriangleMesh m = patch(fertility(), 2000, 12);
  ASSERT_GT(m.num_faces(), 300u);
  const lines::LineSource src = lines::boundary_source(m);
  const lines::LineResult r = lines::line_distances(m, src);
  const std::vector<double> exact = sampled_exact(m, src, 8);
  const Errors e = relative_errors(r.vertex_distance, exact, 0.01 * mean_edge(m));
  std::printf("fertility patch (%zu faces), boundary (%zu edges): MRE %.4f%%, max %.3f%%\n", m.num_faces(),
              src.num_segments(), 100 * e.mean, 100 * e.max);
  EXPECT_LT(e.mean, 0.005);
}

// A point source is a segment of length zero: the kernel then does what the core's GSP does
// (on the input faces) and must be as accurate.
TEST(LinesExact, ZeroLengthSegmentIsAPointSource) {
  const TriangleMesh m = fertility();
  for (Index v : {0u, 2000u}) {
    const lines::LineSource src = lines::polyline_source(m, {{m.positions[v], m.positions[v]}});
    const lines::LineResult r = lines::line_distances(m, src);
    EXPECT_EQ(r.vertex_distance[v], 0.0);
    const std::vector<double> exact = reference::exact_geodesic_distances(m, {reference::ExactSource::at_vertex(v)});
    const Errors e = relative_errors(r.vertex_distance, exact, 1e-9);
    std::printf("fertility, point source at vertex %u: MRE %.4f%%, max %.3f%%\n", v, 100 * e.mean, 100 * e.max);
    EXPECT_LT(e.mean, 0.003);
  }
}

}  // namespace
}  // namespace gsp::test
