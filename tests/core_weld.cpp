// weld_vertices: exact (bit pattern) and tolerant (grid hash) merging, checked against the
// mesh a soup was exploded from and against brute force.
#include <gsp/errors.hpp>
#include <gsp/topology.hpp>
#include <gsp/weld.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "helpers/mesh_builders.hpp"

namespace gsp {
namespace {

TopologyReport report(const TriangleMesh& m) { return analyze_topology(m, build_connectivity(m)); }

TEST(CoreWeld, ExplodedIcosphereWeldsBackToTheSphere) {
  const TriangleMesh sphere = test::icosphere(2);
  const TriangleMesh soup = test::explode(sphere);
  ASSERT_EQ(soup.num_vertices(), 3 * sphere.num_faces());
  EXPECT_EQ(report(soup).components, sphere.num_faces());

  const WeldResult w = weld_vertices(soup);
  EXPECT_EQ(w.mesh.num_vertices(), sphere.num_vertices());
  EXPECT_EQ(w.merged, soup.num_vertices() - sphere.num_vertices());
  EXPECT_EQ(w.mesh.num_faces(), soup.num_faces());
  const TopologyReport r = report(w.mesh);
  EXPECT_EQ(r.components, 1u);
  EXPECT_TRUE(r.is_closed());
  EXPECT_TRUE(r.is_manifold());
  EXPECT_EQ(r.euler_characteristic, 2);
  // Every corner keeps its position.
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(w.mesh.positions[w.mesh.triangles[f][c]], soup.positions[soup.triangles[f][c]]);
}

TEST(CoreWeld, RepresentativeIsTheFirstOccurrence) {
  TriangleMesh m;
  m.positions = {{1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
  m.normals = {{1, 0, 0}, {0, 1, 0}, {9, 9, 9}, {0, 0, 1}, {8, 8, 8}, {7, 7, 7}};
  m.triangles = {{0, 1, 3}, {2, 4, 5}};
  const WeldResult w = weld_vertices(m);
  EXPECT_EQ(w.vertex_map, (std::vector<Index>{0, 1, 0, 2, 1, 0}));
  EXPECT_EQ(w.merged, 3u);
  ASSERT_EQ(w.mesh.num_vertices(), 3u);
  EXPECT_EQ(w.mesh.positions[2], (Vec3{0, 0, 1}));
  ASSERT_EQ(w.mesh.normals.size(), 3u);
  EXPECT_EQ(w.mesh.normals[0], (Vec3{1, 0, 0}));  // the first vertex's normal
  EXPECT_EQ(w.mesh.normals[1], (Vec3{0, 1, 0}));
  // Faces are kept even when welding makes them degenerate.
  EXPECT_EQ(w.mesh.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 1, 0}}));
}

TEST(CoreWeld, SignedZerosAreTheSamePoint) {
  TriangleMesh m;
  m.positions = {{0.0, 1, 2}, {-0.0, 1, 2}, {0.0, -0.0, 0.0}, {-0.0, 0.0, -0.0}};
  EXPECT_EQ(weld_vertices(m).vertex_map, (std::vector<Index>{0, 0, 1, 1}));
}

TEST(CoreWeld, ExactWeldKeepsNearlyEqualPointsApart) {
  TriangleMesh m;
  m.positions = {{1, 1, 1}, {std::nextafter(1.0, 2.0), 1, 1}, {1, 1, 1}};
  const WeldResult w = weld_vertices(m);
  EXPECT_EQ(w.vertex_map, (std::vector<Index>{0, 1, 0}));
  EXPECT_EQ(w.merged, 1u);
}

// The apps' weld (weld_input without a tolerance): identical positions and rounding noise.
// A CAD export writes +-3.5e-15 where 0 was meant; the exploded sphere, with such noise on
// the second copy of every corner, welds back to the sphere; vertices 1e-9 of the diagonal
// apart (as close as distinct ones come on the corpus: ten rounding steps) stay apart.
TEST(CoreWeld, DenoisedWeldMergesRoundingNoiseOnly) {
  const TriangleMesh sphere = test::icosphere(2);
  TriangleMesh soup = test::explode(sphere);
  const BoundingBox box = bounding_box(soup);
  const double diagonal = distance(box.min, box.max);
  ASSERT_GT(diagonal, 1.0);
  std::vector<int> seen(sphere.num_vertices(), 0);
  for (std::size_t f = 0; f < sphere.num_faces(); ++f)
    for (int c = 0; c < 3; ++c) {
      Vec3& p = soup.positions[soup.triangles[f][c]];
      if (seen[sphere.triangles[f][c]]++ % 2 == 1) p = p + Vec3{3.5e-15, -3.5e-15, 1e-14};
    }
  EXPECT_LT(weld_vertices(soup).mesh.num_vertices(), soup.num_vertices());   // the exact weld leaves cracks
  EXPECT_GT(report(weld_vertices(soup).mesh).boundary_loops, 0u);
  const WeldResult w = weld_vertices_denoised(soup);
  EXPECT_EQ(w.mesh.num_vertices(), sphere.num_vertices());
  EXPECT_TRUE(report(w.mesh).is_closed());
  EXPECT_EQ(report(w.mesh).euler_characteristic, 2);
  const WeldResult same = weld_input(soup, 0.0);
  EXPECT_EQ(same.vertex_map, w.vertex_map);

  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 1, 1}, {3.5e-15, 0, -0.0}, {1 + 1e-9 * std::sqrt(3.0), 1, 1}, {1, 1, 1}};
  EXPECT_EQ(weld_vertices_denoised(m).vertex_map, (std::vector<Index>{0, 1, 0, 2, 1}));
  // A tolerance given is the tolerant weld, whatever the noise.
  EXPECT_EQ(weld_input(m, 0.5).vertex_map, weld_vertices(m, 0.5).vertex_map);
  // No extent to take a step from: the exact weld.
  TriangleMesh point;
  point.positions = {{2, 2, 2}, {2, 2, 2}};
  EXPECT_EQ(weld_vertices_denoised(point).vertex_map, (std::vector<Index>{0, 0}));
}

