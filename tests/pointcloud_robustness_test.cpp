// Point-cloud geodesics on clouds with known answers (a plane), with duplicates, outliers and
// several components, on the shared point clouds (normals; large coordinate offsets), and the
// API's checks.
#include "helpers/geodesic_fixtures.hpp"
#include "test_data.hpp"

#include <gsp/errors.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/pointcloud/point_cloud_geodesics.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gsp::test {
namespace {

using pointcloud::PointCloudGeodesics;
using pointcloud::PointGeodesicOptions;
using pointcloud::PointMethod;
using pointcloud::PointSource;
using pointcloud::PositionSeeding;

// n x n unit grid in the plane z = 0, each point moved by up to 0.3 in x and y.
std::vector<Vec3> jittered_plane(int n, std::uint64_t seed, Vec3 offset = {}) {
  SplitMix rng{seed};
  std::vector<Vec3> p;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      p.push_back(offset + Vec3{i + 0.6 * (rng.uniform() - 0.5), j + 0.6 * (rng.uniform() - 0.5), 0});
  return p;
}

struct Rel {
  double mean = 0, max = 0;
};
Rel relative_error(const std::vector<double>& d, const std::vector<Vec3>& p, Vec3 s) {
  Rel r;
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double ex = distance(p[i], s);
    if (ex < 1e-9) continue;
    const double e = std::abs(d[i] - ex) / ex;
    r.mean += e;
    r.max = std::max(r.max, e);
    ++n;
  }
  r.mean /= double(n);
  return r;
}

TEST(PointCloudGeodesics, PlaneGivesEuclideanDistances) {
  const auto pts = jittered_plane(60, 11);
  const PointCloudGeodesics solver(pts);
  EXPECT_EQ(solver.stats().components, 1u);
  EXPECT_EQ(solver.stats().normals_estimated, pts.size());
  const Index s = 30 * 60 + 30;
  PointGeodesicOptions graph, dijkstra;
  graph.method = PointMethod::graph_gsp;
  dijkstra.method = PointMethod::dijkstra;
  const auto r = solver.compute({PointSource::at_point(s)});
  EXPECT_EQ(r.distance[s], 0.0);
  const Rel gsp = relative_error(r.distance, pts, pts[s]);
  const Rel links = relative_error(solver.compute({PointSource::at_point(s)}, graph).distance, pts, pts[s]);
  const Rel dij = relative_error(solver.compute({PointSource::at_point(s)}, dijkstra).distance, pts, pts[s]);
  std::printf("plane: MRE point GSP %.2e%% (max %.2e%%), over the links %.4f%% (max %.3f%%), Dijkstra %.3f%% (max %.2f%%)\n",
              100 * gsp.mean, 100 * gsp.max, 100 * links.mean, 100 * links.max, 100 * dij.mean, 100 * dij.max);
  // The local triangles tile the plane (no hole: every point of a triangle reached through
  // triangles) and the core is exact on planar triangulations, up to single precision.
  EXPECT_LT(gsp.max, 1e-5);
  EXPECT_EQ(r.stats.points_reached_over_links, 0u);
  EXPECT_LT(links.mean, 0.005);
  EXPECT_LT(links.max, 0.05);
  EXPECT_LT(links.mean, dij.mean / 4);
}

TEST(PointCloudGeodesics, PositionSourceSeedsItsNeighbours) {
  const auto pts = jittered_plane(40, 12);
  const PointCloudGeodesics solver(pts);
  const Vec3 x{19.37, 20.21, 0};
  PointGeodesicOptions o;
  const Index near = solver.nearest_point(x);
  for (PointMethod m : {PointMethod::gsp, PointMethod::graph_gsp}) {
    o.method = m;
    o.seeding = PositionSeeding::neighbours;
    const auto r = solver.compute({PointSource::at_position(x, 0.5)}, o);
    double mre = 0, max = 0;   // the offset 0.5 comes on top of the Euclidean distance
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double e = std::abs(r.distance[i] - 0.5 - distance(pts[i], x)) / distance(pts[i], x);
      mre += e / double(pts.size());
      max = std::max(max, e);
    }
    if (m == PointMethod::gsp) {
      // The position becomes a source at the closest point of the local triangles: on a plane
      // that is the position itself, and every distance is Euclidean (single precision).
      EXPECT_LT(max, 1e-5);
      EXPECT_NEAR(r.distance[near], 0.5 + distance(pts[near], x), 1e-6);
    } else {
      EXPECT_LT(mre, 0.01);
      EXPECT_NEAR(r.distance[near], 0.5 + distance(pts[near], x), 1e-9);   // seeded exactly
    }
    o.seeding = PositionSeeding::snap;
    const auto snapped = solver.compute({PointSource::at_position(x)}, o);
    EXPECT_EQ(snapped.distance[near], 0.0);
  }
}

