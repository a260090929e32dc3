// What gsp::anisotropic and SolverOptions::edge_lengths refuse, and the metric sources that
// read data (text format, PLY tensor properties).
#include "helpers/mesh_builders.hpp"

#include <gsp/anisotropic/metric_field.hpp>
#include <gsp/anisotropic/metric_sources.hpp>
#include <gsp/errors.hpp>
#include <gsp/io/mesh_io.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

namespace {

using namespace gsp;
using anisotropic::MetricField;
using anisotropic::MetricLocation;
using anisotropic::SymmetricTensor;

std::vector<double> lengths_of(const TriangleMesh& m) {
  std::vector<double> l;
  for (const Triangle& t : m.triangles)
    for (int i = 0; i < 3; ++i) l.push_back(distance(m.positions[t[i]], m.positions[t[(i + 1) % 3]]));
  return l;
}

GeodesicSolver solver_with(const TriangleMesh& m, std::vector<double> lengths) {
  SolverOptions so;
  so.edge_lengths = std::move(lengths);
  return GeodesicSolver(m, so);
}

TEST(AnisotropicErrors, EdgeLengthsAreChecked) {
  const TriangleMesh m = test::grid(3);
  const std::vector<double> good = lengths_of(m);
  EXPECT_NO_THROW(solver_with(m, good));
  EXPECT_THROW(solver_with(m, std::vector<double>(good.begin(), good.end() - 1)), InvalidInput);
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), -0.5}) {
    std::vector<double> l = good;
    l[4] = bad;
    EXPECT_THROW(solver_with(m, l), InvalidInput) << bad;
  }
  std::vector<double> l = good;
  l[3] = l[4] + l[5] + 1e-3;   // face 1 cannot close
  EXPECT_THROW(solver_with(m, l), InvalidInput);
  l[3] = l[4] + l[5];          // degenerate but legal (a zero-area face)
  EXPECT_NO_THROW(solver_with(m, l));
  l[3] = (l[4] + l[5]) * (1 + 1e-9);   // rounding of a degenerate face is tolerated
  EXPECT_NO_THROW(solver_with(m, l));
}

TEST(AnisotropicErrors, ThreeDConstructionsAreRefusedWithLengths) {
  const TriangleMesh m = test::grid(3);
  const GeodesicSolver s = solver_with(m, lengths_of(m));
  GeodesicOptions face_sources;
  face_sources.want_face_sources = true;
  EXPECT_THROW(s.compute({Source::at_vertex(0)}, face_sources), InvalidInput);
  GeodesicOptions astar;
  astar.targets = {15};
  astar.goal_directed = true;
  EXPECT_THROW(s.compute({Source::at_vertex(0)}, astar), InvalidInput);
  astar.goal_directed = false;   // a targeted run needs no 3D bound
  EXPECT_NEAR(s.compute({Source::at_vertex(0)}, astar).vertex_distance[15], std::sqrt(18.0), 1e-5);
}

