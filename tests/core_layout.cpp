// Cache layout: the permutations are bijections with inverse ranks, applying them keeps the
// geometry and topology, and the clustering order is more local than the input or a shuffle.
#include <gsp/errors.hpp>
#include <gsp/layout.hpp>
#include <gsp/topology.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "helpers/mesh_builders.hpp"

namespace gsp {
namespace {

void expect_valid_layout(const TriangleMesh& m, const Layout& l) {
  ASSERT_EQ(l.vertex_order.size(), m.num_vertices());
  ASSERT_EQ(l.vertex_rank.size(), m.num_vertices());
  ASSERT_EQ(l.face_order.size(), m.num_faces());
  ASSERT_EQ(l.face_rank.size(), m.num_faces());
  std::vector<bool> seen(m.num_vertices(), false);
  for (std::size_t i = 0; i < l.vertex_order.size(); ++i) {
    const Index v = l.vertex_order[i];
    ASSERT_LT(v, m.num_vertices());
    EXPECT_FALSE(seen[v]) << "vertex " << v << " twice";
    seen[v] = true;
    EXPECT_EQ(l.vertex_rank[v], i);
  }
  std::vector<bool> seen_face(m.num_faces(), false);
  for (std::size_t i = 0; i < l.face_order.size(); ++i) {
    const Index f = l.face_order[i];
    ASSERT_LT(f, m.num_faces());
    EXPECT_FALSE(seen_face[f]) << "face " << f << " twice";
    seen_face[f] = true;
    EXPECT_EQ(l.face_rank[f], i);
  }
}

void expect_same_geometry(const TriangleMesh& m, const Layout& l) {
  const TriangleMesh out = apply_layout(m, l);
  ASSERT_EQ(out.num_vertices(), m.num_vertices());
  ASSERT_EQ(out.num_faces(), m.num_faces());
  for (std::size_t i = 0; i < out.num_faces(); ++i) {
    const Triangle& old = m.triangles[l.face_order[i]];
    for (int c = 0; c < 3; ++c) {  // same corners in the same order: orientation kept
      EXPECT_EQ(out.triangles[i][c], l.vertex_rank[old[c]]);
      EXPECT_EQ(out.positions[out.triangles[i][c]], m.positions[old[c]]);
    }
  }
  const TopologyReport a = analyze_topology(m, build_connectivity(m));
  const TopologyReport b = analyze_topology(out, build_connectivity(out));
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.boundary_edges, b.boundary_edges);
  EXPECT_EQ(a.boundary_loops, b.boundary_loops);
  EXPECT_EQ(a.components, b.components);
  EXPECT_EQ(a.nonmanifold_edges, b.nonmanifold_edges);
  EXPECT_EQ(a.nonmanifold_vertices, b.nonmanifold_vertices);
  EXPECT_EQ(a.inconsistent_edges, b.inconsistent_edges);
  EXPECT_EQ(a.duplicate_faces, b.duplicate_faces);
  EXPECT_EQ(a.isolated_vertices, b.isolated_vertices);
  EXPECT_EQ(a.euler_characteristic, b.euler_characteristic);
}

std::vector<TriangleMesh> test_meshes() {
  return {test::single_triangle(), test::quad(),   test::grid(9),     test::tetrahedron(),
          test::icosphere(3),      test::cylinder(16, 9), test::strip(20), test::book(),
          test::bowtie(),          test::flipped_face_tetrahedron(), test::duplicate_and_degenerate(),
          TriangleMesh{}};
}

TEST(CoreLayout, AllLayoutsAreValidAndKeepTheGeometry) {
  for (const TriangleMesh& m : test_meshes()) {
    SCOPED_TRACE(m.num_vertices());
    for (const Layout& l : {compute_cache_layout(m), spatial_layout(m), random_layout(m, 7), identity_layout(m)}) {
      expect_valid_layout(m, l);
      expect_same_geometry(m, l);
    }
  }
}

TEST(CoreLayout, NormalsFollowTheirVertices) {
  TriangleMesh m = test::icosphere(1);
  m.normals = m.positions;  // unit sphere: the normal is the position
  const Layout l = compute_cache_layout(m);
  const TriangleMesh out = apply_layout(m, l);
  ASSERT_EQ(out.normals.size(), m.num_vertices());
  for (std::size_t i = 0; i < out.num_vertices(); ++i) EXPECT_EQ(out.normals[i], out.positions[i]);
}

TEST(CoreLayout, FacesAreOrderedBySmallestNewVertex) {
  const TriangleMesh m = test::icosphere(2);
  const TriangleMesh out = apply_layout(m, compute_cache_layout(m));
  for (std::size_t i = 1; i < out.num_faces(); ++i) {
    Triangle a = out.triangles[i - 1], b = out.triangles[i];
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_LE(a, b) << i;
  }
}

TEST(CoreLayout, IsDeterministic) {
  const TriangleMesh m = test::cylinder(30, 20);
  const Layout a = compute_cache_layout(m), b = compute_cache_layout(m);
  EXPECT_EQ(a.vertex_order, b.vertex_order);
  EXPECT_EQ(a.face_order, b.face_order);
}

TEST(CoreLayout, ComponentsStayContiguousAndIsolatedVerticesGoLast) {
  // Two grids interleaved vertex by vertex, plus two vertices no face names.
  const TriangleMesh g = test::grid(6);
  const Index n = static_cast<Index>(g.num_vertices());
  TriangleMesh m;
  m.positions.push_back({-5, -5, -5});
  for (Index v = 0; v < n; ++v) {
    m.positions.push_back(g.positions[v]);
    m.positions.push_back(g.positions[v] + Vec3{0, 0, 3});
  }
  m.positions.push_back({9, 9, 9});
  for (const Triangle& t : g.triangles) {
    m.triangles.push_back({2 * t[0] + 1, 2 * t[1] + 1, 2 * t[2] + 1});
    m.triangles.push_back({2 * t[0] + 2, 2 * t[1] + 2, 2 * t[2] + 2});
  }
  const Layout l = compute_cache_layout(m);
  expect_valid_layout(m, l);
  // First component (odd input indices) first, then the even ones, then 0 and the last.
  for (Index i = 0; i < n; ++i) EXPECT_EQ(l.vertex_order[i] % 2, 1u) << i;
  for (Index i = n; i < 2 * n; ++i) EXPECT_EQ(l.vertex_order[i] % 2, 0u) << i;
  EXPECT_EQ(l.vertex_order[2 * n], 0u);
  EXPECT_EQ(l.vertex_order[2 * n + 1], 2 * n + 1);
}

TEST(CoreLayout, MeanNeighbourIndexDistanceOfAGridHasAClosedForm) {
  // Row-major grid: n(n+1) edges of length 1, n(n+1) of n+1, n^2 diagonals of n+2, which
  // averages to (n+2)(2n+1)/(3n+2).
  for (int n : {1, 4, 10, 33}) {
    const double expected = double(n + 2) * (2 * n + 1) / (3 * n + 2);
    EXPECT_NEAR(mean_neighbour_index_distance(test::grid(n)), expected, 1e-12 * expected) << n;
  }
  EXPECT_EQ(mean_neighbour_index_distance(TriangleMesh{}), 0.0);
}

TEST(CoreLayout, ClusteringIsMoreLocalThanInputAndShuffle) {
  // The plain mean gap is dominated by the long jumps between top-level clusters, which a
  // hierarchical layout has as many of as a row-major order (docs/layout.md): it must beat a
  // shuffle by far; the log gap, which counts doublings, must beat the input order too.
  for (const TriangleMesh& m : {test::grid(64), test::icosphere(4), test::cylinder(100, 60)}) {
    const TriangleMesh shuffled = apply_layout(m, random_layout(m, 1));
    const TriangleMesh optimised = apply_layout(m, compute_cache_layout(m));
    EXPECT_LT(mean_neighbour_index_distance(optimised), 0.1 * mean_neighbour_index_distance(shuffled));
    EXPECT_LT(mean_log_neighbour_index_distance(optimised), mean_log_neighbour_index_distance(m));
    EXPECT_LT(mean_log_neighbour_index_distance(optimised), mean_log_neighbour_index_distance(shuffled));
  }
}

TEST(CoreLayout, GridLayoutIsHierarchical) {
  // On a 128 x 128-vertex grid (n = 127, a power of two per side) the clustering alone
  // reproduces the Z-order curve's figures (mean gap 85.9, equal to the rows', log gap 3.09
  // against 5.01); turning clusters to face their neighbours lowers the log gap to 3.05 at a
  // mean gap within 1% of the rows'.
  const TriangleMesh m = test::grid(127);
  const TriangleMesh optimised = apply_layout(m, compute_cache_layout(m));
  EXPECT_NEAR(mean_log_neighbour_index_distance(m), 5.01, 0.01);
  EXPECT_LE(mean_log_neighbour_index_distance(optimised), 3.09);
  EXPECT_NEAR(mean_neighbour_index_distance(optimised), mean_neighbour_index_distance(m),
              0.01 * mean_neighbour_index_distance(m));
}

TEST(CoreLayout, LayoutOfAShuffledGridRecoversLocality) {
  const TriangleMesh m = apply_layout(test::grid(100), random_layout(test::grid(100), 5));
  const TriangleMesh optimised = apply_layout(m, compute_cache_layout(m));
  EXPECT_GT(mean_log_neighbour_index_distance(m), 10.0);  // about log2(N) - 2 for a shuffle
  EXPECT_LT(mean_log_neighbour_index_distance(optimised), 3.6);
}

// The Z-order of a shuffled grid: vertices near in space near in memory again, as local as
// the clustering's (3.08 against 3.11; the shuffle: 11.15).
TEST(CoreLayout, SpatialLayoutOfAShuffledGridRecoversLocality) {
  const TriangleMesh m = apply_layout(test::grid(100), random_layout(test::grid(100), 5));
  const TriangleMesh ordered = apply_layout(m, spatial_layout(m));
  EXPECT_LT(mean_log_neighbour_index_distance(ordered), 3.3);
  EXPECT_GT(mean_log_neighbour_index_distance(m), 10.0);
  // Deterministic.
  const Layout a = spatial_layout(m), b = spatial_layout(m);
  EXPECT_EQ(a.vertex_order, b.vertex_order);
  EXPECT_EQ(a.face_order, b.face_order);
}

// A mesh with its faces in four blocks, every fourth face in each (what libigl's upsample
// writes: the four children of a face a quarter of the file apart), vertices as they were.
TriangleMesh faces_in_blocks(const TriangleMesh& m) {
  TriangleMesh out = m;
  out.triangles.clear();
  for (std::size_t r = 0; r < 4; ++r)
    for (std::size_t f = r; f < m.num_faces(); f += 4) out.triangles.push_back(m.triangles[f]);
  return out;
}

TEST(CoreLayout, FaceOrderLayoutKeepsTheVerticesAndSortsTheFacesStably) {
  for (const TriangleMesh& m : test_meshes()) {
    const Layout l = face_order_layout(m);
    expect_valid_layout(m, l);
    expect_same_geometry(m, l);
    for (std::size_t v = 0; v < m.num_vertices(); ++v) EXPECT_EQ(l.vertex_order[v], v);
    auto smallest = [&](Index f) { return *std::min_element(m.triangles[f].begin(), m.triangles[f].end()); };
    for (std::size_t i = 1; i < l.face_order.size(); ++i) {
      const Index a = l.face_order[i - 1], b = l.face_order[i];
      EXPECT_LE(smallest(a), smallest(b)) << i;
      if (smallest(a) == smallest(b)) EXPECT_LT(a, b) << "ties keep the input's order, " << i;
    }
  }
  EXPECT_THROW(face_order_layout(TriangleMesh{{{0, 0, 0}}, {{0, 0, 3}}}), InvalidInput);
}

// order_coherence judges the faces as well as the vertices: the grid's rows are coherent in
// both, its faces in four blocks only in the vertices, and sorting the faces puts them right;
// a shuffle is coherent in neither.
TEST(CoreLayout, OrderCoherenceSeesFacesStoredInBlocks) {
  const TriangleMesh rows = test::grid(100);
  const OrderCoherence a = order_coherence(rows);
  EXPECT_TRUE(a.coherent);
  EXPECT_TRUE(a.faces_coherent) << a.face_spread << " against " << a.random_face_spread;
  const TriangleMesh blocks = faces_in_blocks(rows);
  const OrderCoherence b = order_coherence(blocks);
  EXPECT_TRUE(b.coherent);
  EXPECT_FALSE(b.faces_coherent) << b.face_spread << " against " << b.random_face_spread;
  EXPECT_NEAR(b.random_face_spread, std::log2(double(rows.num_faces())) - 1, 1e-12);
  const OrderCoherence c = order_coherence(apply_layout(blocks, face_order_layout(blocks)));
  EXPECT_TRUE(c.coherent);
  EXPECT_TRUE(c.faces_coherent) << c.face_spread;
  const OrderCoherence d = order_coherence(apply_layout(rows, random_layout(rows, 9)));
  EXPECT_FALSE(d.coherent);
  EXPECT_FALSE(d.faces_coherent);
  // Sorting is asked for only from kSortFacesFrom faces on (below, the state fits the caches).
  EXPECT_FALSE(b.sort_faces);
  const TriangleMesh big = faces_in_blocks(test::grid(512));   // 2 * 512^2 faces: the threshold
  ASSERT_EQ(big.num_faces(), kSortFacesFrom);
  const OrderCoherence e = order_coherence(big);
  EXPECT_TRUE(e.coherent);
  EXPECT_FALSE(e.faces_coherent);
  EXPECT_TRUE(e.sort_faces);
  EXPECT_FALSE(order_coherence(test::grid(512)).sort_faces);
}

TEST(CoreLayout, MeanLogNeighbourIndexDistanceOfAStrip) {
  // strip(q) numbers vertices in pairs across the strip: q+1 rungs of gap 1, 2q rails of gap
  // 2 and q diagonals (a, a+3) of gap 3: mean (q+1 + 2q log2 3 + 2q) / (4q + 1).
  const int q = 50;
  const double expected = (q + 1 + 2 * q * std::log2(3.0) + 2.0 * q) / (4 * q + 1);
  EXPECT_NEAR(mean_log_neighbour_index_distance(test::strip(q)), expected, 1e-12);
}

TEST(CoreLayout, RandomLayoutDependsOnlyOnTheSeed) {
  const TriangleMesh m = test::grid(5);
  const Layout a = random_layout(m, 42), b = random_layout(m, 42), c = random_layout(m, 43);
  EXPECT_EQ(a.vertex_order, b.vertex_order);
  EXPECT_EQ(a.face_order, b.face_order);
  EXPECT_NE(a.vertex_order, c.vertex_order);
  // Pinned values: the shuffle uses our own generator, so these hold on every platform.
  const std::vector<Index> first(a.vertex_order.begin(), a.vertex_order.begin() + 8);
  EXPECT_EQ(first, (std::vector<Index>{0, 4, 32, 31, 2, 33, 34, 19}));
}

TEST(CoreLayout, ApplyLayoutRejectsAMismatchedLayout) {
  const Layout l = identity_layout(test::quad());
  EXPECT_THROW(apply_layout(test::grid(2), l), InvalidInput);
}

// In place: the same mesh as apply_layout (positions, normals, triangles), and the inverse
// layout gives the original back exactly.
TEST(CoreLayout, InPlaceMatchesTheCopyAndTheInverseUndoesIt) {
  TriangleMesh m = test::icosphere(2);
  m.normals = m.positions;
  for (const Layout& l : {compute_cache_layout(m), spatial_layout(m), random_layout(m, 3)}) {
    const TriangleMesh copy = apply_layout(m, l);
    TriangleMesh in_place = m;
    apply_layout_in_place(in_place, l);
    EXPECT_EQ(in_place.positions, copy.positions);
    EXPECT_EQ(in_place.normals, copy.normals);
    EXPECT_EQ(in_place.triangles, copy.triangles);
    apply_layout_in_place(in_place, inverse_layout(l));
    EXPECT_EQ(in_place.positions, m.positions);
    EXPECT_EQ(in_place.normals, m.normals);
    EXPECT_EQ(in_place.triangles, m.triangles);
  }
  TriangleMesh other = test::grid(2);
  EXPECT_THROW(apply_layout_in_place(other, identity_layout(test::quad())), InvalidInput);
}

}  // namespace
}  // namespace gsp
