// The working mesh's Delaunay flips inside planes (extensions/cvt/src/working_flips.hpp) and the
// walk that maps points back to the input (input_walk.hpp): a CAD-like prism whose caps are
// fans of slivers (every cap triangle has the polygon's first vertex as a corner, as CAD
// exports write them) is flipped into Delaunay triangles of the same plane and nothing across
// its creases moves; the CVT's sites on it map back to points of the input's faces; and its
// remesh keeps the prism's topology, which it did not without the flips.
#include "flips.hpp"
#include "input_walk.hpp"
#include "working_flips.hpp"

#include <gsp/cvt/components.hpp>
#include <gsp/cvt/cvt.hpp>
#include <gsp/cvt/remesh.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace gsp;

// A prism over an n-gon on an ellipse (10 by 4: its vertices are not on one circle, where every
// triangulation would be Delaunay), height h; both caps fans from vertex 0.
TriangleMesh fan_prism(int n, double h) {
  TriangleMesh m;
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n;
      m.positions.push_back({10 * std::cos(a), 4 * std::sin(a), z * h});
    }
  const Index top = Index(n);
  for (int i = 1; i + 1 < n; ++i) {
    m.triangles.push_back({0, Index(i + 1), Index(i)});                      // bottom, facing -z
    m.triangles.push_back({top, top + Index(i), top + Index(i + 1)});        // top, facing +z
  }
  for (int i = 0; i < n; ++i) {
    const Index a = Index(i), b = Index((i + 1) % n);
    m.triangles.push_back({a, b, top + b});
    m.triangles.push_back({a, top + b, top + a});
  }
  return m;
}

double area(const TriangleMesh& m) {
  double s = 0;
  for (const Triangle& t : m.triangles)
    s += 0.5 * norm(cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]));
  return s;
}

Vec3 point_of(const TriangleMesh& m, Index f, const std::array<double, 3>& b) {
  const Triangle& t = m.triangles[f];
  return b[0] * m.positions[t[0]] + b[1] * m.positions[t[1]] + b[2] * m.positions[t[2]];
}

TEST(CvtPlanarFlips, CapsBecomeDelaunayAndTheSidesStay) {
  TriangleMesh m = fan_prism(60, 4);
  const TriangleMesh before = m;
  std::vector<bool> changed(m.num_faces(), false);
  const std::size_t flips = cvt::detail::delaunay_flips_in_planes(m, 1e-9, 1000000, changed);
  EXPECT_GT(flips, 0u);
  EXPECT_NEAR(area(m), area(before), 1e-9 * area(before));
  ASSERT_EQ(m.num_faces(), before.num_faces());
  for (Index f = 0; f < m.num_faces(); ++f) {
    // Side faces (a vertex on each cap) are never flipped: the crease is not a plane.
    const Triangle& t = before.triangles[f];
    const bool side = !(t[0] < 60 && t[1] < 60 && t[2] < 60) && !(t[0] >= 60 && t[1] >= 60 && t[2] >= 60);
    if (side) EXPECT_FALSE(changed[f]) << f;
    // Every face still faces the way its cap does.
    const Triangle& u = m.triangles[f];
    const Vec3 n = cross(m.positions[u[1]] - m.positions[u[0]], m.positions[u[2]] - m.positions[u[0]]);
    if (!side) EXPECT_GT(std::abs(n.z), 0) << f;
    if (!side) EXPECT_EQ(n.z > 0, m.positions[u[0]].z > 0) << f;
  }
  // Delaunay inside the caps: the two angles opposite each cap edge sum to at most pi.
  std::size_t checked = 0;
  for (Index f = 0; f < m.num_faces(); ++f)
    for (Index g = f + 1; g < m.num_faces(); ++g)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const Triangle &t = m.triangles[f], &u = m.triangles[g];
          const Index a = t[i], b = t[(i + 1) % 3];
          if (!(u[j] == b && u[(j + 1) % 3] == a)) continue;
          const Vec3 pa = m.positions[a], pb = m.positions[b];
          const Vec3 pc = m.positions[t[(i + 2) % 3]], pd = m.positions[u[(j + 2) % 3]];
          if (std::abs(pc.z - pd.z) > 0) continue;   // across the crease
          auto angle = [](Vec3 o, Vec3 x, Vec3 y) { return std::acos(dot(x - o, y - o) / (norm(x - o) * norm(y - o))); };
          EXPECT_LE(angle(pc, pa, pb) + angle(pd, pb, pa), M_PI + 1e-9);
          ++checked;
        }
  EXPECT_GT(checked, 100u);
}

TEST(CvtPlanarFlips, NothingFlipsAcrossABend) {
  // Two triangles folded along their shared edge by 1e-3 of its length: off one plane by more
  // than the height allowed, so the edge stays even though it is not Delaunay.
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {10, 0, 0}, {5, 0.5, 0}, {5, -0.5, 0.01}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}};
  std::vector<bool> changed(2, false);
  EXPECT_EQ(cvt::detail::delaunay_flips_in_planes(m, 1e-3, 100, changed), 0u);
  EXPECT_EQ(cvt::detail::delaunay_flips_in_planes(m, 0.1, 100, changed), 1u);
}

TEST(CvtPlanarFlips, TheWalkFindsTheFaceHoldingAPoint) {
  const TriangleMesh m = fan_prism(80, 4);
  const cvt::detail::InputWalk walk(m);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  for (int k = 0; k < 200; ++k) {
    const Vec3 x{u(rng), u(rng), 4};
    // Start at the top cap's first face: the point is several slivers away.
    const auto [face, b] = walk.locate(1, x, true);
    for (double c : b) EXPECT_GE(c, 0);
    EXPECT_NEAR(b[0] + b[1] + b[2], 1, 1e-12);
    EXPECT_LT(distance(point_of(m, face, b), x), 1e-9) << k;
  }
}

TEST(CvtPlanarFlips, SitesMapBackAndTheRemeshKeepsTheTopology) {
  const TriangleMesh m = fan_prism(120, 3);
  cvt::CvtOptions o;
  o.sites = 600;
  o.threads = 1;
  const cvt::CvtResult with = cvt::compute_cvt(m, o);
  EXPECT_GT(with.stats.planar_flips, 0u);
  for (const cvt::Site& s : with.sites) {
    ASSERT_LT(s.point.element, m.num_faces());
    for (double c : s.point.barycentric) EXPECT_GE(c, -1e-9);
    EXPECT_LT(distance(point_of(m, s.point.element, s.point.barycentric), s.position), 1e-7);
  }
  std::string why;
  EXPECT_TRUE(cvt::same_topology_per_component(m, cvt::restricted_delaunay(with).mesh, &why)) << why;

  o.planar_flips = false;
  const cvt::CvtResult without = cvt::compute_cvt(m, o);
  EXPECT_EQ(without.stats.planar_flips, 0u);
  // Without the flips the caps' regions come out of GSP on slivers: more sites added to
  // repair them than with.
  EXPECT_GT(without.stats.sites_added, with.stats.sites_added);
}

}  // namespace
