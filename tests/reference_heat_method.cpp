// The heat method (gsp::reference, CGAL Heat_method_3) against exact geodesics.
#include <gsp/errors.hpp>
#include <gsp/reference/exact_geodesics.hpp>
#include <gsp/reference/heat_method.hpp>

#include "helpers/mesh_builders.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using gsp::Index;
using gsp::TriangleMesh;
using gsp::reference::HeatMethodMode;
using gsp::reference::HeatMethodSolver;

struct Errors {
  double mean_relative = 0, max_relative = 0;
};

// Relative errors over vertices farther than `min_distance` from the source (near the source
// the relative error of any smoothed method is dominated by the source's own smoothing).
Errors compare(const std::vector<double>& approx, const std::vector<double>& exact, double min_distance) {
  Errors e;
  std::size_t n = 0;
  for (std::size_t v = 0; v < exact.size(); ++v) {
    if (!(exact[v] > min_distance)) continue;
    const double r = std::abs(approx[v] - exact[v]) / exact[v];
    e.mean_relative += r;
    e.max_relative = std::max(e.max_relative, r);
    ++n;
  }
  e.mean_relative /= double(n);
  return e;
}

// On a smooth shape with regular triangles the heat method is within a few percent.
// Measured on icosphere(4) (2,562 vertices) from vertex 0: 1.06 % mean and 19 % max relative
// error (the max near the source) for both modes; the icosphere is already Delaunay, so the
// intrinsic retriangulation flips nothing there.
TEST(HeatMethod, CloseToExactOnIcosphere) {
  const TriangleMesh sphere = gsp::test::icosphere(4);
  const auto exact = gsp::reference::exact_geodesic_distances(sphere, {gsp::reference::ExactSource::at_vertex(0)});
  for (HeatMethodMode mode : {HeatMethodMode::direct, HeatMethodMode::intrinsic_delaunay}) {
    HeatMethodSolver heat(sphere, mode);
    const auto d = heat.solve({0});
    ASSERT_EQ(d.size(), sphere.num_vertices());
    EXPECT_NEAR(d[0], 0.0, 1e-9);
    const Errors e = compare(d, exact, 0.05);
    const char* name = mode == HeatMethodMode::direct ? "direct" : "idt";
    EXPECT_LT(e.mean_relative, 0.05) << name;
    EXPECT_LT(e.max_relative, 0.25) << name;
    RecordProperty(std::string(name) + "_mre", std::to_string(e.mean_relative));
    RecordProperty(std::string(name) + "_max", std::to_string(e.max_relative));
  }
}

// Solving twice with different sources reuses the factorisation and gives independent answers.
TEST(HeatMethod, SolveIsRepeatableAndSourceDependent) {
  const TriangleMesh sphere = gsp::test::icosphere(3);
  HeatMethodSolver heat(sphere);
  const auto a1 = heat.solve({0});
  const auto b = heat.solve({5});
  const auto a2 = heat.solve({0});
  for (std::size_t v = 0; v < a1.size(); ++v) EXPECT_DOUBLE_EQ(a1[v], a2[v]);
  EXPECT_NEAR(b[5], 0.0, 1e-9);
  EXPECT_GT(a1[5], 0.5);
  // Two sources: compared with the exact distance to the nearer one.
  const auto both = heat.solve({0, 5});
  const auto exact = gsp::reference::exact_geodesic_distances(
      sphere, {gsp::reference::ExactSource::at_vertex(0), gsp::reference::ExactSource::at_vertex(5)});
  EXPECT_LT(compare(both, exact, 0.1).mean_relative, 0.05);
}

// A flat sheet of obtuse triangles (every other row shifted, long diagonals): the intrinsic
// Delaunay retriangulation flips the long diagonals and is clearly more accurate than the
// direct cotan Laplacian (measured mean relative error 15.6 % direct, 2.0 % intrinsic);
// exact distances are Euclidean here.
TEST(HeatMethod, IntrinsicDelaunayHelpsOnObtuseTriangles) {
  TriangleMesh m;
  const int n = 30;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back({i + 0.45 * (j % 2), 0.5 * j, 0});
  for (Index j = 0; j < Index(n); ++j)
    for (Index i = 0; i < Index(n); ++i) {
      const Index a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      if (j % 2 == 0) {  // next row shifted right: a-c is the long diagonal
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
      } else {  // next row shifted left: b-d is the long diagonal
        m.triangles.push_back({a, b, d});
        m.triangles.push_back({b, c, d});
      }
    }
  const Index source = (n / 2) * (n + 1) + n / 2;
  std::vector<double> euclid(m.num_vertices());
  for (std::size_t v = 0; v < euclid.size(); ++v) euclid[v] = gsp::distance(m.positions[v], m.positions[source]);
  const Errors direct = compare(HeatMethodSolver(m, HeatMethodMode::direct).solve({source}), euclid, 1.0);
  const Errors idt = compare(HeatMethodSolver(m, HeatMethodMode::intrinsic_delaunay).solve({source}), euclid, 1.0);
  RecordProperty("direct_mre", std::to_string(direct.mean_relative));
  RecordProperty("idt_mre", std::to_string(idt.mean_relative));
  EXPECT_LT(idt.mean_relative, 0.05);
  EXPECT_LT(idt.mean_relative, direct.mean_relative);
}

TEST(HeatMethod, ComponentsWithoutSourceAreInfinite) {
  const TriangleMesh s = gsp::test::icosphere(2);
  TriangleMesh m = s;
  const Index offset = Index(m.positions.size());
  for (const auto& p : s.positions) m.positions.push_back(p + gsp::Vec3{5, 0, 0});
  for (const auto& t : s.triangles) m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  m.positions.push_back({9, 9, 9});  // isolated
  HeatMethodSolver heat(m, HeatMethodMode::intrinsic_delaunay);
  EXPECT_EQ(heat.num_components(), 2u);
  const auto d = heat.solve({3});
  const auto alone = HeatMethodSolver(s, HeatMethodMode::intrinsic_delaunay).solve({3});
  for (Index v = 0; v < offset; ++v) EXPECT_NEAR(d[v], alone[v], 1e-9);
  for (Index v = offset; v < m.num_vertices(); ++v) EXPECT_EQ(d[v], std::numeric_limits<double>::infinity());
}

TEST(HeatMethod, RefusesAndRejects) {
  EXPECT_THROW(HeatMethodSolver{gsp::test::book()}, gsp::TopologyError);
  HeatMethodSolver heat(gsp::test::grid(3));
  EXPECT_THROW(heat.solve({}), gsp::InvalidInput);
  EXPECT_THROW(heat.solve({16}), gsp::InvalidInput);
}

}  // namespace
