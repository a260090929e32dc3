// gsp::cvt::detect_features: creases by dihedral angle, boundaries, corners and curves, on
// shapes whose features are known (a box, a folded plate, a square, a tube).
#include "helpers/mesh_builders.hpp"

#include <gsp/cvt/features.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace gsp;

// The box [0,a]x[0,b]x[0,c] as 12 triangles, outward.
TriangleMesh box(double a, double b, double c) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.positions.push_back({(i & 1) * a, ((i >> 1) & 1) * b, ((i >> 2) & 1) * c});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({Index(q[0]), Index(q[1]), Index(q[2])});
    m.triangles.push_back({Index(q[0]), Index(q[2]), Index(q[3])});
  }
  return m;
}

// Two unit squares (4 triangles) meeting along the y axis, the second one turned up by
// `fold` degrees.
TriangleMesh folded_plate(double fold) {
  const double r = fold * M_PI / 180;
  TriangleMesh m;
  m.positions = {{-1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {-1, 1, 0}, {std::cos(r), 0, std::sin(r)}, {std::cos(r), 1, std::sin(r)}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
  return m;
}

TEST(CvtFeatures, BoxHasTwelveCreasesEightCornersTwelveCurves) {
  const cvt::Features f = cvt::detect_features(box(1, 2, 3));
  EXPECT_EQ(f.edges.size(), 12u);   // the 6 face diagonals are flat
  EXPECT_EQ(f.corners.size(), 8u);
  ASSERT_EQ(f.curves.size(), 12u);
  for (const auto& c : f.curves) EXPECT_EQ(c.size(), 2u);

  // Split 1-to-4: every crease is two edges, the curves run corner to corner through the midpoint.
  const cvt::Features g = cvt::detect_features(midpoint_subdivide(box(1, 2, 3)));
  EXPECT_EQ(g.edges.size(), 24u);
  EXPECT_EQ(g.corners.size(), 8u);
  ASSERT_EQ(g.curves.size(), 12u);
  for (const auto& c : g.curves) {
    ASSERT_EQ(c.size(), 3u);
    EXPECT_LT(c.front(), 8u);   // corners are the box's own vertices
    EXPECT_LT(c.back(), 8u);
    EXPECT_GE(c[1], 8u);        // the midpoint
  }
}

TEST(CvtFeatures, DihedralThreshold) {
  cvt::FeatureOptions o;
  o.boundary = false;
  EXPECT_EQ(cvt::detect_features(folded_plate(30), o).edges.size(), 0u);   // 30 < 40 degrees
  const cvt::Features f = cvt::detect_features(folded_plate(50), o);
  ASSERT_EQ(f.edges.size(), 1u);
  EXPECT_EQ(f.edges[0], (std::array<Index, 2>{1, 2}));
  EXPECT_EQ(f.corners, (std::vector<Index>{1, 2}));   // a curve's ends are corners
  o.angle = 20;
  EXPECT_EQ(cvt::detect_features(folded_plate(30), o).edges.size(), 1u);
}

TEST(CvtFeatures, BoundaryCornersAndClosedCurves) {
  const cvt::Features sq = cvt::detect_features(test::grid(4));
  EXPECT_EQ(sq.edges.size(), 16u);
  EXPECT_EQ(sq.corners, (std::vector<Index>{0, 4, 20, 24}));
  ASSERT_EQ(sq.curves.size(), 4u);
  for (const auto& c : sq.curves) EXPECT_EQ(c.size(), 5u);
  cvt::FeatureOptions o;
  o.boundary = false;
  EXPECT_TRUE(cvt::detect_features(test::grid(4), o).edges.empty());

  // A tube of 32 segments turns by 11.25 degrees per rim vertex: two closed curves, no corner
  // (its side faces meet at 11.25 degrees too: no crease).
  const cvt::Features tube = cvt::detect_features(test::cylinder(32, 3));
  EXPECT_EQ(tube.edges.size(), 64u);
  EXPECT_TRUE(tube.corners.empty());
  ASSERT_EQ(tube.curves.size(), 2u);
  for (const auto& c : tube.curves) {
    EXPECT_EQ(c.size(), 33u);
    EXPECT_EQ(c.front(), c.back());
  }
}

}  // namespace
