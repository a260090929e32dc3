// Properties every geodesic distance field must have, checked on curved meshes where GSP is
// approximate: symmetry, the triangle inequality, truncation, multi-source minimum, and
// independence of the memory layout and queue strategy. Tolerances are stated per test and are
// a few times the method's own error (about 0.2-0.5% mean on these meshes).
#include "helpers/geodesic_fixtures.hpp"
#include "test_data.hpp"

#include <gsp/errors.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace gsp::test {
namespace {

TriangleMesh curved_mesh() {
  if (have_shared_data()) return io::read_mesh(shared_mesh("fertility.off")).mesh;
  return icosphere(4);
}

double field(const GeodesicSolver& s, Index from, Index to) {
  return s.compute({Source::at_vertex(from)}).vertex_distance[to];
}

TEST(GeodesicInvariants, SymmetryWithinTwoPercent) {
  const TriangleMesh m = curved_mesh();
  const GeodesicSolver solver(m);
  SplitMix rng{5};
  double worst = 0, sum = 0;
  int pairs = 0;
  for (int i = 0; i < 12; ++i) {
    const Index a = Index(rng.next() % m.num_vertices()), b = Index(rng.next() % m.num_vertices());
    if (a == b) continue;
    const double ab = field(solver, a, b), ba = field(solver, b, a);
    ASSERT_TRUE(std::isfinite(ab) && std::isfinite(ba));
    const double e = std::abs(ab - ba) / std::max(ab, ba);
    worst = std::max(worst, e), sum += e, ++pairs;
  }
  // Each direction carries the method's own error (0.2-0.5% mean, a few % at worst).
  EXPECT_LT(worst, 0.02);
  EXPECT_LT(sum / pairs, 0.005);
}

TEST(GeodesicInvariants, TriangleInequalityOnSamples) {
  const TriangleMesh m = curved_mesh();
  const GeodesicSolver solver(m);
  SplitMix rng{11};
  for (int i = 0; i < 6; ++i) {
    const Index a = Index(rng.next() % m.num_vertices()), b = Index(rng.next() % m.num_vertices());
    const auto da = solver.compute({Source::at_vertex(a)}).vertex_distance;
    const auto db = solver.compute({Source::at_vertex(b)}).vertex_distance;
    // d(a, c) <= d(a, b) + d(b, c) for every vertex c, up to the method's error (1%).
    for (std::size_t c = 0; c < m.num_vertices(); ++c)
      ASSERT_LE(da[c], (da[b] + db[c]) * 1.01 + 1e-9) << "a " << a << " b " << b << " c " << c;
  }
}

TEST(GeodesicInvariants, MaxDistanceTruncationEqualsFullInsideRadius) {
  const TriangleMesh m = curved_mesh();
  const GeodesicSolver solver(m);
  const auto full = solver.compute({Source::at_vertex(17)});
  double far = 0;
  for (double d : full.vertex_distance) far = std::max(far, d);
  GeodesicOptions o;
  o.max_distance = 0.3 * far;
  const auto cut = solver.compute({Source::at_vertex(17)}, o);
  std::size_t inside = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    if (full.vertex_distance[v] <= o.max_distance * 0.98) {
      ++inside;
      ASSERT_NEAR(cut.vertex_distance[v], full.vertex_distance[v], 1e-6 * far) << "vertex " << v;
    }
    if (std::isfinite(cut.vertex_distance[v])) EXPECT_LE(cut.vertex_distance[v], o.max_distance);
  }
  EXPECT_GT(inside, 10u);
  // Local work: fewer faces were touched than in the full run.
  EXPECT_LT(cut.stats.faces_reached, full.stats.faces_reached);
}

