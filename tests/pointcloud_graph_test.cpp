// The k-NN / radius neighbour graph against brute force, its symmetry, and its components.
#include "helpers/geodesic_fixtures.hpp"

#include <gsp/errors.hpp>
#include <gsp/pointcloud/neighbour_graph.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace gsp::test {
namespace {

using pointcloud::build_neighbour_graph;
using pointcloud::connected_components;
using pointcloud::Neighbourhood;
using pointcloud::NeighbourOptions;

std::vector<Vec3> random_points(std::size_t n, std::uint64_t seed) {
  SplitMix rng{seed};
  std::vector<Vec3> p(n);
  for (Vec3& x : p) x = {rng.uniform(), rng.uniform(), rng.uniform()};
  return p;
}

std::set<Index> links_of(const pointcloud::NeighbourGraph& g, Index i) {
  return {g.neighbour.begin() + g.begin[i], g.neighbour.begin() + g.begin[i + 1]};
}

TEST(PointCloudGraph, KnnMatchesBruteForceAndIsSymmetric) {
  const auto pts = random_points(500, 3);
  NeighbourOptions o;
  o.k = 7;
  const auto g = build_neighbour_graph(pts, o);
  ASSERT_EQ(g.num_points(), pts.size());
  for (Index i = 0; i < pts.size(); ++i) {
    std::vector<Index> order(pts.size());
    for (Index j = 0; j < pts.size(); ++j) order[j] = j;
    std::sort(order.begin(), order.end(), [&](Index a, Index b) { return distance(pts[a], pts[i]) < distance(pts[b], pts[i]); });
    const std::set<Index> mine = links_of(g, i);
    for (int a = 1; a <= 7; ++a) EXPECT_TRUE(mine.count(order[a])) << i;   // order[0] is i itself
    EXPECT_GE(mine.size(), 7u);
    EXPECT_FALSE(mine.count(i));
    for (Index j : mine) EXPECT_TRUE(links_of(g, j).count(i)) << "asymmetric link " << i << "-" << j;
  }
  for (std::size_t e = 0; e < g.neighbour.size(); ++e) EXPECT_GE(g.length[e], 0.0);
}

TEST(PointCloudGraph, RadiusMatchesBruteForce) {
  const auto pts = random_points(300, 4);
  NeighbourOptions o;
  o.rule = Neighbourhood::radius;
  o.radius = 0.15;
  const auto g = build_neighbour_graph(pts, o);
  for (Index i = 0; i < pts.size(); ++i) {
    std::set<Index> brute;
    for (Index j = 0; j < pts.size(); ++j)
      if (j != i && distance(pts[i], pts[j]) < 0.15) brute.insert(j);
    EXPECT_EQ(links_of(g, i), brute) << i;
  }
}

TEST(PointCloudGraph, TwoDistantClustersAreTwoComponents) {
  auto pts = random_points(100, 5);
  for (const Vec3& p : random_points(50, 6)) pts.push_back(p + Vec3{100, 0, 0});
  const auto c = connected_components(build_neighbour_graph(pts));
  EXPECT_EQ(c.count, 2u);
  EXPECT_EQ(c.id[0], 0u);
  EXPECT_EQ(c.id[120], 1u);
}

TEST(PointCloudGraph, RejectsBadInput) {
  NeighbourOptions o;
  o.k = 0;
  EXPECT_THROW(build_neighbour_graph(random_points(10, 1), o), InvalidInput);
  o = {};
  o.rule = Neighbourhood::radius;
  EXPECT_THROW(build_neighbour_graph(random_points(10, 1), o), InvalidInput);
  std::vector<Vec3> bad = random_points(10, 1);
  bad[3].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(build_neighbour_graph(bad), InvalidInput);
  EXPECT_EQ(build_neighbour_graph({}).num_points(), 0u);
}

}  // namespace
}  // namespace gsp::test
