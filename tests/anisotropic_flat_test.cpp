// gsp::anisotropic on flat meshes: a constant metric makes the plane another flat plane (a
// linear image of it), so GSP must reproduce the closed form sqrt(e^T M e) at every vertex,
// on regular and irregular triangulations, with and without the intrinsic Delaunay flips.
#include "helpers/geodesic_fixtures.hpp"

#include <gsp/anisotropic/metric_field.hpp>
#include <gsp/anisotropic/metric_sources.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using namespace gsp;
using gsp::anisotropic::MetricField;
using gsp::anisotropic::SymmetricTensor;

struct Case {
  std::string name;
  TriangleMesh mesh;
};

std::vector<Case> planar_meshes() {
  return {{"regular grid", test::grid(12)},
          {"jittered grid seed 1", test::jittered_grid(12, 0.25, 1)},
          {"jittered grid seed 7", test::jittered_grid(14, 0.2, 7)}};
}

// Every vertex against the closed form `exact(dx, dy)`; returns the largest relative error.
template <class Exact>
double max_error(const TriangleMesh& mesh, const MetricField& field, Index source, Exact exact,
                 bool delaunay, Precision precision) {
  SolverOptions so;
  so.intrinsic_delaunay = delaunay;
  GeodesicOptions go;
  go.precision = precision;
  const GeodesicResult r = anisotropic::geodesic_distances(mesh, field, {Source::at_vertex(source)}, go, so);
  double worst = 0;
  const Vec3 s = mesh.positions[source];
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    const double want = exact(mesh.positions[v].x - s.x, mesh.positions[v].y - s.y);
    if (v == source) {
      EXPECT_EQ(r.vertex_distance[v], 0.0);
      continue;
    }
    worst = std::max(worst, test::relative_error(r.vertex_distance[v], want));
  }
  return worst;
}

TEST(AnisotropicFlat, ConstantDiagonalMetricIsExactEverywhere) {
  for (const Case& c : planar_meshes())
    for (auto [a, b] : {std::pair{4.0, 1.0}, std::pair{0.25, 2.25}})
      for (bool delaunay : {true, false})
        for (Precision p : {Precision::single, Precision::double_precision})
          for (Index source : {Index(0), Index(c.mesh.num_vertices() / 2)}) {
            const auto exact = [a = a, b = b](double dx, double dy) { return std::sqrt(a * dx * dx + b * dy * dy); };
            const double err = max_error(c.mesh, MetricField::constant(SymmetricTensor::diagonal(a, b, 1)), source,
                                         exact, delaunay, p);
            EXPECT_LE(err, 1e-4) << c.name << " diag(" << a << ", " << b << ") delaunay " << delaunay
                                 << " double " << (p == Precision::double_precision) << " source " << source;
          }
}

TEST(AnisotropicFlat, RotatedDirectionFieldIsExactEverywhere) {
  const double pi = std::acos(-1.0);
  for (const Case& c : planar_meshes())
    for (double angle : {pi / 6, 2.0})
      for (double ratio : {3.0, 0.5})
        for (bool delaunay : {true, false}) {
          const Vec3 d{std::cos(angle), std::sin(angle), 0};
          // Given unnormalised and tilted out of the plane: the metric projects and normalises.
          const MetricField field = anisotropic::direction_metric(c.mesh, Vec3{2 * d.x, 2 * d.y, 0.7}, ratio);
          const auto exact = [&](double dx, double dy) {
            const double along = dx * d.x + dy * d.y, across = -dx * d.y + dy * d.x;
            return std::sqrt(ratio * ratio * along * along + across * across);
          };
          const Index source = Index(c.mesh.num_vertices() / 2);
          EXPECT_LE(max_error(c.mesh, field, source, exact, delaunay, Precision::single), 1e-4)
              << c.name << " angle " << angle << " ratio " << ratio << " delaunay " << delaunay;
        }
}

TEST(AnisotropicFlat, LayoutDoesNotChangeTheMetric) {
  // Per-face lengths must follow their faces through the cache reordering: with a metric
  // that differs per face (a direction field on a bent strip) the reordered and the input
  // layouts agree.
  const test::BentStrip s = test::bent_strip(24, 10, 2.0, 2.5, 0.15);
  const MetricField field = anisotropic::direction_metric(s.mesh, {0, 0, 1}, 2.5);
  SolverOptions reordered, as_is;
  as_is.optimize_layout = false;
  GeodesicOptions go;
  go.precision = Precision::double_precision;
  const auto a = anisotropic::geodesic_distances(s.mesh, field, {Source::at_vertex(5)}, go, reordered);
  const auto b = anisotropic::geodesic_distances(s.mesh, field, {Source::at_vertex(5)}, go, as_is);
  for (std::size_t v = 0; v < s.mesh.num_vertices(); ++v) EXPECT_NEAR(a.vertex_distance[v], b.vertex_distance[v], 1e-9);
  // The strip unrolls to a rectangle and the direction (the cylinder's axis) stays the unrolled
  // y axis, so the closed form holds here too.
  for (std::size_t v = 0; v < s.mesh.num_vertices(); ++v) {
    const double dx = s.unrolled[v][0] - s.unrolled[5][0], dy = s.unrolled[v][1] - s.unrolled[5][1];
    const double want = std::sqrt(dx * dx + 2.5 * 2.5 * dy * dy);
    if (v != 5) EXPECT_LE(test::relative_error(a.vertex_distance[v], want), 1e-4) << v;
  }
}

TEST(AnisotropicFlat, FacePointSourceUsesTheMetric) {
  // A source inside a face: its corner distances are metric lengths from the point.
  const TriangleMesh m = test::grid(8);
  const auto field = MetricField::constant(SymmetricTensor::diagonal(9, 1, 1));
  const Index f = 2 * (4 * 8 + 4);   // face {a, b, c} of the square at (4, 4)
  const std::array<double, 3> bary{0.2, 0.5, 0.3};
  const auto r = anisotropic::geodesic_distances(m, field, {Source::in_face(f, bary)});
  Vec3 p{0, 0, 0};
  for (int i = 0; i < 3; ++i) p = p + bary[i] * m.positions[m.triangles[f][i]];
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const double dx = m.positions[v].x - p.x, dy = m.positions[v].y - p.y;
    EXPECT_LE(test::relative_error(r.vertex_distance[v], std::sqrt(9 * dx * dx + dy * dy)), 1e-4) << v;
  }
}

}  // namespace
