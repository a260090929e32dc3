// gsp::lines on flat meshes: every unfolding is the plane itself, so the distance to a segment
// source must be the Euclidean distance to the segment (not to sample points of it), for any
// triangulation. Closed forms, several irregular triangulations, 1e-5 relative (double
// precision gives ~1e-12).
#include "lines_support.hpp"

#include <gsp/errors.hpp>
#include <gsp/lines/line_distances.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gsp::test {
namespace {

using lines::LineResult;
using lines::LineSource;

struct Case {
  int n;
  unsigned seed;
};
const Case kCases[] = {{9, 1}, {14, 2}, {21, 3}, {30, 4}};

// Distances and labels against the closed form: min over segments of the 3D point-segment
// distance. Labels are checked where the nearest segment is clear (not a tie).
void expect_closed_form(const TriangleMesh& m, const LineResult& r, const std::vector<std::array<Vec3, 2>>& segs,
                        const std::string& what) {
  ASSERT_EQ(r.vertex_distance.size(), m.num_vertices());
  double worst = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    double best = INFINITY, second = INFINITY;
    Index label = kInvalidIndex;
    for (std::size_t s = 0; s < segs.size(); ++s) {
      const double d = point_segment_distance(m.positions[v], segs[s][0], segs[s][1]);
      if (d < best) second = best, best = d, label = Index(s);
      else second = std::min(second, d);
    }
    const double got = r.vertex_distance[v];
    worst = std::max(worst, std::abs(got - best) / std::max(best, 1e-3));
    ASSERT_NEAR(got, best, 1e-5 * best + 1e-9) << what << ": vertex " << v;
    if (second - best > 1e-6) ASSERT_EQ(r.vertex_segment[v], label) << what << ": vertex " << v;
  }
  ::testing::Test::RecordProperty(what + "_max_rel_error", std::to_string(worst));
}

TEST(LinesPlane, OneSegmentIsTheDistanceToTheSegment) {
  const Plane pl;
  for (const Case& c : kCases) {
    const TriangleMesh m = jittered_square(c.n, c.seed);
    const Vec3 a = pl.at(0.23, 0.41), b = pl.at(0.71, 0.58);
    const LineSource src = lines::polyline_source(m, {{a, b}});
    EXPECT_EQ(src.num_segments(), 1u);
    EXPECT_GT(src.pieces.size(), 2u);   // the segment crosses several faces
    EXPECT_LT(src.max_snap_distance, 1e-12);
    const LineResult r = lines::line_distances(m, src);
    expect_closed_form(m, r, {{a, b}}, "segment n=" + std::to_string(c.n));
  }
}

TEST(LinesPlane, OpenPolylineWithConcaveCornersIsTheMinimumOverItsSegments) {
  const Plane pl;
  const std::vector<Vec3> zigzag{pl.at(0.1, 0.2), pl.at(0.35, 0.75), pl.at(0.5, 0.3), pl.at(0.8, 0.7),
                                 pl.at(0.9, 0.15)};
  std::vector<std::array<Vec3, 2>> segs;
  for (std::size_t i = 0; i + 1 < zigzag.size(); ++i) segs.push_back({zigzag[i], zigzag[i + 1]});
  for (const Case& c : kCases) {
    const TriangleMesh m = jittered_square(c.n, c.seed + 10);
    const LineSource src = lines::polyline_source(m, {zigzag});
    EXPECT_EQ(src.num_segments(), 4u);
    const LineResult r = lines::line_distances(m, src);
    expect_closed_form(m, r, segs, "zigzag n=" + std::to_string(c.n));
  }
}

TEST(LinesPlane, ClosedPolylineRepeatsItsFirstPoint) {
  const Plane pl;
  const std::vector<Vec3> loop{pl.at(0.3, 0.3), pl.at(0.7, 0.25), pl.at(0.6, 0.8), pl.at(0.3, 0.3)};
  std::vector<std::array<Vec3, 2>> segs;
  for (std::size_t i = 0; i + 1 < loop.size(); ++i) segs.push_back({loop[i], loop[i + 1]});
  for (const Case& c : kCases) {
    const TriangleMesh m = jittered_square(c.n, c.seed + 20);
    const LineResult r = lines::line_distances(m, lines::polyline_source(m, {loop}));
    expect_closed_form(m, r, segs, "loop n=" + std::to_string(c.n));
  }
}