TEST(GeodesicInvariants, MultiSourceIsTheMinimumOfSingleSources) {
  const TriangleMesh m = curved_mesh();
  const GeodesicSolver solver(m);
  const Index s[3] = {3, Index(m.num_vertices() / 2), Index(m.num_vertices() - 9)};
  const auto multi = solver.compute({Source::at_vertex(s[0]), Source::at_vertex(s[1]), Source::at_vertex(s[2])});
  std::vector<std::vector<double>> single;
  for (Index v : s) single.push_back(solver.compute({Source::at_vertex(v)}).vertex_distance);
  double sum = 0, worst = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const double expect = std::min({single[0][v], single[1][v], single[2][v]});
    const double e = relative_error(multi.vertex_distance[v], expect);
    sum += e, worst = std::max(worst, e);
    // The label names a source whose own field is (near) the minimum.
    const Index label = multi.vertex_source[v];
    ASSERT_LT(label, 3u);
    EXPECT_LE(single[label][v], expect * 1.02 + 1e-9);
  }
  // Where fronts meet, one virtual source per face cannot hold both: a vertex whose faces all
  // went to the other source keeps that source's (slightly longer) distance. Rare and small.
  EXPECT_LT(sum / double(m.num_vertices()), 5e-4);
  EXPECT_LT(worst, 0.06);
}

TEST(GeodesicInvariants, LayoutDoesNotChangeTheResult) {
  const TriangleMesh m = curved_mesh();
  SolverOptions plain;
  plain.optimize_layout = false;
  for (Precision p : {Precision::single, Precision::double_precision}) {
    GeodesicOptions o;
    o.precision = p;
    const auto a = GeodesicSolver(m).compute({Source::at_vertex(42)}, o).vertex_distance;
    const auto b = GeodesicSolver(m, plain).compute({Source::at_vertex(42)}, o).vertex_distance;
    double sum = 0;
    for (std::size_t v = 0; v < m.num_vertices(); ++v) sum += relative_error(a[v], b[v]);
    // Same arithmetic on the same faces; only the order of equal-length ties may differ.
    EXPECT_LT(sum / double(m.num_vertices()), p == Precision::single ? 1e-5 : 1e-10);
  }
}

TEST(GeodesicInvariants, SharedMeshGivesTheSameFieldsAndIsNotCopiedWithoutLayout) {
  const auto shared = std::make_shared<const TriangleMesh>(curved_mesh());
  SolverOptions plain;
  plain.optimize_layout = false;
  for (bool layout : {false, true}) {
    SolverOptions so = plain;
    so.optimize_layout = layout;
    const GeodesicSolver copied(*shared, so);
    const GeodesicSolver sharing(shared, so);
    // Without a layout the solver keeps the caller's mesh (one more owner); with one, its own
    // reordered copy.
    EXPECT_EQ(shared.use_count(), layout ? 1 : 2);
    for (Source s : {Source::at_vertex(42), Source::in_face(17, {0.2, 0.3, 0.5})}) {
      EXPECT_EQ(copied.compute({s}).vertex_distance, sharing.compute({s}).vertex_distance);
      // Two queries: the first builds its starting state, the second copies the kept records.
      EXPECT_EQ(sharing.compute({s}).vertex_distance, copied.compute({s}).vertex_distance);
    }
    std::vector<bool> seen(shared->num_faces(), false);
    for (Index f = 0; f < shared->num_faces(); ++f) {
      const Index r = sharing.face_memory_rank(f);
      ASSERT_LT(r, shared->num_faces());
      EXPECT_FALSE(seen[r]) << "face_memory_rank is not a permutation";
      seen[r] = true;
      if (!layout) EXPECT_EQ(r, f);
    }
  }
  EXPECT_THROW(GeodesicSolver(std::shared_ptr<const TriangleMesh>()), InvalidInput);
}

