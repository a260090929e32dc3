// Boundary edges fitted to the input's boundary curve (extensions/cvt/src/boundary_fit.*): a
// chord that cuts a corner of the curve is split on the curve, also where one end is a dent the
// dual left inside the surface.
#include "boundary_curves.hpp"
#include "boundary_fit.hpp"
#include "triangle_geometry.hpp"

#include "helpers/mesh_builders.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace gsp;
using cvt::detail::BoundaryCurves;
using cvt::detail::split_boundary_edges;

// The 8 x 8 square as five triangles round a point above its lower side's middle, which is at `m`.
TriangleMesh fan(Vec3 m) {
  TriangleMesh t;
  t.positions = {{0, 0, 0}, m, {8, 0, 0}, {8, 8, 0}, {0, 8, 0}, {4, 1.5, 0}};
  t.triangles = {{0, 1, 5}, {1, 2, 5}, {2, 3, 5}, {3, 4, 5}, {4, 0, 5}};
  return t;
}

double smallest_angle_deg(const TriangleMesh& m) {
  return cvt::detail::mesh_min_angle(m) * 180.0 / M_PI;
}

TEST(CvtBoundaryFit, ChordOnTheCurveIsNotSplit) {
  const TriangleMesh surface = test::grid(8);
  const BoundaryCurves curves(surface);
  TriangleMesh m = fan({4, 0, 0});
  EXPECT_EQ(split_boundary_edges(m, curves, 0.1, 30.0, 3), 0u);
  EXPECT_EQ(m.num_faces(), 5u);
}

// The lower side's middle vertex 0.3 inside: both chords from it cut the curve's
// stretch by more than the bound, so the edges are split at the curve's points, with the
// floor lowered to 20 degrees for an edge with an end off the curve.
TEST(CvtBoundaryFit, DentInTheDualsBoundaryIsSplitOntoTheCurve) {
  const TriangleMesh surface = test::grid(8);
  const BoundaryCurves curves(surface);
  TriangleMesh m = fan({4, 0.3, 0});
  const double before = smallest_angle_deg(m);
  const std::size_t splits = split_boundary_edges(m, curves, 0.1, 30.0, 3);
  ASSERT_GE(splits, 1u);
  EXPECT_EQ(m.num_faces(), 5u + splits);
  for (std::size_t v = 6; v < m.num_vertices(); ++v) EXPECT_NEAR(m.positions[v].y, 0.0, 1e-12);   // on the curve
  for (const Triangle& t : m.triangles) {
    const Vec3 n = cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
    EXPECT_GT(n.z, 0.0);   // orientation kept
  }
  EXPECT_GE(smallest_angle_deg(m), std::min(before, cvt::detail::kDentFloorDeg) - 1e-9);
}

}  // namespace
