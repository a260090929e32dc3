// The flat-corner rule's crease limits (gsp/intrinsic/saddle_creases.hpp; docs/gsp-core.md,
// rule 4): a fan round one vertex, split twice at edge midpoints. The fan's edges become
// straight creases of flat vertices running out from the centre; where the centre is a saddle
// their flat vertices are plain, where it is a cone point of positive curvature they stay flat,
// and the flat vertices inside the old faces (no crease) stay flat either way. And a closed
// convex mesh split once: each new vertex is alone on its crease between two convex ones, and
// convex itself; split twice, the creases are three long and their ends plain as before.
#include <gsp/connectivity.hpp>
#include <gsp/intrinsic/edge_lengths.hpp>
#include <gsp/intrinsic/vertex_kinds.hpp>
#include <gsp/subdivide.hpp>

#include "helpers/mesh_builders.hpp"

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

// Every old vertex of an icosphere is convex. Split once, each new vertex is the middle of an
// old edge: flat, next to two convex vertices along its crease and to four flat ones, and
// treated as convex (a bend there only over-estimates); before, plain. Split twice, the
// middles of the old edges (all their neighbours flat) stay flat, the vertices next to the old
// ones plain: their creases are three vertices long.
TEST(SaddleCreases, AFlatVertexAloneOnACreaseBetweenConvexOnesIsConvex) {
  const TriangleMesh ico = test::icosphere(0);
  const TriangleMesh once = midpoint_subdivide(ico, 1);
  const auto kind = kinds(once);
  for (Index v = 0; v < Index(ico.num_vertices()); ++v) ASSERT_EQ(kind[v], intrinsic::kConvexVertex) << v;
  for (Index v = Index(ico.num_vertices()); v < Index(once.num_vertices()); ++v)
    EXPECT_EQ(kind[v], intrinsic::kConvexVertex) << v;

  const TriangleMesh twice = midpoint_subdivide(ico, 2);
  const auto kind2 = kinds(twice);
  for (const Triangle& t : ico.triangles)
    for (int i = 0; i < 3; ++i) {
      const Vec3 a = ico.positions[t[i]], b = ico.positions[t[(i + 1) % 3]];
      EXPECT_EQ(kind2[at(twice, 0.5 * (a + b))], intrinsic::kFlatVertex);
      EXPECT_EQ(kind2[at(twice, 0.75 * a + 0.25 * b)], intrinsic::kPlainVertex);
    }
}

// Next to a saddle (or a boundary corner, plain) a lone crease vertex stays plain: the fan
// split once, its centre a saddle and its rim a boundary.
TEST(SaddleCreases, ALoneCreaseVertexNextToASaddleStaysPlain) {
  TriangleMesh fan;
  fan.positions.push_back({0, 0, 0});
  for (int i = 0; i < 6; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / 6;
    fan.positions.push_back({std::cos(a), std::sin(a), i % 2 ? 0.5 : -0.5});
  }
  for (Index i = 0; i < 6; ++i) fan.triangles.push_back({0, 1 + i, 1 + (i + 1) % 6});
  const TriangleMesh m = midpoint_subdivide(fan, 1);
  const auto kind = kinds(m);
  ASSERT_EQ(kind[0], intrinsic::kSaddleVertex);
  for (Index i = 1; i <= 6; ++i) EXPECT_EQ(kind[at(m, 0.5 * m.positions[i])], intrinsic::kPlainVertex) << i;
}

}  // namespace
}  // namespace gsp
