// The local triangles of point-cloud GSP (PointMethod::gsp, docs/pointcloud.md): what they
// cover on clouds with known answers (a plane, a sphere), and the API around them.
#include "helpers/geodesic_fixtures.hpp"

#include <gsp/errors.hpp>
#include <gsp/pointcloud/point_cloud_geodesics.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>

namespace gsp::test {
namespace {

using pointcloud::PointCloudGeodesics;
using pointcloud::PointCloudOptions;
using pointcloud::PointGeodesicOptions;
using pointcloud::PointMethod;
using pointcloud::PointSource;
using gsp::Strategy;

constexpr double kPi = 3.14159265358979323846;

// Points on the unit sphere by the Fibonacci spiral (nearly uniform, no two equal).
std::vector<Vec3> fibonacci_sphere(int n) {
  std::vector<Vec3> p;
  const double golden = kPi * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z);
    p.push_back({r * std::cos(golden * i), r * std::sin(golden * i), z});
  }
  return p;
}

TEST(PointCloudTriangles, TileAJitteredPlane) {
  SplitMix rng{21};
  std::vector<Vec3> pts;
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i) pts.push_back({i + 0.6 * (rng.uniform() - 0.5), j + 0.6 * (rng.uniform() - 0.5), 0});
  const PointCloudGeodesics solver(pts);
  const auto& st = solver.stats();
  const auto tris = solver.local_triangles();
  EXPECT_EQ(st.local_triangles, tris.size());
  EXPECT_EQ(st.triangle_components, 1u);
  EXPECT_EQ(st.points_without_triangle, 0u);
  // A Delaunay triangulation of n points in a square has about 2n triangles; the union of the
  // one-rings adds the other diagonal where four points are nearly co-circular.
  EXPECT_GT(tris.size(), 2 * pts.size() * 9 / 10);
  EXPECT_LT(tris.size(), 3 * pts.size());
  double area = 0;
  for (const Triangle& t : tris) {
    for (Index v : t) ASSERT_LT(v, pts.size());
    EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    area += 0.5 * norm(cross(pts[t[1]] - pts[t[0]], pts[t[2]] - pts[t[0]]));
  }
  // Overlaps only where one-rings disagree: the area is close to the convex hull's (~39^2).
  EXPECT_GT(area, 0.95 * 39 * 39);
  EXPECT_LT(area, 1.25 * 39 * 39);
}

TEST(PointCloudTriangles, SphereGreatCircles) {
  const auto pts = fibonacci_sphere(3000);
  const PointCloudGeodesics solver(pts);
  EXPECT_EQ(solver.stats().triangle_components, 1u);
  EXPECT_EQ(solver.stats().points_without_triangle, 0u);
  PointGeodesicOptions links, dijkstra;
  links.method = PointMethod::graph_gsp;
  dijkstra.method = PointMethod::dijkstra;
  const Index s = 1234;
  const auto err = [&](const std::vector<double>& d) {
    double sum = 0, worst = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const double ex = std::acos(std::clamp(dot(pts[i], pts[s]), -1.0, 1.0));
      if (ex < 0.2 || ex > kPi - 0.2) continue;   // away from the source and its antipode
      const double e = (d[i] - ex) / ex;
      sum += std::abs(e);
      worst = std::max(worst, std::abs(e));
      ++n;
    }
    return std::pair{sum / double(n), worst};
  };
  const auto [tri_mre, tri_max] = err(solver.compute({PointSource::at_point(s)}).distance);
  const auto [link_mre, link_max] = err(solver.compute({PointSource::at_point(s)}, links).distance);
  const auto [dij_mre, dij_max] = err(solver.compute({PointSource::at_point(s)}, dijkstra).distance);
  std::printf("sphere, 3000 points: MRE triangles %.3f%% (max %.3f%%), links %.3f%% (max %.3f%%), Dijkstra %.3f%%\n",
              100 * tri_mre, 100 * tri_max, 100 * link_mre, 100 * link_max, 100 * dij_mre);
  // Inscribed triangles are shorter than the sphere by about (edge / radius)^2 / 24 (0.2% at
  // this spacing); paths run on them, never through the ball.
  EXPECT_LT(tri_mre, 0.005);
  EXPECT_LT(tri_max, 0.02);
  EXPECT_LT(tri_mre, dij_mre / 5);
}

