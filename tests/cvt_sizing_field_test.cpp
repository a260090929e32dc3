// The edge remesh's sizing field (extensions/cvt/src/sizing_field.hpp): shares of the spacing
// from the input's bends, graded; and what it does to a remesh of a handle thinner than the
// spacing.
#include "edge_remesh.hpp"
#include "sizing_field.hpp"

#include "cvt_components.hpp"
#include "cvt_farthest_point.hpp"
#include "cvt_meshes.hpp"
#include "helpers/mesh_builders.hpp"

#include <gsp/cvt/closest_point_index.hpp>
#include <gsp/cvt/components.hpp>
#include <gsp/cvt/features.hpp>
#include <gsp/cvt/quality.hpp>
#include <gsp/cvt/surface.hpp>
#include <gsp/errors.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace gsp::cvt {
namespace {

// The largest distance of an input vertex from the remesh: how much of a thin part was lost.
double farthest_input_vertex(const TriangleMesh& input, const TriangleMesh& remesh) {
  return test::farthest_point(input.positions, remesh);
}

TEST(SizingField, FlatAndGentlyCurvedSurfacesKeepTheSpacing) {
  for (const double s : detail::curvature_sizing(test::square_grid(20), {}, 0.1)) EXPECT_EQ(s, 1.0);
  // A unit sphere at spacing 0.2: an edge spans 0.2 radians, far below one.
  for (const double s : detail::curvature_sizing(test::icosphere(3), {}, 0.2)) EXPECT_EQ(s, 1.0);
}

TEST(SizingField, ThinTubeGetsEdgesSpanningOneRadianOfItsBend) {
  // Tube radius 0.1, spacing 0.3: an edge of one radian round the tube is 0.1 long, a third of
  // the spacing (16 facets round the tube: chords, so the curvature read is within a few %).
  const TriangleMesh torus = test::torus(0.1, 96, 16);
  const std::vector<double> share = detail::curvature_sizing(torus, {}, 0.3);
  for (const double s : share) EXPECT_NEAR(s, 1.0 / 3.0, 0.05);
  // Two radians per edge: twice the share.
  detail::SizingOptions o;
  o.radians_per_edge = 2;
  for (const double s : detail::curvature_sizing(torus, {}, 0.3, o)) EXPECT_NEAR(s, 2.0 / 3.0, 0.1);
  // The floor: a quarter of the spacing at most.
  for (const double s : detail::curvature_sizing(torus, {}, 0.6)) EXPECT_EQ(s, 0.25);
}

TEST(SizingField, CreasesOnFeatureLinesAreNotBends) {
  // A plate with a hole: its rims are creases of 90 degrees. Given as feature edges they do not
  // shrink the spacing; left out they do.
  const TriangleMesh plate = test::plate_with_hole(1.0, 0.3, 0.05, 64);
  FeatureOptions fo;
  fo.angle = 40;
  fo.boundary = false;
  std::vector<std::pair<Index, Index>> creases;
  for (const std::vector<Index>& c : detect_features(plate, fo).curves)
    for (std::size_t i = 1; i < c.size(); ++i) creases.emplace_back(c[i - 1], c[i]);
  ASSERT_FALSE(creases.empty());
  const std::vector<double> with = detail::curvature_sizing(plate, creases, 0.3);
  const std::vector<double> without = detail::curvature_sizing(plate, {}, 0.3);
  EXPECT_GT(*std::min_element(with.begin(), with.end()), 0.99);
  EXPECT_LT(*std::min_element(without.begin(), without.end()), 0.9);
}

TEST(SizingField, SharesAreGraded) {
  // A narrow ridge across a square (z = 0.02 exp(-(x - 0.5)^2 / (2 0.03^2)), curvature about
  // 22 on its crest, but flat beside it within half a spacing, so the mean there is lower):
  // the share is smallest there and grows by at most `gradation` per spacing of distance, so at the
  // square's sides it is back to 1.
  TriangleMesh ridge = test::square_grid(80);
  for (Vec3& p : ridge.positions) p.z = 0.02 * std::exp(-(p.x - 0.5) * (p.x - 0.5) / (2 * 0.03 * 0.03));
  const double L = 0.2;
  const std::vector<double> share = detail::curvature_sizing(ridge, {}, L);
  double crest = 1, side = 0;
  for (std::size_t v = 0; v < share.size(); ++v) {
    const double x = ridge.positions[v].x;
    if (std::abs(x - 0.5) < 1e-9) crest = std::min(crest, share[v]);
    if (x < 1e-9) side = std::max(side, share[v]);
  }
  EXPECT_EQ(crest, *std::min_element(share.begin(), share.end()));
  EXPECT_LT(crest, 0.75);
  EXPECT_EQ(side, 1.0);
  for (const Triangle& t : ridge.triangles)
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      const double d = distance(ridge.positions[a], ridge.positions[b]);
      EXPECT_LE(std::abs(share[a] - share[b]), detail::SizingOptions{}.gradation * d / L + 1e-12);
    }
}