TEST(AnisotropicErrors, TensorsAreChecked) {
  const TriangleMesh m = test::grid(2);
  EXPECT_THROW(anisotropic::metric_edge_lengths(m, MetricField::constant(SymmetricTensor::diagonal(1, -1, 1))),
               InvalidInput);
  EXPECT_THROW(anisotropic::metric_edge_lengths(m, MetricField::constant(SymmetricTensor::diagonal(1, 1, 0))),
               InvalidInput);
  EXPECT_THROW(anisotropic::metric_edge_lengths(m, MetricField::constant({1, 2, 0, 1, 0, 1})), InvalidInput);
  EXPECT_THROW(anisotropic::metric_edge_lengths(
                   m, MetricField::constant({1, std::numeric_limits<double>::quiet_NaN(), 0, 1, 0, 1})),
               InvalidInput);
  const MetricField wrong_count{MetricLocation::per_face, std::vector<SymmetricTensor>(m.num_faces() - 1)};
  EXPECT_THROW(anisotropic::metric_edge_lengths(m, wrong_count), InvalidInput);
  const MetricField per_vertex{MetricLocation::per_vertex, std::vector<SymmetricTensor>(m.num_vertices())};
  EXPECT_NO_THROW(anisotropic::metric_edge_lengths(m, per_vertex));
  for (double ratio : {0.0, -2.0, std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(anisotropic::direction_metric(m, {1, 0, 0}, ratio), InvalidInput);
    EXPECT_THROW(anisotropic::curvature_metric(m, ratio), InvalidInput);
  }
  EXPECT_THROW(anisotropic::direction_metric(m, {0, 0, 0}, 2), InvalidInput);
}

TEST(AnisotropicErrors, DirectionPerpendicularToTheFaceIsIsotropic) {
  const TriangleMesh m = test::grid(2);
  const MetricField f = anisotropic::direction_metric(m, {0, 0, 1}, 5);
  for (const SymmetricTensor& t : f.tensors) EXPECT_EQ(t.excess({1, 2, 3}), 0.0);
  EXPECT_EQ(anisotropic::metric_edge_lengths(m, f), lengths_of(m));
}

MetricField parse(const std::string& text, std::size_t nv = 9, std::size_t nf = 8) {
  std::istringstream in(text);
  return anisotropic::parse_metric_text(in, "metric.txt", nv, nf);
}

TEST(AnisotropicErrors, TextFormat) {
  const MetricField c = parse("# one tensor for all\n  2 0 0 1 0 1  # xx xy xz yy yz zz\n");
  EXPECT_EQ(c.location, MetricLocation::constant);
  EXPECT_EQ(c.tensors[0].xx, 2.0);
  std::string faces, vertices;
  for (int i = 0; i < 8; ++i) faces += "1 0.5 0 1 0 1\n";
  for (int i = 0; i < 9; ++i) vertices += "1 0 0 1 0 3\n";
  EXPECT_EQ(parse(faces).location, MetricLocation::per_face);
  EXPECT_EQ(parse(vertices).location, MetricLocation::per_vertex);
  EXPECT_EQ(parse(vertices).tensors[8].zz, 3.0);
  EXPECT_EQ(parse("per-face\n" + faces, 8, 8).location, MetricLocation::per_face);
  EXPECT_THROW(parse(faces, 8, 8), IoError);                          // ambiguous without the keyword
  const auto error_of = [&](const std::string& text) {
    try {
      parse(text);
    } catch (const IoError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of(faces + "1 0 0 1 0 1\n1 0 0 1 0 1\n"), "metric.txt: 10 tensors: expected 1, 8 (faces) or 9 (vertices)");
  EXPECT_EQ(error_of("1 0 0 1 0\n"), "metric.txt:line 1: expected six finite numbers xx xy xz yy yz zz");
  EXPECT_EQ(error_of("\n1 0 0 1 0 1 7\n"), "metric.txt:line 2: more than six numbers");
  EXPECT_EQ(error_of("1 0 0 1 0 nan\n"), "metric.txt:line 1: expected six finite numbers xx xy xz yy yz zz");
  EXPECT_EQ(error_of("per-edge\n1 0 0 1 0 1\n"),
            "metric.txt:line 1: \"per-edge\" is not constant, per-face, per-vertex or six numbers");
  EXPECT_EQ(error_of("per-face\n1 0 0 1 0 1\n"), "metric.txt: 1 tensors, the keyword asks for 8");
  EXPECT_EQ(error_of("1 0 0 -1 0 1\n"), "metric.txt:tensor 1: not symmetric positive definite");
  EXPECT_EQ(error_of("# nothing\n"), "metric.txt: no tensors");
  EXPECT_THROW(anisotropic::read_metric_file("/nonexistent/metric.txt", 9, 8), IoError);
}

TEST(AnisotropicErrors, PlyTensorProperties) {
  const TriangleMesh m = test::grid(2);
  io::VertexAttributes a;
  const char* names[6] = {"tensor_xx", "tensor_xy", "tensor_xz", "tensor_yy", "tensor_yz", "tensor_zz"};
  const float values[6] = {4, 0.5f, 0, 1, 0, 1};
  for (int k = 0; k < 6; ++k) a.scalars.push_back({names[k], std::vector<float>(m.num_vertices(), values[k])});
  const auto path = std::filesystem::temp_directory_path() / ("gsp-aniso-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + ".ply");
  io::write_mesh(path.string(), m, a);
  const io::ReadResult back = io::read_mesh(path.string());
  std::filesystem::remove(path);
  ASSERT_TRUE(anisotropic::has_tensor_attributes(back.attributes));
  const MetricField f = anisotropic::metric_from_attributes(back.attributes, m.num_vertices());
  EXPECT_EQ(f.location, MetricLocation::per_vertex);
  EXPECT_EQ(f.tensors[3].xx, 4.0);
  EXPECT_EQ(f.tensors[3].xy, 0.5);
  // Edge (0,0)-(1,0): sqrt(4); (0,0)-(1,1): sqrt(4 + 2 * 0.5 + 1).
  const auto l = anisotropic::metric_edge_lengths(m, f);
  EXPECT_DOUBLE_EQ(l[0], 2.0);
  EXPECT_DOUBLE_EQ(l[2], std::sqrt(6.0));
  a.scalars.pop_back();
  EXPECT_THROW(anisotropic::metric_from_attributes(a, m.num_vertices()), InvalidInput);
  EXPECT_FALSE(anisotropic::has_tensor_attributes(io::VertexAttributes{}));
}

}  // namespace
