// CvtOptions::cone_angle (off by default): spike tips (interior vertices whose angles sum far
// below 360 degrees) get fixed sites, so the remesh has a vertex at each tip instead of cutting it off. On a
// regular tetrahedron (every corner a tip of 180 degrees) and on flat-sided square pyramids.
#include <gsp/closest_point.hpp>
#include <gsp/cvt/cvt.hpp>
#include <gsp/cvt/surface.hpp>
#include <gsp/errors.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

using namespace gsp;

constexpr double kTips = 240;   // the value docs/cvt.md measured (the option is off by default)

TriangleMesh tetrahedron() {
  TriangleMesh m;
  m.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  m.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return m;
}

// A square pyramid of height h over [-1,1]^2 with its base closed: the apex's four face
// angles sum to less than 240 degrees, a base corner's to 90 plus two acute face angles.
TriangleMesh pyramid(double h) {
  TriangleMesh m;
  m.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, h}};
  m.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 2, 1}, {0, 3, 2}};
  return m;
}

double nearest_vertex(const TriangleMesh& m, Vec3 p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Vec3& q : m.positions) best = std::min(best, distance(p, q));
  return best;
}

cvt::SurfaceRemeshResult remesh(const TriangleMesh& m, std::size_t vertices, double cone_angle) {
  cvt::SurfaceRemeshOptions o;
  o.cvt.sites = vertices;
  o.cvt.threads = 1;
  o.cvt.cone_angle = cone_angle;
  return cvt::remesh_surface(m, o);
}

TEST(CvtSpikeTips, TetrahedronCornersAreVertices) {
  const TriangleMesh m = tetrahedron();
  const auto kept = remesh(m, 400, kTips);
  ASSERT_EQ(kept.remeshed(), 1u);
  EXPECT_EQ(kept.cvt_stats.cone_sites, 4u);
  const auto cut = remesh(m, 400, 0);
  ASSERT_EQ(cut.remeshed(), 1u);
  EXPECT_EQ(cut.cvt_stats.cone_sites, 0u);
  for (const Vec3& corner : m.positions) {
    EXPECT_LT(nearest_vertex(kept.mesh, corner), 1e-9);
    // Cut off, a corner lies a good part of a spacing (about 0.25 here) from the remesh.
    EXPECT_GT(nearest_vertex(cut.mesh, corner), 0.03);
  }
}

TEST(CvtSpikeTips, TheApexOfAPyramid) {
  const TriangleMesh m = pyramid(3.0);   // apex: 4 x 35 degrees
  const auto r = remesh(m, 600, kTips);
  ASSERT_EQ(r.remeshed(), 1u);
  EXPECT_GE(r.cvt_stats.cone_sites, 1u);
  EXPECT_LT(nearest_vertex(r.mesh, m.positions[4]), 1e-9);
}

TEST(CvtSpikeTips, NotSharperThanHalfTheAngle) {
  // An apex of 75 degrees (below 240 / 2) is left to the free sites, and the base corners
  // (90 + 2 x 80.7 = 251 degrees) are not tips: no fixed site.
  const auto r = remesh(pyramid(6.0), 600, kTips);
  ASSERT_EQ(r.remeshed(), 1u);
  EXPECT_EQ(r.cvt_stats.cone_sites, 0u);
}

TEST(CvtSpikeTips, AtMostOneSiteInFifty) {
  // 100 sites allow 2 fixed sites: the tetrahedron's 4 tips are cut to its 2 sharpest (all
  // equal: the first two in vertex order).
  const auto r = remesh(tetrahedron(), 100, kTips);
  ASSERT_EQ(r.remeshed(), 1u);
  EXPECT_EQ(r.cvt_stats.cone_sites, 2u);
}

TEST(CvtSpikeTips, AngleOutOfRangeIsRefused) {
  cvt::CvtOptions o;
  o.sites = 100;
  o.cone_angle = 400;
  EXPECT_THROW(cvt::compute_cvt(tetrahedron(), o), InvalidInput);
}

}  // namespace
