// gsp-geodesic --metric end to end: every metric source against a closed form or the library,
// and the CLI contract for bad specs (exit 2) and bad metric data (exit 1).
#include "apps_support.hpp"
#include "helpers/mesh_builders.hpp"

#include <gsp/anisotropic/metric_field.hpp>
#include <gsp/anisotropic/metric_sources.hpp>
#include <gsp/io/mesh_io.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gsp::test {
namespace {

const std::string kApp = "gsp-geodesic";
constexpr Index kCentre = 60;   // (5, 5) on the 10 x 10 grid

std::string grid_file(const ScratchDir& dir, const io::VertexAttributes& attributes = {}) {
  const std::string path = (dir / "grid.ply").string();
  io::write_mesh(path, grid(10), attributes);
  return path;
}

// --layout on: the library's default layout, so the app's field and the library's agree to
// rounding (auto may pick another order for one field: GSP's order effects).
RunResult geodesic(const ScratchDir& dir, const std::string& input, const std::string& metric) {
  return run(bin(kApp) + " " + quote(input) + " --source-vertex " + std::to_string(kCentre) + " --layout on --metric " +
                 quote(metric) + " -o " + quote((dir / "d.txt").string()),
             dir);
}

// The app's field on the grid against sqrt(a dx^2 + b dy^2) from the centre.
void expect_diagonal_metric(const ScratchDir& dir, double a, double b) {
  const std::vector<double> got = io::read_values_txt((dir / "d.txt").string());
  const TriangleMesh m = grid(10);
  ASSERT_EQ(got.size(), m.num_vertices());
  const Vec3 s = m.positions[kCentre];
  for (std::size_t v = 0; v < got.size(); ++v) {
    const double dx = m.positions[v].x - s.x, dy = m.positions[v].y - s.y;
    const double want = std::sqrt(a * dx * dx + b * dy * dy);
    EXPECT_NEAR(got[v], want, 1e-4 * want) << v;
  }
}

TEST(AnisotropicApp, DirectionField) {
  ScratchDir dir("aniso");
  const auto r = geodesic(dir, grid_file(dir), "direction=0,1,0:ratio=2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_diagonal_metric(dir, 1, 4);
}

TEST(AnisotropicApp, TensorFile) {
  ScratchDir dir("aniso");
  write_file(dir / "metric.txt", "# x costs sqrt(3)\nconstant\n3 0 0 1 0 1\n");
  const auto r = geodesic(dir, grid_file(dir), (dir / "metric.txt").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_diagonal_metric(dir, 3, 1);
}

TEST(AnisotropicApp, PlyTensorProperties) {
  ScratchDir dir("aniso");
  io::VertexAttributes a;
  const char* names[6] = {"tensor_xx", "tensor_xy", "tensor_xz", "tensor_yy", "tensor_yz", "tensor_zz"};
  const float values[6] = {2, 0, 0, 5, 0, 1};
  for (int k = 0; k < 6; ++k) a.scalars.push_back({names[k], std::vector<float>(121, values[k])});
  const auto r = geodesic(dir, grid_file(dir, a), "attributes");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_diagonal_metric(dir, 2, 5);
}

TEST(AnisotropicApp, CurvatureMatchesTheLibrary) {
  ScratchDir dir("aniso");
  const std::string sample = std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off";
  const TriangleMesh m = io::read_mesh(sample).mesh;
  for (int rounds : {3, 0}) {
    const std::string spec = rounds == 3 ? "curvature:ratio=3" : "curvature:ratio=3:smooth=0";
    const auto r = geodesic(dir, sample, spec);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<double> got = io::read_values_txt((dir / "d.txt").string());
    const auto lib =
        anisotropic::geodesic_distances(m, anisotropic::curvature_metric(m, 3, rounds), {Source::at_vertex(kCentre)});
    ASSERT_EQ(got.size(), lib.vertex_distance.size());
    for (std::size_t v = 0; v < got.size(); ++v)
      ASSERT_NEAR(got[v], lib.vertex_distance[v], 1e-6 * (1 + lib.vertex_distance[v])) << spec << " " << v;
  }
}

TEST(AnisotropicApp, BadSpecsAreUsageErrors) {
  ScratchDir dir("aniso");
  const std::string input = grid_file(dir);
  for (const char* spec : {"direction=1,0,0", "direction=1,0:ratio=2", "direction=0,0,0:ratio=2",
                           "direction=1,0,0:ratio=x", "curvature", "curvature:ratio=-1", "curvature:ratio=0",
                           "curvature:ratio=2:smooth=-1", "curvature:ratio=2:smooth=x", "curvatures:ratio=2"}) {
    const auto r = geodesic(dir, input, spec);
    EXPECT_EQ(r.exit_code, 2) << spec << ": " << r.err;
    EXPECT_NE(r.err.find("--metric"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "d.txt"));
  }
  const auto r = run(bin(kApp) + " " + quote(input) + " --source-vertex 0 --method dijkstra --metric curvature:ratio=2 -o " +
                         quote((dir / "d.txt").string()),
                     dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
}

TEST(AnisotropicApp, BadMetricDataIsAnInputError) {
  ScratchDir dir("aniso");
  const std::string input = grid_file(dir);
  write_file(dir / "not_spd.txt", "1 0 0 -1 0 1\n");
  write_file(dir / "count.txt", "1 0 0 1 0 1\n1 0 0 1 0 1\n");
  write_file(dir / "syntax.txt", "1 0 0 1 zero 1\n");
  const std::pair<std::string, std::string> cases[] = {
      {(dir / "not_spd.txt").string(), "not symmetric positive definite"},
      {(dir / "count.txt").string(), "2 tensors: expected 1, 200 (faces) or 121 (vertices)"},
      {(dir / "syntax.txt").string(), "line 1: expected six finite numbers"},
      {(dir / "missing.txt").string(), "cannot open"},
      {"attributes", "no tensor_xx"}};
  for (const auto& [spec, message] : cases) {
    const auto r = geodesic(dir, input, spec);
    EXPECT_EQ(r.exit_code, 1) << spec << ": " << r.err;
    EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "d.txt"));
  }
}

}  // namespace
}  // namespace gsp::test