TEST(PointCloudGeodesics, TwoSourcesGiveVoronoiLabels) {
  const auto pts = jittered_plane(40, 13);
  const PointCloudGeodesics solver(pts);
  const auto r = solver.compute({PointSource::at_point(5 * 40 + 5), PointSource::at_point(34 * 40 + 34)});
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double d0 = distance(pts[i], pts[5 * 40 + 5]), d1 = distance(pts[i], pts[34 * 40 + 34]);
    if (std::abs(d0 - d1) > 1.0) EXPECT_EQ(r.source[i], d0 < d1 ? 0u : 1u) << i;
  }
}

TEST(PointCloudGeodesics, MaxDistanceStopsThePropagation) {
  const auto pts = jittered_plane(50, 14);
  const PointCloudGeodesics solver(pts);
  PointGeodesicOptions o;
  o.max_distance = 8;
  const Index s = 25 * 50 + 25;
  const auto full = solver.compute({PointSource::at_point(s)});
  const auto r = solver.compute({PointSource::at_point(s)}, o);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (full.distance[i] < 7) EXPECT_DOUBLE_EQ(r.distance[i], full.distance[i]) << i;
    if (std::isfinite(r.distance[i])) EXPECT_LE(r.distance[i], 8.0);
  }
  EXPECT_LT(r.stats.update_steps, full.stats.update_steps / 5);
}

TEST(PointCloudGeodesics, DuplicatesOutliersAndComponents) {
  auto pts = jittered_plane(30, 15);
  const std::size_t plane = pts.size();
  for (Index i = 0; i < 40; ++i) pts.push_back(pts[i * 7]);    // exact duplicates
  for (int i = 0; i < 15; ++i) pts.push_back(pts[100]);       // more copies than k
  pts.push_back({15, 15, 40});                                 // an outlier: its neighbours are far
  for (const Vec3& p : jittered_plane(5, 16, {500, 0, 0})) pts.push_back(p);   // another component
  const PointCloudGeodesics solver(pts);
  const auto& st = solver.stats();
  EXPECT_EQ(st.points, pts.size());
  EXPECT_EQ(st.duplicates, 55u);
  EXPECT_EQ(st.unique_points, pts.size() - 55);
  EXPECT_EQ(st.components, 2u);
  // The outlier and the points of the far cluster's edge have no triangle of their own.
  EXPECT_GE(st.points_without_triangle, 1u);
  EXPECT_EQ(st.triangle_components, 2u);
  for (PointMethod m : {PointMethod::gsp, PointMethod::graph_gsp, PointMethod::dijkstra}) {
    PointGeodesicOptions o;
    o.method = m;
    const auto r = solver.compute({PointSource::at_point(plane + 3)}, o);   // a duplicate of point 21
    if (m == PointMethod::gsp) EXPECT_GE(r.stats.points_reached_over_links, 1u);   // the outlier
    for (std::size_t i = 0; i < pts.size(); ++i) {
      ASSERT_FALSE(std::isnan(r.distance[i])) << i;
      if (i < plane + 56) {
        EXPECT_TRUE(std::isfinite(r.distance[i])) << i;
        EXPECT_EQ(r.source[i], 0u);
      } else {
        EXPECT_EQ(r.distance[i], std::numeric_limits<double>::infinity()) << i;
        EXPECT_EQ(r.source[i], kInvalidIndex);
      }
    }
    EXPECT_EQ(r.distance[21], 0.0);
    for (Index i = 0; i < 40; ++i) EXPECT_EQ(r.distance[plane + i], r.distance[i * 7]);
    EXPECT_GT(r.distance[plane + 55], 39.0);   // the outlier, 40 above the plane
    EXPECT_EQ(r.stats.points_reached, plane + 56);
  }
}

TEST(PointCloudGeodesics, ZeroAndNonFiniteInputNormalsFallBackToPca) {
  auto pts = jittered_plane(10, 17);
  std::vector<Vec3> normals(pts.size(), Vec3{0, 0, 1});
  normals[3] = {0, 0, 0};
  normals[4] = {std::numeric_limits<double>::quiet_NaN(), 0, 1};
  const PointCloudGeodesics solver(pts, normals);
  EXPECT_EQ(solver.stats().normals_from_input, pts.size() - 2);
  EXPECT_EQ(solver.stats().normals_estimated, 2u);
  EXPECT_NEAR(std::abs(solver.normals()[3].z), 1.0, 1e-9);
}

