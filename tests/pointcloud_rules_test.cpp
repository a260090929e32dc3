// The graph propagation's rules (PointMethod::graph_gsp, docs/pointcloud.md): links unfolded
// with their arc length (chords cut below a curved surface), and steep and gap links (across
// thin gaps) left out unless nothing else reaches a point; and the same gaps on the local
// triangles (PointMethod::gsp), whose one-rings leave steep links out.
#include "helpers/geodesic_fixtures.hpp"

#include <gsp/errors.hpp>
#include <gsp/mesh.hpp>
#include <gsp/pointcloud/point_cloud_geodesics.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gsp::test {
namespace {

using pointcloud::PointCloudGeodesics;
using pointcloud::PointGeodesicOptions;
using pointcloud::PointMethod;
using pointcloud::PointSource;

PointGeodesicOptions over_links() {
  PointGeodesicOptions o;
  o.method = PointMethod::graph_gsp;
  return o;
}

constexpr double kPi = 3.14159265358979323846;

// A cylinder of radius 1 sampled coarsely around (n points per ring, rings 0.3 apart, every
// other ring turned by half a step): developable, so unfolding is exact and the only error
// left is the chords' (each link cuts 2 sin(t/2) for the arc t).
std::vector<Vec3> cylinder(int n, int rings) {
  std::vector<Vec3> p;
  for (int r = 0; r < rings; ++r)
    for (int i = 0; i < n; ++i) {
      const double a = 2 * kPi * (i + 0.5 * (r % 2)) / n;
      p.push_back({std::cos(a), std::sin(a), 0.3 * r});
    }
  return p;
}

// Mean signed and absolute relative error against the cylinder's geodesics from point s, over
// the points of s's own ring (less than 0.8 of the way round): their geodesics run along the
// ring, through the ring's points, so every step is straight and only the link lengths count.
std::pair<double, double> cylinder_errors(const std::vector<double>& d, const std::vector<Vec3>& p, Index s) {
  double sum = 0, abs_sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double da = std::acos(std::clamp(p[i].x * p[s].x + p[i].y * p[s].y, -1.0, 1.0));
    const double exact = std::hypot(da, p[i].z - p[s].z);
    if (exact < 1e-9 || da > 0.8 * kPi || p[i].z != p[s].z) continue;
    sum += (d[i] - exact) / exact;
    abs_sum += std::abs(d[i] - exact) / exact;
    ++n;
  }
  return {sum / double(n), abs_sum / double(n)};
}

TEST(PointCloudRules, ArcLengthLinksRemoveTheChordsBias) {
  const auto pts = cylinder(24, 40);   // 15 degrees per link around: chords 0.29% short
  const PointCloudGeodesics solver(pts);
  const Index s = 20 * 24;
  PointGeodesicOptions chords = over_links();
  chords.curved_links = false;
  const auto [chord_signed, chord_mre] = cylinder_errors(solver.compute({PointSource::at_point(s)}, chords).distance, pts, s);
  const auto [arc_signed, arc_mre] =
      cylinder_errors(solver.compute({PointSource::at_point(s)}, over_links()).distance, pts, s);
  std::printf("cylinder, 24 x 40 points: chords signed %+.4f%% (MRE %.4f%%), arcs signed %+.4f%% (MRE %.4f%%)\n",
              100 * chord_signed, 100 * chord_mre, 100 * arc_signed, 100 * arc_mre);
  const double deficit = 1 - std::sin(kPi / 24) / (kPi / 24);   // chord / arc for 15 degrees
  EXPECT_NEAR(chord_signed, -deficit, 0.1 * deficit);   // chords are shorter than the arcs they cut
  EXPECT_NEAR(arc_signed, 0.0, 0.1 * deficit);
  EXPECT_LT(arc_mre, chord_mre / 5);
}

// A sheet folded over: two 75 x 30 grids (spacing 0.4) at z = +-0.4, joined along x = 29.6
// by a half cylinder of radius 0.4, with their normals. Points along the sheets' borders
// have the point across the gap (0.8, slope 1) and ones at 0.89 (slope 0.89) among their 10
// nearest, so the k-NN graph links the sheets straight across, and every such link is steep.
TriangleMesh folded_sheet(bool with_fold) {
  TriangleMesh m;
  for (int y = 0; y < 30; ++y) {
    for (double z : {0.4, -0.4})
      for (int x = 0; x < 75; ++x) {
        m.positions.push_back({0.4 * x, 0.4 * y, z});
        m.normals.push_back({0, 0, z > 0 ? 1.0 : -1.0});
      }
    if (with_fold)
      for (int a = 1; a < 4; ++a) {   // 3 points inside the fold, about 0.31 apart
        const double t = kPi / 2 - a * kPi / 4;
        m.positions.push_back({29.6 + 0.4 * std::cos(t), 0.4 * y, 0.4 * std::sin(t)});
        m.normals.push_back({std::cos(t), 0, std::sin(t)});
      }
  }
  return m;
}

TEST(PointCloudRules, SteepLinksDoNotShortcutAcrossAGap) {
  const TriangleMesh m = folded_sheet(true);
  const PointCloudGeodesics solver(m);
  const Index source = Index(15 * 153 + 12);   // (4.8, 6, +0.4)
  const Index below = source + 75;             // (4.8, 6, -0.4)
  const auto r = solver.compute({PointSource::at_point(source)}, over_links());
  const auto t = solver.compute({PointSource::at_point(source)});
  const double around = 24.8 + kPi * 0.4 + 24.8;
  std::printf("folded sheet: to the point below %.3f over the links, %.3f on the triangles (around the fold %.3f, "
              "through the gap 0.8)\n", r.distance[below], t.distance[below], around);
  EXPECT_NEAR(r.distance[below], around, 0.02 * around);
  EXPECT_EQ(r.stats.steep_links_used, 0u);
  EXPECT_NEAR(t.distance[below], around, 0.02 * around);
  EXPECT_EQ(t.stats.points_reached_over_links, 0u);
  // Every link used: the graph's links across the gap carry the front straight through.
  PointGeodesicOptions all_links = over_links();
  all_links.steep_link_slope = 1;
  all_links.gap_link_slope = 1;
  EXPECT_LT(solver.compute({PointSource::at_point(source)}, all_links).distance[below], 2.0);
}

