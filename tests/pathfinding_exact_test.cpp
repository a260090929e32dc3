// Traced GSP paths against exact polyhedral geodesics (CGAL) on a benign mesh.
#include "helpers/geodesic_fixtures.hpp"
#include "pathfinding_support.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/pathfinding/path_tracer.hpp>
#include <gsp/reference/exact_geodesics.hpp>

#include <gtest/gtest.h>

#include <cstdio>

namespace gsp::test {
namespace {

using pathfinding::Endpoint;

// Every traced path is a true surface path (never shorter than the geodesic) and, pulled taut
// in its sleeve of faces, within 0.5% of the exact length (measured on these 48 pairs: mean
// 0.003%, max 0.07%; on camelhead and three more seeds at most 0.7%).
TEST(PathExact, FertilityRandomPairsAgainstExact) {
  const TriangleMesh m = io::read_mesh(std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off").mesh;
  reference::ExactGeodesicSolver exact(m);
  const GeodesicSolver solver(m);
  const pathfinding::PathTracer tracer(m);
  GeodesicOptions o;
  o.want_face_sources = true;
  SplitMix rng{2024};
  double worst = 0, worst_field = 0, sum = 0;
  int n = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const Index s = Index(rng.next() % m.num_vertices());
    const GeodesicResult field = solver.compute({Source::at_vertex(s)}, o);
    const std::vector<double> ex = exact.distances_from_vertex(s);
    for (int k = 0; k < 8; ++k) {
      const Index t = Index(rng.next() % m.num_vertices());
      if (t == s) continue;
      SCOPED_TRACE("source " + std::to_string(s) + " target " + std::to_string(t));
      const auto path = tracer.trace(field, Endpoint::at_vertex(t));
      expect_valid_path(m, path);
      const double rel = (path.length - ex[t]) / ex[t];
      EXPECT_GT(rel, -1e-6) << "a surface path cannot be shorter than the geodesic";
      EXPECT_LT(rel, 0.005);
      worst = std::max(worst, rel);
      worst_field = std::max(worst_field, std::abs(path.length - path.field_distance) / path.field_distance);
      sum += rel, ++n;
    }
  }
  EXPECT_LT(sum / n, 0.001);
  std::printf("paths vs exact: mean %.4f%%, max %.4f%%; max |path - field| %.4f%%\n", 100 * sum / n,
              100 * worst, 100 * worst_field);
}

}  // namespace
}  // namespace gsp::test