// A solver that takes the mesh (laid out in place, or kept as it is) answers as one that copies
// it, and release_mesh() gives the mesh back in the caller's order, bit for bit.
TEST(GeodesicInvariants, ATakenMeshIsGivenBackInItsOrder) {
  const TriangleMesh m = curved_mesh();
  for (int mode = 0; mode < 3; ++mode) {
    SCOPED_TRACE(mode);
    SolverOptions so;
    so.optimize_layout = mode > 0;
    so.spatial_layout = mode == 2;
    const GeodesicSolver copying(m, so);
    TriangleMesh mine = m;
    GeodesicSolver taking(std::move(mine), so);
    for (Source s : {Source::at_vertex(3), Source::in_face(40, {0.6, 0.2, 0.2})}) {
      const GeodesicResult a = copying.compute({s}), b = taking.compute({s});
      EXPECT_EQ(a.vertex_distance, b.vertex_distance);
      EXPECT_EQ(a.vertex_source, b.vertex_source);
    }
    const TriangleMesh back = std::move(taking).release_mesh();
    EXPECT_EQ(back.positions, m.positions);
    EXPECT_EQ(back.triangles, m.triangles);
    EXPECT_THROW(std::move(taking).release_mesh(), InvalidInput);
  }
  // A shared mesh is copied back; the caller's stays as it was.
  const auto shared = std::make_shared<const TriangleMesh>(m);
  GeodesicSolver sharing(shared);
  const TriangleMesh back = std::move(sharing).release_mesh();
  EXPECT_EQ(back.positions, m.positions);
  EXPECT_EQ(shared->triangles, m.triangles);
}

TEST(GeodesicInvariants, PreparationOnTwoThreadsGivesTheSameSolver) {
  const TriangleMesh m = curved_mesh();
  SolverOptions one, two;
  one.threads = 1;
  two.threads = 2;   // forced: the mesh is below the automatic size
  const GeodesicSolver a(m, one), b(m, two);
  EXPECT_EQ(a.intrinsic_flips(), b.intrinsic_flips());
  for (Source s : {Source::at_vertex(3), Source::in_face(40, {0.6, 0.2, 0.2})}) {
    const GeodesicResult ra = a.compute({s}), rb = b.compute({s});
    EXPECT_EQ(ra.vertex_distance, rb.vertex_distance);
    EXPECT_EQ(ra.vertex_source, rb.vertex_source);
  }
  EXPECT_GT(b.timings().vertex_analysis, 0.0);
  EXPECT_GT(b.timings().delaunay, 0.0);
}

// Label correcting converges to (nearly) the same fix point in any order, whatever the step:
// also below the keys' rounding (f = 1e-300, or 1e-9 in single precision far out), which left
// the speed limiter's limit where it was, so that once postponing it deferred the same entries
// for ever (gsp-geodesic --step 1e-300 hung); the limit now moves past the round's base.
TEST(GeodesicInvariants, StrategiesAgree) {
  const TriangleMesh m = curved_mesh();
  const GeodesicSolver solver(m);
  GeodesicOptions pq;
  pq.strategy = Strategy::priority_queue;
  const auto ref = solver.compute({Source::at_vertex(7)}, pq).vertex_distance;
  for (Strategy s : {Strategy::speed_limiter, Strategy::speed_limiter_postpone, Strategy::static_postpone, Strategy::dynamic_postpone,
                     Strategy::hybrid_postpone, Strategy::bfs}) {
    for (double f : {1.0, 1e-9, 1e-300}) {
      for (Precision p : {Precision::single, Precision::double_precision}) {
        GeodesicOptions o;
        o.strategy = s;
        o.f = f, o.f0 = f, o.f1 = 0.1 * f;
        o.precision = p;
        const auto d = solver.compute({Source::at_vertex(7)}, o).vertex_distance;
        double sum = 0;
        for (std::size_t v = 0; v < m.num_vertices(); ++v) sum += relative_error(d[v], ref[v]);
        EXPECT_LT(sum / double(m.num_vertices()), 2e-3) << "strategy " << int(s) << " f " << f;
      }
    }
  }
}

TEST(GeodesicInvariants, DisconnectedPartsAreInfinityAndNothingIsNaN) {
  TriangleMesh m = icosphere(2);
  const TriangleMesh other = icosphere(1);
  const Index offset = Index(m.num_vertices());
  for (Vec3 p : other.positions) m.positions.push_back(p + Vec3{5, 0, 0});
  for (Triangle t : other.triangles) m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  m.positions.push_back({9, 9, 9});   // an isolated vertex
  const auto r = geodesic_distances(m, {Source::at_vertex(0)});
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    ASSERT_FALSE(std::isnan(r.vertex_distance[v]));
    if (v < offset) EXPECT_TRUE(std::isfinite(r.vertex_distance[v]));
    else EXPECT_TRUE(std::isinf(r.vertex_distance[v])) << v;
  }
}

