// The intrinsic Delaunay flips under the solver: they must keep the surface (areas, angle sums,
// vertices) and end with every flippable edge Delaunay; and they must pay off on CAD slivers.
#include "helpers/geodesic_fixtures.hpp"

#include "intrinsic_delaunay.hpp"   // internal (libgsp/src)

#include <gsp/connectivity.hpp>
#include <gsp/geodesics.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gsp::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

double angle(double a, double b, double opposite) {
  return std::acos(std::clamp((a * a + b * b - opposite * opposite) / (2 * a * b), -1.0, 1.0));
}

double area(double a, double b, double c) {
  const double s = (a + b + c) / 2;
  return std::sqrt(std::max(0.0, s * (s - a) * (s - b) * (s - c)));
}

// The way CAD exports triangulate a polygon: a fan from one boundary vertex of a disk with n
// boundary points, every triangle a sliver towards the far side (far from Delaunay), lifted
// onto a gentle bump (height 0 gives the planar polygon).
TriangleMesh sliver_fan(int n, double height) {
  TriangleMesh m;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * kPi * i / n;
    const double x = std::cos(a), y = std::sin(a);
    m.positions.push_back({x, y, height * (1 - x * x - y * y + 0.3 * x)});
  }
  for (int i = 1; i + 1 < n; ++i) m.triangles.push_back({0, Index(i), Index(i + 1)});
  return m;
}

detail::IntrinsicTriangulation from_mesh(const TriangleMesh& m) {
  detail::IntrinsicTriangulation t;
  t.triangles = m.triangles;
  const Connectivity c = build_connectivity(m);
  t.ring = c.radial_next;
  t.skipped.assign(m.num_faces(), false);
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    for (int i = 0; i < 3; ++i)
      t.length.push_back(distance(m.positions[m.triangles[f][i]], m.positions[m.triangles[f][(i + 1) % 3]]));
  return t;
}

TEST(IntrinsicDelaunay, FlipsKeepTheSurfaceAndEndDelaunay) {
  for (const TriangleMesh& m : {sliver_fan(40, 0.3), jittered_grid(10, 0.25, 4), icosphere(2)}) {
    detail::IntrinsicTriangulation t = from_mesh(m);
    std::vector<double> angle_sum_before(m.num_vertices(), 0), angle_sum_after(m.num_vertices(), 0);
    double area_before = 0, area_after = 0;
    auto accumulate = [&](const detail::IntrinsicTriangulation& x, std::vector<double>& sums, double& total) {
      for (std::size_t f = 0; f < x.triangles.size(); ++f) {
        const double l[3] = {x.length[3 * f], x.length[3 * f + 1], x.length[3 * f + 2]};
        total += area(l[0], l[1], l[2]);
        for (int i = 0; i < 3; ++i) sums[x.triangles[f][i]] += angle(l[i], l[(i + 2) % 3], l[(i + 1) % 3]);
      }
    };
    accumulate(t, angle_sum_before, area_before);
    detail::make_intrinsic_delaunay(t, 100000);
    accumulate(t, angle_sum_after, area_after);
    EXPECT_NEAR(area_after, area_before, 1e-9 * area_before);
    for (std::size_t v = 0; v < m.num_vertices(); ++v) EXPECT_NEAR(angle_sum_after[v], angle_sum_before[v], 1e-9);
    // Twins agree on their length, and every interior edge is Delaunay now.
    for (Index h = 0; h < Index(t.length.size()); ++h) {
      const Index g = t.ring[h];
      if (g == h) continue;
      ASSERT_EQ(t.ring[g], h);
      EXPECT_NEAR(t.length[g], t.length[h], 1e-12);
      const double a1 = angle(t.length[next_halfedge(h)], t.length[prev_halfedge(h)], t.length[h]);
      const double a2 = angle(t.length[next_halfedge(g)], t.length[prev_halfedge(g)], t.length[g]);
      EXPECT_LE(a1 + a2, kPi + 1e-9);
    }
  }
}

TEST(IntrinsicDelaunay, SolverUsesItForVertexSourcesAndStaysExactOnPlanes) {
  const TriangleMesh fan = sliver_fan(60, 0.3);
  const GeodesicSolver solver(fan);
  EXPECT_GT(solver.intrinsic_flips(), 0u);
  // A flat fan of slivers: distances stay exact through the flips.
  const TriangleMesh flat = sliver_fan(60, 0.0);
  const auto r = geodesic_distances(flat, {Source::at_vertex(7)});
  for (std::size_t v = 0; v < flat.num_vertices(); ++v)
    EXPECT_NEAR(r.vertex_distance[v], distance(flat.positions[v], flat.positions[7]), 1e-5);
  // Per-face virtual sources need the input faces: the solver uses them then, and the two
  // runs agree closely.
  GeodesicOptions with_faces;
  with_faces.want_face_sources = true;
  const auto a = solver.compute({Source::at_vertex(3)});
  const auto b = solver.compute({Source::at_vertex(3)}, with_faces);
  ASSERT_EQ(b.face_sources.size(), fan.num_faces());
  for (std::size_t v = 0; v < fan.num_vertices(); ++v) EXPECT_NEAR(a.vertex_distance[v], b.vertex_distance[v], 0.05);
  for (std::size_t f = 0; f < fan.num_faces(); ++f) EXPECT_LT(a.face_source[f], 1u);
}

}  // namespace
}  // namespace gsp::test
