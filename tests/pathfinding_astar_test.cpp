// Goal-directed queries (GeodesicOptions::targets, goal_directed): the same target distances
// as a full propagation, from a fraction of the faces.
#include "helpers/geodesic_fixtures.hpp"
#include "helpers/mesh_builders.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace gsp::test {
namespace {

TriangleMesh fertility() {
  return io::read_mesh(std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off").mesh;
}

// Targets at about 10% of the largest distance from the source: A* expands at most 20% of the
// faces a full run reaches and gives the target the same distance within 0.1% on average.
TEST(GoalDirected, NearTargetsCostAFractionOfTheMesh) {
  const TriangleMesh m = fertility();
  const GeodesicSolver solver(m);
  SplitMix rng{11};
  double worst_fraction = 0, diff_sum = 0;
  int pairs = 0;
  for (int trial = 0; trial < 5; ++trial) {
    const Index s = Index(rng.next() % m.num_vertices());
    GeodesicOptions full;
    full.want_face_sources = true;
    const GeodesicResult all = solver.compute({Source::at_vertex(s)}, full);
    double far = 0;
    for (double d : all.vertex_distance) far = std::max(far, d);
    // The vertex nearest to 10% of that, in a random direction: the first one in random order.
    Index t = kInvalidIndex;
    for (int k = 0; k < 100000 && t == kInvalidIndex; ++k) {
      const Index v = Index(rng.next() % m.num_vertices());
      if (std::abs(all.vertex_distance[v] - 0.1 * far) < 0.01 * far) t = v;
    }
    ASSERT_NE(t, kInvalidIndex);
    for (bool astar : {true, false}) {
      GeodesicOptions o = full;
      o.targets = {t};
      o.goal_directed = astar;
      const GeodesicResult r = solver.compute({Source::at_vertex(s)}, o);
      // A* settles faces in heap order, the full run in the speed limiter's: GSP's
      // label-correcting fix point depends a little on the order (docs/gsp-core.md), so a
      // single pair can differ by more than 0.1% (over 120 pairs: mean 0.025%, max 0.82%;
      // on the worst of these five, source 76, A* is the closer to exact: +0.12% vs +0.27%).
      const double diff = std::abs(r.vertex_distance[t] - all.vertex_distance[t]) / all.vertex_distance[t];
      EXPECT_LT(diff, 1e-2) << "source " << s << " target " << t << (astar ? " A*" : " settle");
      diff_sum += diff, ++pairs;
      const double fraction = double(r.stats.faces_reached) / double(all.stats.faces_reached);
      EXPECT_LT(fraction, astar ? 0.2 : 0.5) << "source " << s << " target " << t;
      if (astar) worst_fraction = std::max(worst_fraction, fraction);
      std::printf("source %u target %u (%.1f): %s reached %.1f%% of the faces, %llu update steps (full %llu)\n", s,
                  t, all.vertex_distance[t], astar ? "A*    " : "settle", 100 * fraction,
                  (unsigned long long)r.stats.update_steps, (unsigned long long)all.stats.update_steps);
    }
  }
  std::printf("A*: at most %.1f%% of the faces; mean difference from the full run %.3f%%\n", 100 * worst_fraction,
              100 * diff_sum / pairs);
  EXPECT_LT(diff_sum / pairs, 1e-3);
}

// Several far targets: every one gets the distance of a full run in the same (heap) order —
// GSP's result depends slightly on the order faces are expanded in (far targets differ by up to
// 0.8% between the heap and the default speed limiter on fertility), stopping early must not
// change it: settling in heap order matches within 0.1%. A* expands faces in yet another order;
// for these far targets its distances are up to 0.75% longer (measured), bounded here by 1%.
// A* expands fewer faces than plain settling. Vertex-only runs (intrinsic Delaunay
// faces) take targets too.
TEST(GoalDirected, SeveralTargetsAndBothTriangulations) {
  const TriangleMesh m = fertility();
  const GeodesicSolver solver(m);
  for (bool face_sources : {true, false}) {
    GeodesicOptions full;
    full.want_face_sources = face_sources;
    full.strategy = Strategy::priority_queue;
    const GeodesicResult all = solver.compute({Source::at_vertex(100)}, full);
    GeodesicOptions o = full;
    o.targets = {200, 300, 100};   // the source itself may be a target
    o.goal_directed = true;
    const GeodesicResult a = solver.compute({Source::at_vertex(100)}, o);
    o.goal_directed = false;
    const GeodesicResult b = solver.compute({Source::at_vertex(100)}, o);
    for (Index t : o.targets) {
      EXPECT_NEAR(a.vertex_distance[t], all.vertex_distance[t], 1e-2 * all.vertex_distance[t] + 1e-12);
      EXPECT_NEAR(b.vertex_distance[t], all.vertex_distance[t], 1e-3 * all.vertex_distance[t] + 1e-12);
    }
    EXPECT_EQ(a.vertex_distance[100], 0.0);
    EXPECT_LE(a.stats.faces_reached, b.stats.faces_reached);
    EXPECT_LT(b.stats.faces_reached, all.stats.faces_reached);
  }
}

TEST(GoalDirected, UnreachableTargetAndBadOptions) {
  TriangleMesh m = grid(3);
  const TriangleMesh g = m;
  const Index off = Index(m.num_vertices());
  for (Vec3 p : g.positions) m.positions.push_back(p + Vec3{10, 0, 0});
  for (Triangle t : g.triangles) m.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
  GeodesicOptions o;
  o.targets = {off + 2};
  o.goal_directed = true;
  const GeodesicResult r = geodesic_distances(m, {Source::at_vertex(0)}, o);
  EXPECT_TRUE(std::isinf(r.vertex_distance[off + 2]));
  EXPECT_NEAR(r.vertex_distance[15], std::sqrt(18.0), 1e-5);   // its own component is complete
  GeodesicOptions bad;
  bad.goal_directed = true;
  EXPECT_THROW(geodesic_distances(m, {Source::at_vertex(0)}, bad), InvalidInput);
  bad.targets = {Index(m.num_vertices())};
  EXPECT_THROW(geodesic_distances(m, {Source::at_vertex(0)}, bad), InvalidInput);
}

}  // namespace
}  // namespace gsp::test
