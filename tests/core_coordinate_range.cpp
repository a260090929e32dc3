// validate_positions: coordinates up to kMaxCoordinate in magnitude and spans down to kMinExtent
// give the distances of the same mesh at unit scale, scaled; beyond them the input is refused
// with a one-line reason (at 1e300 every length overflowed and GSP answered 0 everywhere; at
// 1e20 gsp-cvt's closest-point searches, in single precision, gave a NaN Hausdorff distance).
#include <gsp/dijkstra.hpp>
#include <gsp/errors.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/mesh.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "helpers/mesh_builders.hpp"

namespace gsp {
namespace {

TriangleMesh scaled(TriangleMesh m, double s) {
  for (Vec3& p : m.positions) p = s * p;
  return m;
}

std::string message(const TriangleMesh& m) {
  try {
    validate(m);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(CoreCoordinateRange, DistancesScaleWithTheMeshUpToTheLimits) {
  const TriangleMesh unit = test::icosphere(2);
  const std::vector<double> base = GeodesicSolver(unit).compute({Source::at_vertex(0)}).vertex_distance;
  const std::vector<double> base_edges = dijkstra_distances(unit, {Source::at_vertex(0)}).vertex_distance;
  for (const double s : {1.1 * kMinExtent, 1e-9, 1e9, 0.9 * kMaxCoordinate}) {
    const TriangleMesh m = scaled(unit, s);
    const std::vector<double> d = GeodesicSolver(m).compute({Source::at_vertex(0)}).vertex_distance;
    const std::vector<double> e = dijkstra_distances(m, {Source::at_vertex(0)}).vertex_distance;
    ASSERT_EQ(d.size(), base.size());
    for (std::size_t v = 0; v < d.size(); ++v) {
      EXPECT_NEAR(d[v] / s, base[v], 1e-6 * (1 + base[v])) << "scale " << s << " vertex " << v;
      EXPECT_NEAR(e[v] / s, base_edges[v], 1e-9 * (1 + base_edges[v])) << "scale " << s << " vertex " << v;
    }
  }
}

TEST(CoreCoordinateRange, RefusesCoordinatesOutOfRange) {
  const TriangleMesh unit = test::icosphere(1);
  const std::string far = message(scaled(unit, 1e300));
  EXPECT_NE(far.find("vertex 0 has a coordinate of magnitude"), std::string::npos) << far;
  EXPECT_NE(far.find("scale the input"), std::string::npos) << far;
  const std::string tiny = message(scaled(unit, 1e-300));
  EXPECT_NE(tiny.find("the positions span only"), std::string::npos) << tiny;
  // One vertex out of range is enough: its edges' squares overflow.
  TriangleMesh one = unit;
  one.positions[5].y = -2 * kMaxCoordinate;
  EXPECT_NE(message(one).find("vertex 5 has a coordinate of magnitude 2e+18"), std::string::npos) << message(one);
  EXPECT_THROW(GeodesicSolver(scaled(unit, 1e300)), InvalidInput);
  EXPECT_THROW(dijkstra_distances(scaled(unit, 1e-300), {Source::at_vertex(0)}), InvalidInput);
}

TEST(CoreCoordinateRange, EverythingAtOnePointIsDegenerateNotAnError) {
  TriangleMesh m = test::quad();
  for (Vec3& p : m.positions) p = Vec3{3, 4, 5};
  EXPECT_EQ(message(m), "");
  const std::vector<double> d = GeodesicSolver(m).compute({Source::at_vertex(0)}).vertex_distance;
  for (double x : d) EXPECT_EQ(x, 0.0);
}

}  // namespace
}  // namespace gsp
