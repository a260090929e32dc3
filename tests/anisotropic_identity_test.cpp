// An isotropic metric (identity tensors, ratio 1) must give the plain GSP result bit for bit:
// the metric's lengths equal the core's 3D lengths exactly, and the solver then does the same
// arithmetic.
#include "helpers/mesh_builders.hpp"
#include "test_data.hpp"

#include <gsp/anisotropic/metric_field.hpp>
#include <gsp/anisotropic/metric_sources.hpp>
#include <gsp/io/mesh_io.hpp>

#include <gtest/gtest.h>

namespace {

using namespace gsp;
using gsp::anisotropic::MetricField;

TriangleMesh fertility() {
  return io::read_mesh(std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off").mesh;
}

std::vector<double> plain_lengths(const TriangleMesh& m) {
  std::vector<double> l;
  for (const Triangle& t : m.triangles)
    for (int i = 0; i < 3; ++i) l.push_back(distance(m.positions[t[i]], m.positions[t[(i + 1) % 3]]));
  return l;
}

// The straight-line bound holds for a metric scaled by the square root of its smallest
// eigenvalue (anisotropic::line_scale): 1 for identity tensors, so the metric runs keep the
// plain runs' bound and the update step's test (rule 8) bit for bit; and without both too.
GeodesicOptions line_bound(bool on) {
  GeodesicOptions go;
  go.straight_line_bound = on;
  go.straight_line_test = on;
  return go;
}

void expect_same_result(const TriangleMesh& mesh, const MetricField& field, const char* what) {
  const std::vector<Source> sources{Source::at_vertex(0), Source::at_vertex(Index(mesh.num_vertices() / 3), 0.5)};
  for (bool delaunay : {true, false})
    for (Precision p : {Precision::single, Precision::double_precision})
    for (bool bound : {true, false}) {
      SolverOptions so;
      so.intrinsic_delaunay = delaunay;
      GeodesicOptions go = line_bound(bound);
      go.precision = p;
      const GeodesicResult plain = GeodesicSolver(mesh, so).compute(sources, go);
      const GeodesicResult metric = anisotropic::geodesic_distances(mesh, field, sources, go, so);
      EXPECT_EQ(metric.vertex_distance, plain.vertex_distance) << what << " delaunay " << delaunay;
      EXPECT_EQ(metric.vertex_source, plain.vertex_source) << what;
      EXPECT_EQ(metric.face_distance, plain.face_distance) << what;
      EXPECT_EQ(metric.stats.update_steps, plain.stats.update_steps) << what;
    }
  // A face-point source runs on the input faces.
  const std::vector<Source> face{Source::in_face(7, {0.2, 0.3, 0.5})};
  EXPECT_EQ(anisotropic::geodesic_distances(mesh, field, face).vertex_distance,
            GeodesicSolver(mesh).compute(face).vertex_distance)
      << what;
}

TEST(AnisotropicIdentity, RatioOneIsPlainGspBitForBitOnFertility) {
  const TriangleMesh m = fertility();
  ASSERT_EQ(m.num_vertices(), 4494u);
  const MetricField fields[] = {MetricField::constant(anisotropic::SymmetricTensor::identity()),
                                anisotropic::direction_metric(m, {0.3, -1, 0.2}, 1.0),
                                anisotropic::curvature_metric(m, 1.0)};
  for (const MetricField& f : fields) EXPECT_EQ(anisotropic::metric_edge_lengths(m, f), plain_lengths(m));
  expect_same_result(m, fields[0], "identity");
  expect_same_result(m, fields[1], "direction ratio 1");
  expect_same_result(m, fields[2], "curvature ratio 1");
}

TEST(AnisotropicIdentity, RatioOneIsPlainGspBitForBitOnAFlatGrid) {
  // Every interior vertex is flat: the flat test from lengths must agree with the 3D one.
  const TriangleMesh m = test::grid(10);
  expect_same_result(m, anisotropic::direction_metric(m, {1, 1, 0}, 1.0), "grid");
}

TEST(AnisotropicIdentity, GivenLengthsEqualToTheDefaultChangeNothing) {
  // The core option on its own: the 3D lengths passed explicitly. Without a line scale the
  // solver knows no 3D bound for them (neither the bound nor rule 8); with scale 1 it is the
  // plain solver.
  const TriangleMesh m = fertility();
  SolverOptions so;
  so.edge_lengths = plain_lengths(m);
  EXPECT_EQ(GeodesicSolver(m, so).compute({Source::at_vertex(42)}).vertex_distance,
            GeodesicSolver(m).compute({Source::at_vertex(42)}, line_bound(false)).vertex_distance);
  so.edge_lengths_line_scale = 1;
  EXPECT_EQ(GeodesicSolver(m, so).compute({Source::at_vertex(42)}).vertex_distance,
            GeodesicSolver(m).compute({Source::at_vertex(42)}).vertex_distance);
}

}  // namespace