TEST(GeodesicInvariants, FlippedFacesGiveTheSameDistances) {
  TriangleMesh m = icosphere(3);
  TriangleMesh flipped = m;
  for (std::size_t f = 0; f < flipped.num_faces(); f += 3) std::swap(flipped.triangles[f][1], flipped.triangles[f][2]);
  const auto a = geodesic_distances(m, {Source::at_vertex(5)}).vertex_distance;
  const auto b = geodesic_distances(flipped, {Source::at_vertex(5)}).vertex_distance;
  // Same geometry, same arithmetic, but flipping swaps each face's next/prev halfedges and so
  // the processing order; which of two near-equal candidates a face keeps depends on that
  // order (the same happens when only the heap's tie-breaking changes): ~0.05% on average.
  double sum = 0, worst = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const double e = relative_error(b[v], a[v]);
    sum += e, worst = std::max(worst, e);
  }
  EXPECT_LT(sum / double(m.num_vertices()), 2e-3);
  EXPECT_LT(worst, 0.01);
}

TEST(GeodesicInvariants, NonManifoldEdgesAndVerticesAreCrossed) {
  // Book: three pages on one spine; from a page corner every other page corner is reached
  // over the spine.
  const TriangleMesh book_mesh = book();
  const auto r = geodesic_distances(book_mesh, {Source::at_vertex(2)});
  for (double d : r.vertex_distance) EXPECT_TRUE(std::isfinite(d));
  // Bow-tie: two triangles meeting at one vertex; the far triangle is reached through it.
  const TriangleMesh tie = bowtie();
  const auto t = geodesic_distances(tie, {Source::at_vertex(1)});
  for (std::size_t v = 0; v < tie.num_vertices(); ++v) {
    ASSERT_TRUE(std::isfinite(t.vertex_distance[v])) << v;
    // Every path runs through the shared vertex 0: d(v) = d(1, 0) + |0 - v| on the far side.
    if (v == 3 || v == 4)
      EXPECT_NEAR(t.vertex_distance[v], distance(tie.positions[1], tie.positions[0]) +
                                            distance(tie.positions[0], tie.positions[v]), 1e-5);
  }
}

TEST(GeodesicInvariants, DegenerateFacesNeverProduceNaN) {
  TriangleMesh m = grid(6);
  const Index n = Index(m.num_vertices());
  m.positions.push_back(m.positions[10]);                 // a duplicate of vertex 10
  m.triangles.push_back({10, 11, n});                     // zero-length edge 10 - n
  m.triangles.push_back({10, 10, 11});                    // repeated index
  m.triangles.push_back({0, 1, 2});                       // collinear: zero area
  m.triangles.push_back({n, 11, 17});
  const auto r = geodesic_distances(m, {Source::at_vertex(0)});
  for (double d : r.vertex_distance) {
    ASSERT_FALSE(std::isnan(d));
    EXPECT_TRUE(std::isfinite(d));
  }
  EXPECT_NEAR(r.vertex_distance[n], r.vertex_distance[10], 1e-5);
}

TEST(GeodesicInvariants, BadSourcesAreRejected) {
  const TriangleMesh m = grid(3);
  EXPECT_THROW(geodesic_distances(m, {Source::at_vertex(99)}), InvalidInput);
  EXPECT_THROW(geodesic_distances(m, {Source::in_face(99, {1, 0, 0})}), InvalidInput);
  EXPECT_THROW(geodesic_distances(m, {Source::in_face(0, {0.5, 0.7, 0})}), InvalidInput);
  EXPECT_THROW(geodesic_distances(m, {Source::at_vertex(0, -1.0)}), InvalidInput);
  TriangleMesh bad = m;
  bad.positions[3].x = std::nan("");
  EXPECT_THROW(GeodesicSolver{bad}, InvalidInput);
}

}  // namespace
}  // namespace gsp::test