TEST(PointCloudTriangles, EveryQueueStrategyOfTheCore) {
  const auto pts = fibonacci_sphere(1500);
  const PointCloudGeodesics solver(pts);
  const auto base = solver.compute({PointSource::at_point(3)});
  for (Strategy s : {Strategy::static_postpone, Strategy::dynamic_postpone, Strategy::hybrid_postpone, Strategy::bfs,
                     Strategy::priority_queue}) {
    PointGeodesicOptions o;
    o.strategy = s;
    const auto r = solver.compute({PointSource::at_point(3)}, o);
    double worst = 0, sum = 0;
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (base.distance[i] > 0) {
        const double e = std::abs(r.distance[i] - base.distance[i]) / base.distance[i];
        worst = std::max(worst, e);
        sum += e;
      }
    // Label correcting converges to nearly the same fix point in any order, as on meshes
    // (GeodesicInvariants.StrategiesAgree); single points differ by up to 2% on this soup.
    EXPECT_LT(sum / double(pts.size()), 2e-3) << int(s);
    EXPECT_LT(worst, 0.03) << int(s);
  }
  PointGeodesicOptions links;
  links.method = PointMethod::graph_gsp;
  links.strategy = Strategy::priority_queue;
  EXPECT_THROW(solver.compute({PointSource::at_point(3)}, links), InvalidInput);
  PointGeodesicOptions bad;
  bad.f = 0;
  EXPECT_THROW(solver.compute({PointSource::at_point(3)}, bad), InvalidInput);
}

TEST(PointCloudTriangles, ConcurrentQueriesMatchSequentialOnes) {
  const auto pts = fibonacci_sphere(2000);
  const PointCloudGeodesics solver(pts);
  std::vector<std::vector<double>> alone(4), together(4);
  for (Index s = 0; s < 4; ++s) alone[s] = solver.compute({PointSource::at_point(s * 400)}).distance;
  std::vector<std::thread> threads;
  for (Index s = 0; s < 4; ++s)
    threads.emplace_back([&, s] { together[s] = solver.compute({PointSource::at_point(s * 400)}).distance; });
  for (std::thread& t : threads) t.join();
  for (Index s = 0; s < 4; ++s) EXPECT_EQ(together[s], alone[s]) << s;   // the same arithmetic
}

TEST(PointCloudTriangles, BuiltOnlyWhenAsked) {
  const auto pts = fibonacci_sphere(500);
  PointCloudOptions o;
  o.local_triangles = false;
  const PointCloudGeodesics graph_only(pts, {}, o);
  EXPECT_EQ(graph_only.stats().local_triangles, 0u);
  EXPECT_TRUE(graph_only.local_triangles().empty());
  EXPECT_THROW(graph_only.compute({PointSource::at_point(0)}), InvalidInput);
  PointGeodesicOptions links;
  links.method = PointMethod::graph_gsp;
  const auto r = graph_only.compute({PointSource::at_point(0)}, links);
  EXPECT_EQ(r.stats.points_reached, pts.size());
}

TEST(PointCloudTriangles, IndicesAreInputPointsAndDuplicatesShareTheirs) {
  auto pts = fibonacci_sphere(400);
  pts.push_back(pts[7]);   // a duplicate: the triangles name point 7, never 400
  const PointCloudGeodesics solver(pts);
  bool seven = false;
  for (const Triangle& t : solver.local_triangles())
    for (Index v : t) {
      EXPECT_NE(v, 400u);
      seven = seven || v == 7;
    }
  EXPECT_TRUE(seven);
  const auto r = solver.compute({PointSource::at_point(400)});
  EXPECT_EQ(r.distance[7], 0.0);
  EXPECT_EQ(r.distance[400], 0.0);
}

TEST(PointCloudTriangles, HubListedByEveryPointStillTriangulates) {
  // 60 pairs of points 1 from the centre in spiral directions, 0.01 apart: every point's 10
  // nearest include the centre, whose graph degree is then 120 (its one-ring keeps the nearest
  // 40 candidates). Every point is reached, over triangles or links.
  std::vector<Vec3> pts{{0, 0, 0}};
  for (const Vec3& d : fibonacci_sphere(60)) {
    pts.push_back(d);
    pts.push_back(1.01 * d);
  }
  const PointCloudGeodesics solver(pts);
  const auto r = solver.compute({PointSource::at_point(0)});
  EXPECT_EQ(r.stats.points_reached, pts.size());
  for (std::size_t i = 1; i < pts.size(); ++i) EXPECT_GE(r.distance[i], norm(pts[i]) * (1 - 1e-6)) << i;
}

}  // namespace
}  // namespace gsp::test