// The same fold with the sheets 0.24 apart and the lower one shifted by half a spacing in y
// (a slit narrower than the sampling, like camelhead's lips): the k-NN links across are
// diagonal, 0.31 long at slope 0.77 and 0.51 long at slope 0.47 at both ends, so none is
// steep at one end (0.8), every one is steep at both (the gap rule, 0.35).
TriangleMesh staggered_fold() {
  TriangleMesh m;
  for (int y = 0; y < 30; ++y) {
    for (int side = 0; side < 2; ++side)
      for (int x = 0; x < 75; ++x) {
        m.positions.push_back({0.4 * x, 0.4 * y + 0.2 * side, side ? -0.12 : 0.12});
        m.normals.push_back({0, 0, side ? -1.0 : 1.0});
      }
    for (int side = 0; side < 2; ++side)
      for (int a = 1; a < 6; ++a) {   // 5 points inside the fold (radius 0.12), 30 degrees apart
        const double t = kPi / 2 - a * kPi / 6;
        m.positions.push_back({29.6 + 0.12 * std::cos(t), 0.4 * y + 0.2 * side, 0.12 * std::sin(t)});
        m.normals.push_back({std::cos(t), 0, std::sin(t)});
      }
  }
  return m;
}

TEST(PointCloudRules, GapLinksDoNotShortcutAcrossANarrowSlit) {
  const TriangleMesh m = staggered_fold();
  const PointCloudGeodesics solver(m);
  // Source 2 from the fold, 6 from the nearest border (where longer links cross at lower
  // slopes): around the fold is the shortest way to the other sheet.
  const Index source = Index(15 * 160 + 69);   // (27.6, 6, +0.12)
  const Index below = source + 75;             // (27.6, 6.2, -0.12)
  const double around = std::hypot(2 + kPi * 0.12 + 2, 0.2);
  const auto r = solver.compute({PointSource::at_point(source)}, over_links());
  PointGeodesicOptions steep_only = over_links();
  steep_only.gap_link_slope = 1;
  const double without = solver.compute({PointSource::at_point(source)}, steep_only).distance[below];
  std::printf("staggered fold: to the point below %.4f (around the fold %.4f; steep rule only %.4f)\n",
              r.distance[below], around, without);
  EXPECT_NEAR(r.distance[below], around, 0.02 * around);
  EXPECT_EQ(r.stats.steep_links_used, 0u);
  EXPECT_LT(without, 1.0);   // the steep rule alone lets the front through the slit
  PointGeodesicOptions bad = over_links();
  bad.gap_link_slope = -0.1;
  EXPECT_THROW(solver.compute({PointSource::at_point(source)}, bad), InvalidInput);
}

TEST(PointCloudRules, PointsOnlySteepLinksReachAreStillReached) {
  const TriangleMesh m = folded_sheet(false);   // two sheets, linked only across the gap
  const PointCloudGeodesics solver(m);
  EXPECT_EQ(solver.stats().components, 1u);
  const Index source = Index(15 * 150 + 12);
  const auto r = solver.compute({PointSource::at_point(source)}, over_links());
  EXPECT_GT(r.stats.steep_links_used, 0u);
  EXPECT_EQ(r.stats.points_reached, m.num_vertices());
  // On the triangles: two sheets, two pieces (no triangle uses a steep link). The lower one is
  // reached over the links, by shortest paths along them, then the core's propagation runs
  // from its nearest entry point; here the source's own 10 nearest include the point below
  // (one of five at 0.8), so that point is 0.8 away, as for Dijkstra on the same links.
  EXPECT_EQ(solver.stats().triangle_components, 2u);
  const auto t = solver.compute({PointSource::at_point(source)});
  PointGeodesicOptions dijkstra;
  dijkstra.method = PointMethod::dijkstra;
  const auto d = solver.compute({PointSource::at_point(source)}, dijkstra);
  EXPECT_EQ(t.stats.points_reached, m.num_vertices());
  EXPECT_GT(t.stats.points_reached_over_links, 0u);
  EXPECT_NEAR(t.distance[source + 75], d.distance[source + 75], 1e-6);
  for (Index q = 0; q < m.num_vertices(); ++q) EXPECT_LE(t.distance[q], d.distance[q] * (1 + 1e-6)) << q;
  // The graph propagation enters the bottom sheet over the first steep link it finds (in point
  // order: the border at y = 0): 6 to the border, 0.8 across, 6 back. No point below is nearer
  // than its Euclidean distance.
  EXPECT_NEAR(r.distance[source + 75], 12.8, 0.02 * 12.8);
  for (Index x = 0; x < 75; ++x) {
    const Index q = Index(15 * 150 + 75 + x);
    EXPECT_GE(r.distance[q], distance(m.positions[q], m.positions[source]) - 1e-9) << x;
    EXPECT_GE(t.distance[q], distance(m.positions[q], m.positions[source]) * (1 - 1e-6)) << x;
  }
  PointGeodesicOptions bad = over_links();
  bad.steep_link_slope = -1;
  EXPECT_THROW(solver.compute({PointSource::at_point(source)}, bad), InvalidInput);
}

}  // namespace
}  // namespace gsp::test