TEST(PointCloudGeodesics, RejectsBadInput) {
  auto pts = jittered_plane(5, 18);
  EXPECT_THROW(PointCloudGeodesics(pts, std::vector<Vec3>(3)), InvalidInput);
  const PointCloudGeodesics solver(pts);
  EXPECT_THROW(solver.compute({PointSource::at_point(25)}), InvalidInput);
  EXPECT_THROW(solver.compute({PointSource::at_position({0, std::nan(""), 0})}), InvalidInput);
  EXPECT_THROW(solver.compute({PointSource::at_point(0, std::numeric_limits<double>::infinity())}), InvalidInput);
  pts[2].x = std::numeric_limits<double>::infinity();
  EXPECT_THROW(PointCloudGeodesics{pts}, InvalidInput);
  const PointCloudGeodesics empty(std::vector<Vec3>{});
  EXPECT_EQ(empty.compute({}).distance.size(), 0u);
  EXPECT_THROW(empty.compute({PointSource::at_position({0, 0, 0})}), InvalidInput);
  EXPECT_EQ(empty.nearest_point({0, 0, 0}), kInvalidIndex);
}

// Every point of the source's graph component gets a finite distance, every other +inf.
void expect_component_reached(const PointCloudGeodesics& solver, Index source) {
  const auto r = solver.compute({PointSource::at_point(source)});
  const auto comp = solver.component_ids();
  std::size_t in_component = 0;
  for (std::size_t i = 0; i < r.distance.size(); ++i) {
    ASSERT_FALSE(std::isnan(r.distance[i]));
    if (comp[i] == comp[source]) {
      ++in_component;
      EXPECT_TRUE(std::isfinite(r.distance[i])) << i;
    } else {
      EXPECT_EQ(r.distance[i], std::numeric_limits<double>::infinity()) << i;
    }
  }
  EXPECT_EQ(r.stats.points_reached, in_component);
}

TEST(PointCloudShared, KittenWithNormals) {
  if (!have_shared_data()) GTEST_SKIP() << "shared meshes not found";
  const TriangleMesh cloud = io::read_mesh(shared_mesh("kitten_points.xyz")).mesh;
  ASSERT_EQ(cloud.num_vertices(), 5210u);   // SOURCES.md
  const PointCloudGeodesics solver(cloud);
  EXPECT_EQ(solver.stats().normals_from_input, solver.stats().unique_points);
  expect_component_reached(solver, 0);
}

TEST(PointCloudShared, B9WithLargeCoordinateOffsets) {
  if (!have_shared_data()) GTEST_SKIP() << "shared meshes not found";
  const TriangleMesh cloud = io::read_mesh(shared_mesh("b9_training_points.ply")).mesh;
  ASSERT_EQ(cloud.num_vertices(), 22300u);   // SOURCES.md
  const PointCloudGeodesics solver(cloud);
  EXPECT_GT(solver.stats().mean_link_length, 0.0);
  std::printf("b9: %zu points, %zu duplicates, %zu components (largest %zu), mean link %.4g\n",
              solver.stats().points, solver.stats().duplicates, solver.stats().components,
              solver.stats().largest_component, solver.stats().mean_link_length);
  expect_component_reached(solver, 0);
  // On the local triangles: a point of a triangle around point 0 is no farther than the
  // triangle's edge (a straight path on the surface), up to the core's single precision.
  const auto on_triangles = solver.compute({PointSource::at_point(0)});
  std::size_t edges = 0;
  for (const Triangle& t : solver.local_triangles())
    for (int c = 0; c < 3; ++c)
      if (t[c] == 0) {
        for (int o = 1; o < 3; ++o) {
          const Index q = t[(c + o) % 3];
          EXPECT_LE(on_triangles.distance[q], distance(cloud.positions[0], cloud.positions[q]) * (1 + 1e-6)) << q;
          ++edges;
        }
      }
  EXPECT_GT(edges, 0u);
  // Neighbouring points over the links: the distance is at most the link (no precision lost to
  // the offsets); with chords as links, since arcs are longer by design (docs/pointcloud.md).
  PointGeodesicOptions chords;
  chords.method = PointMethod::graph_gsp;
  chords.curved_links = false;
  const auto r = solver.compute({PointSource::at_point(0)}, chords);
  const auto& g = solver.graph();
  const Index u0 = solver.unique_index()[0];
  for (Index e = g.begin[u0]; e < g.begin[u0 + 1]; ++e) {
    // graph index -> an input point with that index: the first one mapping to it
    for (std::size_t i = 0; i < cloud.num_vertices(); ++i)
      if (solver.unique_index()[i] == g.neighbour[e]) {
        EXPECT_LE(r.distance[i], g.length[e] * (1 + 1e-9));
        EXPECT_GT(r.distance[i], 0.5 * g.length[e]);
        break;
      }
  }
}

}  // namespace
}  // namespace gsp::test