TEST(CoreWeld, ToleranceMergesCloseNeighboursAcrossCells) {
  // Points straddling cell boundaries (cell = tolerance) must still find each other.
  TriangleMesh m;
  const double tol = 0.1;
  m.positions = {{0.0998, 0, 0}, {0.1001, 0, 0}, {-0.0001, 0, 0}, {0.25, 0, 0}, {0.0998, -0.0999, 0.0}};
  const WeldResult w = weld_vertices(m, tol);
  // 1, 2 and 4 are within 0.1 of 0 but in other cells; 3 is 0.15 away.
  EXPECT_EQ(w.vertex_map, (std::vector<Index>{0, 0, 0, 1, 0}));
  EXPECT_EQ(w.mesh.positions[0], m.positions[0]);
}

TEST(CoreWeld, ToleranceGroupsDoNotChain) {
  // 0 -- 0.06 -- 1 -- 0.06 -- 2: 1 joins 0, but 2 is 0.12 from 0 (the representative)
  // and so starts a group of its own; the result is independent of any hashing.
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {0.06, 0, 0}, {0.12, 0, 0}};
  EXPECT_EQ(weld_vertices(m, 0.1).vertex_map, (std::vector<Index>{0, 0, 1}));
}

TEST(CoreWeld, ToleranceAgreesWithBruteForce) {
  // A jittered soup: every representative the grid search picks must be the lowest-index
  // earlier representative within the tolerance, as a quadratic scan finds it.
  TriangleMesh m;
  std::uint64_t state = 12345;
  auto uniform = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  for (int i = 0; i < 3000; ++i) m.positions.push_back({uniform(), uniform(), 0.2 * uniform()});
  const double tol = 0.02;
  const WeldResult w = weld_vertices(m, tol);

  std::vector<Index> rep(m.num_vertices());
  std::vector<Index> reps;
  for (Index i = 0; i < m.num_vertices(); ++i) {
    rep[i] = i;
    for (Index r : reps)
      if (distance(m.positions[r], m.positions[i]) < tol) {
        rep[i] = r;
        break;  // reps are in increasing order
      }
    if (rep[i] == i) reps.push_back(i);
  }
  ASSERT_EQ(w.mesh.num_vertices(), reps.size());
  EXPECT_GT(w.merged, 100u);  // the test exercises merging at all
  for (Index i = 0; i < m.num_vertices(); ++i)
    EXPECT_EQ(w.mesh.positions[w.vertex_map[i]], m.positions[rep[i]]) << i;
}

TEST(CoreWeld, ToleranceWeldsAPerturbedSoup) {
  TriangleMesh soup = test::explode(test::grid(10));
  for (std::size_t i = 0; i < soup.num_vertices(); ++i)
    soup.positions[i].z += 1e-9 * static_cast<double>(i);  // no two corners bit-equal
  EXPECT_EQ(weld_vertices(soup).merged, 0u);
  const WeldResult w = weld_vertices(soup, 1e-5);
  EXPECT_EQ(w.mesh.num_vertices(), 121u);
  const TopologyReport r = report(w.mesh);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.boundary_loops, 1u);
  EXPECT_EQ(r.euler_characteristic, 1);
}

TEST(CoreWeld, UnweldMapsValuesBack) {
  const TriangleMesh soup = test::explode(test::quad());
  const WeldResult w = weld_vertices(soup);
  ASSERT_EQ(w.mesh.num_vertices(), 4u);
  std::vector<double> welded_values(w.mesh.num_vertices());
  for (std::size_t v = 0; v < welded_values.size(); ++v) welded_values[v] = w.mesh.positions[v].x + 10 * w.mesh.positions[v].y;
  const std::vector<double> back = unweld_values(welded_values, w.vertex_map);
  ASSERT_EQ(back.size(), soup.num_vertices());
  for (std::size_t v = 0; v < back.size(); ++v)
    EXPECT_DOUBLE_EQ(back[v], soup.positions[v].x + 10 * soup.positions[v].y);
}

TEST(CoreWeld, EmptyMeshAndBadTolerance) {
  EXPECT_EQ(weld_vertices(TriangleMesh{}).mesh.num_vertices(), 0u);
  EXPECT_THROW(weld_vertices(test::quad(), -1.0), InvalidInput);
  EXPECT_THROW(weld_vertices(test::quad(), std::nan("")), InvalidInput);
  TriangleMesh bad = test::quad();
  bad.triangles[1][2] = 7;
  EXPECT_THROW(weld_vertices(bad), InvalidInput);
}

TEST(CoreWeld, HugeCoordinatesWithATinyToleranceStillWork) {
  // Cell coordinates beyond the int64 range are clamped: correctness must not depend on them.
  TriangleMesh m;
  m.positions = {{1e300, 0, 0}, {1e300, 0, 0}, {-1e300, 5, 0}, {0, 0, 0}};
  const WeldResult w = weld_vertices(m, 1e-9);
  EXPECT_EQ(w.vertex_map, (std::vector<Index>{0, 0, 1, 2}));
}

}  // namespace
}  // namespace gsp