TEST(SizingField, HandleThinnerThanTheSpacingKeepsItsShape) {
  // A tube of radius 0.06 at spacing 0.2: with one spacing everywhere the remesh keeps the
  // handle's topology as a flat ribbon of two edges round it (input vertices up to about the
  // radius away); with edges of at most one radian of the bend (6 round the tube) it stays a
  // tube, within a chord's sagitta (0.06 (1 - cos 0.5) = 0.007) and the smoothing's shrinkage.
  const TriangleMesh torus = test::torus(0.06, 96, 12);
  const ClosestPointIndex surface(torus);
  const TriangleMesh uniform = detail::remesh_by_edge_operations(torus, surface, 0.2, 40, 10, 1000000);
  detail::SizingOptions sizing;
  const TriangleMesh sized =
      detail::remesh_by_edge_operations(torus, surface, 0.2, 40, 10, 1000000, 0, nullptr, &sizing);
  ASSERT_FALSE(uniform.triangles.empty());
  ASSERT_FALSE(sized.triangles.empty());
  std::string why;
  EXPECT_TRUE(same_topology_per_component(torus, sized, &why)) << why;
  EXPECT_GT(farthest_input_vertex(torus, uniform), 0.04);
  EXPECT_LT(farthest_input_vertex(torus, sized), 0.02);
  EXPECT_GE(measure_mesh_quality(sized).min_angle, 20.0);
}

// Around the far vertices the share is cut to the factor times theirs, graded back by 0.2 per
// spacing of straight-line distance, never below the floor; vertices beyond the reach keep
// theirs, and a share already smaller stays.
TEST(SizingField, RefinedAroundFarVertices) {
  const TriangleMesh square = test::square_grid(40);   // the unit square, vertex spacing 1/40
  const double L = 0.1;
  std::vector<double> share;   // empty: 1 everywhere
  Index centre = 0, low = 0;
  for (Index v = 0; v < square.num_vertices(); ++v) {
    if (distance(square.positions[v], Vec3{0.5, 0.5, 0}) < 1e-9) centre = v;
    if (distance(square.positions[v], Vec3{0.9, 0.9, 0}) < 1e-9) low = v;
  }
  detail::refine_around(square, {centre}, L, 0.5, 0.2, 0.125, share);
  ASSERT_EQ(share.size(), square.num_vertices());
  for (Index v = 0; v < square.num_vertices(); ++v) {
    const double d = distance(square.positions[v], square.positions[centre]);
    EXPECT_NEAR(share[v], std::min(1.0, 0.5 + 0.2 * d / L), 1e-12) << "vertex " << v;
  }
  // Again at the centre: halved again (0.25), then the floor (0.125) holds.
  detail::refine_around(square, {centre}, L, 0.5, 0.2, 0.125, share);
  EXPECT_DOUBLE_EQ(share[centre], 0.25);
  share[low] = 0.01;
  detail::refine_around(square, {centre, centre}, L, 0.5, 0.2, 0.125, share);
  EXPECT_DOUBLE_EQ(share[centre], 0.125);
  EXPECT_DOUBLE_EQ(share[low], 0.01);
  for (Index v = 0; v < square.num_vertices(); ++v)
    if (distance(square.positions[v], square.positions[centre]) > 0.875 / 0.2 * L + 1e-9) EXPECT_TRUE(share[v] == 1.0 || v == low);
}

TEST(SizingField, RemeshSurfaceRefusesAnAngleOutOfRange) {
  SurfaceRemeshOptions o;
  o.cvt.sites = 100;
  o.method = RemeshMethod::edges;
  o.edge_sizing_angle = -1;
  EXPECT_THROW(remesh_surface(test::icosphere(2), o), InvalidInput);
  o.edge_sizing_angle = 181;
  EXPECT_THROW(remesh_surface(test::icosphere(2), o), InvalidInput);
}

}  // namespace
}  // namespace gsp::cvt
