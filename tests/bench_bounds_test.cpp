// Unit tests of gsp-bench's physical bounds (bounds.hpp) and of the category lookup of its
// corpus mode (categories.hpp), compiled in from the app's sources: synthetic distances that
// break each bound must be reported with the right size and count.
#include "bounds.hpp"
#include "categories.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using gsp::bench::BoundStats;
using gsp::bench::physical_bounds;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Source at the origin; vertex 3 sits on the source's position (a duplicate vertex).
gsp::TriangleMesh four_points() {
  gsp::TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 0}};
  m.triangles = {{0, 1, 2}};
  return m;
}

TEST(BenchBounds, RespectedBoundsReportZero) {
  // Straight line 1 and 2, edge paths 1 and 2: exact distances on this flat triangle.
  const BoundStats s = physical_bounds(four_points(), 0, {0, 1, 2, 0}, {0, 1, 2, 0});
  EXPECT_EQ(s.below_line, 0.0);
  EXPECT_EQ(s.above_edge, 0.0);
  EXPECT_EQ(s.below_count + s.above_count + s.nan + s.unreached, 0u);
  EXPECT_EQ(s.checked, 4u);
  EXPECT_FALSE(gsp::bench::violates(s));
}

TEST(BenchBounds, BelowTheStraightLineAndNaNAreReported) {
  // Vertex 1: d = 0.5 at straight-line distance 1 (50% short); vertex 2 NaN; the duplicate at
  // the source's position with d = 0 has no line to fall short of.
  const BoundStats s = physical_bounds(four_points(), 0, {0, 0.5, std::nan(""), 0}, {0, 1, 2, 0});
  EXPECT_DOUBLE_EQ(s.below_line, 0.5);
  EXPECT_EQ(s.below_count, 1u);
  EXPECT_EQ(s.above_edge, 0.0);   // short of the edge path is allowed
  EXPECT_EQ(s.nan, 1u);
  EXPECT_EQ(s.checked, 3u);
  EXPECT_TRUE(gsp::bench::violates(s));
}

TEST(BenchBounds, AboveTheEdgePathAndUnreachedAreReported) {
  // Vertex 1: 1.5 where the edge path is 1 (50% long); vertex 2 left at +inf though an edge
  // path reaches it; 0.5% above the edge path is within the 1% margin of the counts.
  const BoundStats s = physical_bounds(four_points(), 0, {0, 1.5, kInf, 0}, {0, 1, 2, 0});
  EXPECT_DOUBLE_EQ(s.above_edge, 0.5);
  EXPECT_EQ(s.above_count, 1u);
  EXPECT_EQ(s.unreached, 1u);
  EXPECT_EQ(s.below_line, 0.0);
  const BoundStats small = physical_bounds(four_points(), 0, {0, 1.005, 2, 0}, {0, 1, 2, 0});
  EXPECT_NEAR(small.above_edge, 0.005, 1e-12);
  EXPECT_EQ(small.above_count, 0u);
  EXPECT_FALSE(gsp::bench::violates(small));

  const BoundStats w = gsp::bench::worst_of(s, small);
  EXPECT_DOUBLE_EQ(w.above_edge, 0.5);
  EXPECT_EQ(w.above_count, 1u);
  EXPECT_EQ(w.unreached, 1u);
}

TEST(BenchCategories, ReadsTheCharacterColumnOfTheFileRow) {
  const std::string md =
      "# Meshes\n\nSome text | with a bar.\n\n"
      "| File | Format | Character | Origin |\n|---|---|---|---|\n"
      "| `scan.obj` | OBJ | benign (scan) | somewhere |\n"
      "| `cad.stl` | STL | malign (CAD) | elsewhere |\n"
      "| `points.ply` | PLY | point cloud | there |\n";
  EXPECT_EQ(gsp::bench::category_in(md, "scan.obj"), "benign");
  EXPECT_EQ(gsp::bench::category_in(md, "cad.stl"), "malign");
  EXPECT_EQ(gsp::bench::category_in(md, "points.ply"), "unknown");
  EXPECT_EQ(gsp::bench::category_in(md, "absent.off"), "unknown");
  EXPECT_EQ(gsp::bench::category_in(md, "scan"), "unknown");   // the whole name, in backticks
  EXPECT_EQ(gsp::bench::category_in("", "scan.obj"), "unknown");
}

}  // namespace