TEST(LinesPlane, TwoPolylinesNumberTheirSegmentsInOrder) {
  const Plane pl;
  const TriangleMesh m = jittered_square(17, 5);
  const std::vector<Vec3> first{pl.at(0.1, 0.1), pl.at(0.3, 0.2)}, second{pl.at(0.8, 0.9), pl.at(0.9, 0.6),
                                                                         pl.at(0.6, 0.5)};
  const LineSource src = lines::polyline_source(m, {first, second});
  ASSERT_EQ(src.num_segments(), 3u);
  const LineResult r = lines::line_distances(m, src);
  expect_closed_form(m, r, {{first[0], first[1]}, {second[0], second[1]}, {second[1], second[2]}}, "two");
}

TEST(LinesPlane, ChainOfMeshEdges) {
  for (const Case& c : kCases) {
    const TriangleMesh m = jittered_square(c.n, c.seed + 30);
    // Row j = n/2 of the grid: consecutive vertices are always joined by an edge, and the
    // jitter makes the chain a zigzag.
    std::vector<Index> chain;
    const int j = c.n / 2;
    for (int i = 1; i < c.n; ++i) chain.push_back(Index(i + j * (c.n + 1)));
    const LineSource src = lines::vertex_chain_source(m, chain, false);
    std::vector<std::array<Vec3, 2>> segs;
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) segs.push_back({m.positions[chain[i]], m.positions[chain[i + 1]]});
    ASSERT_EQ(src.num_segments(), segs.size());
    const LineResult r = lines::line_distances(m, src);
    for (Index v : chain) EXPECT_EQ(r.vertex_distance[v], 0.0);
    expect_closed_form(m, r, segs, "chain n=" + std::to_string(c.n));
  }
}

TEST(LinesPlane, BoundaryOfTheSquareIsTheDistanceToItsSides) {
  const Plane pl;
  for (const Case& c : kCases) {
    const TriangleMesh m = jittered_square(c.n, c.seed + 40);
    const LineSource src = lines::boundary_source(m);
    EXPECT_EQ(src.num_segments(), std::size_t(4 * c.n));
    const LineResult r = lines::line_distances(m, src);
    for (std::size_t v = 0; v < m.num_vertices(); ++v) {
      const Vec3 d = m.positions[v] - pl.origin;
      const double x = dot(d, pl.u), y = dot(d, pl.v);
      const double expected = std::max(0.0, std::min({x, 1 - x, y, 1 - y}));
      ASSERT_NEAR(r.vertex_distance[v], expected, 1e-5 * expected + 1e-9) << "n=" << c.n << " vertex " << v;
    }
  }
}

TEST(LinesPlane, MaxDistanceLeavesFartherVerticesUnreached) {
  const Plane pl;
  const TriangleMesh m = jittered_square(20, 7);
  const Vec3 a = pl.at(0.4, 0.5), b = pl.at(0.6, 0.5);
  lines::LineOptions o;
  o.max_distance = 0.2;
  const LineResult r = lines::line_distances(m, lines::polyline_source(m, {{a, b}}), o);
  std::size_t inside = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const double d = point_segment_distance(m.positions[v], a, b);
    if (d <= 0.2 - 1e-9) {
      ++inside;
      ASSERT_NEAR(r.vertex_distance[v], d, 1e-5 * d + 1e-9) << v;
    } else if (d > 0.2 + 1e-9) {
      ASSERT_TRUE(std::isinf(r.vertex_distance[v])) << v;
      ASSERT_EQ(r.vertex_segment[v], kInvalidIndex) << v;
    }
  }
  EXPECT_GT(inside, 20u);
  EXPECT_LT(r.stats.faces_reached, m.num_faces());
}

}  // namespace
}  // namespace gsp::test
