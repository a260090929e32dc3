// The flat-corner rule's crease limit (gsp/intrinsic/saddle_creases.hpp; docs/gsp-core.md,
// rule 4): a fan round one vertex, split twice at edge midpoints. The fan's edges become
// straight creases of flat vertices running out from the centre; where the centre is a saddle
// their flat vertices are plain, where it is a cone point of positive curvature they stay flat,
// and the flat vertices inside the old faces (no crease) stay flat either way.
#include <gsp/connectivity.hpp>
#include <gsp/intrinsic/edge_lengths.hpp>
#include <gsp/intrinsic/vertex_kinds.hpp>
#include <gsp/subdivide.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gsp {
namespace {

// Centre 0 and a ring of six at radius 1, heights alternating +-h (a saddle: angle sum above
// 2 pi) or all -h (a cone: below), then two midpoint splits.
TriangleMesh split_fan(bool saddle, double h) {
  TriangleMesh fan;
  fan.positions.push_back({0, 0, 0});
  for (int i = 0; i < 6; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / 6;
    fan.positions.push_back({std::cos(a), std::sin(a), saddle && i % 2 ? h : -h});
  }
  for (Index i = 0; i < 6; ++i) fan.triangles.push_back({0, 1 + i, 1 + (i + 1) % 6});
  return midpoint_subdivide(fan, 2);
}

std::vector<std::uint8_t> kinds(const TriangleMesh& m) {
  const Connectivity conn = build_connectivity(m);
  const std::vector<bool> none(m.num_faces(), false);
  return intrinsic::vertex_kinds(m, conn, none, {}, {}, intrinsic::halfedge_lengths(m));
}

// The vertex at position p.
Index at(const TriangleMesh& m, Vec3 p) {
  for (Index v = 0; v < Index(m.num_vertices()); ++v)
    if (norm(m.positions[v] - p) < 1e-12) return v;
  ADD_FAILURE() << "no vertex at the point";
  return 0;
}

TEST(SaddleCreases, FlatVerticesOnCreasesFromASaddleArePlain) {
  const TriangleMesh m = split_fan(true, 0.5);
  const auto kind = kinds(m);
  ASSERT_EQ(kind[0], intrinsic::kSaddleVertex);
  for (Index i = 1; i <= 6; ++i) {
    // The middle of old edge 0-i: flat (angle sum 2 pi), all its neighbours flat, on a crease
    // from the saddle.
    EXPECT_EQ(kind[at(m, 0.5 * m.positions[i])], intrinsic::kPlainVertex) << i;
  }
  // Inside old face (0, 1, 2), at the middle of the split's edge from the middle of 0-1 to the
  // middle of 0-2: flat, no crease through it.
  const Vec3 inside = 0.5 * (0.5 * m.positions[1] + 0.5 * m.positions[2]);
  EXPECT_EQ(kind[at(m, inside)], intrinsic::kFlatVertex);
}

TEST(SaddleCreases, CreasesFromAConePointKeepTheRule) {
  const TriangleMesh m = split_fan(false, 0.5);
  const auto kind = kinds(m);
  ASSERT_EQ(kind[0], intrinsic::kConvexVertex);
  for (Index i = 1; i <= 6; ++i) EXPECT_EQ(kind[at(m, 0.5 * m.positions[i])], intrinsic::kFlatVertex) << i;
}

}  // namespace
}  // namespace gsp
