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

// The straight-line bound is a 3D fact a metric does not have: the solver leaves it out with
// edge lengths, so the plain runs compared with the metric ones leave it out too.
GeodesicOptions without_line_bound() {
  GeodesicOptions go;
  go.straight_line_bound = false;
  go.straight_line_test = false;   // neither the bound nor the update step's test (rule 8)
  return go;
}

void expect_same_result(const TriangleMesh& mesh, const MetricField& field, const char* what) {
  const std::vector<Source> sources{Source::at_vertex(0), Source::at_vertex(Index(mesh.num_vertices() / 3), 0.5)};
  for (bool delaunay : {true, false})
    for (Precision p : {Precision::single, Precision::double_precision}) {
      SolverOptions so;
      so.intrinsic_delaunay = delaunay;
      GeodesicOptions go = without_line_bound();
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
            GeodesicSolver(mesh).compute(face, without_line_bound()).vertex_distance)
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
  // The core option on its own: the 3D lengths passed explicitly.
  const TriangleMesh m = fertility();
  SolverOptions so;
  so.edge_lengths = plain_lengths(m);
  EXPECT_EQ(GeodesicSolver(m, so).compute({Source::at_vertex(42)}).vertex_distance,
            GeodesicSolver(m).compute({Source::at_vertex(42)}, without_line_bound()).vertex_distance);
}

}  // namespace
