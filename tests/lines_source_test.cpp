// gsp::lines sources: mesh edges, vertex chains, the boundary, snapped polylines, the polyline
// text formats, and the errors each refuses with.
#include "lines_support.hpp"
#include "test_data.hpp"

#include <gsp/errors.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/lines/line_distances.hpp>
#include <gsp/lines/polyline_text.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace gsp::test {
namespace {

// Expects `f` to throw E with `part` in its message.
template <class E, class F>
void expect_error(F&& f, const std::string& part) {
  try {
    f();
    ADD_FAILURE() << "no exception, expected one mentioning \"" << part << "\"";
  } catch (const E& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TriangleMesh tetrahedron() {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return m;
}

TEST(LinesSource, EdgesArePlacedInEveryFaceThatHasThem) {
  const TriangleMesh m = jittered_square(4, 1);
  // (0,0)-(1,0) lies on the boundary (one face); (1,1)-(2,1) inside (two faces).
  const lines::LineSource src = lines::edge_source(m, {{0, 1}, {6, 7}});
  ASSERT_EQ(src.num_segments(), 2u);
  std::size_t first = 0, second = 0;
  for (const lines::SegmentPiece& p : src.pieces) (p.segment == 0 ? first : second)++;
  EXPECT_EQ(first, 1u);
  EXPECT_EQ(second, 2u);
  EXPECT_EQ(src.segments[1][0], m.positions[6]);
  EXPECT_EQ(src.segments[1][1], m.positions[7]);
}

TEST(LinesSource, EdgeErrorsNameTheEdge) {
  const TriangleMesh m = jittered_square(4, 1);
  expect_error<InvalidInput>([&] { lines::edge_source(m, {{0, 1}, {0, 12}}); }, "0-12 is not an edge");
  expect_error<InvalidInput>([&] { lines::edge_source(m, {{3, 3}}); }, "repeats a vertex");
  expect_error<InvalidInput>([&] { lines::edge_source(m, {{0, 99}}); }, "vertex 99 does not exist");
  expect_error<InvalidInput>([&] { lines::vertex_chain_source(m, {0}, false); }, "at least two");
}

TEST(LinesSource, ClosedChainAddsTheClosingEdge) {
  const TriangleMesh m = jittered_square(4, 1);
  // Around the cell (1,1): vertices 6, 7, 12, 11 are joined by the cell's four sides.
  EXPECT_EQ(lines::vertex_chain_source(m, {6, 7, 12, 11}, false).num_segments(), 3u);
  EXPECT_EQ(lines::vertex_chain_source(m, {6, 7, 12, 11}, true).num_segments(), 4u);
  EXPECT_EQ(lines::vertex_chain_source(m, {6, 7, 12, 11, 6}, true).num_segments(), 4u);
}

TEST(LinesSource, BoundaryHasOneSegmentPerBoundaryEdge) {
  const TriangleMesh m = jittered_square(6, 2);
  const lines::LineSource src = lines::boundary_source(m);
  EXPECT_EQ(src.num_segments(), 24u);
  EXPECT_EQ(src.pieces.size(), 24u);
  expect_error<InvalidInput>([&] { lines::boundary_source(tetrahedron()); }, "mesh has no boundary");
}

TEST(LinesSource, PolylineErrors) {
  const TriangleMesh m = jittered_square(4, 1);
  expect_error<InvalidInput>([&] { lines::polyline_source(m, {{Vec3{0, 0, 0}}}); }, "at least two points");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_error<InvalidInput>([&] { lines::polyline_source(m, {{Vec3{0, 0, 0}, Vec3{nan, 0, 0}}}); },
                             "point 1 is not finite");
  TriangleMesh cloud;
  cloud.positions = {{0, 0, 0}};
  expect_error<InvalidInput>([&] { lines::polyline_source(cloud, {{Vec3{0, 0, 0}, Vec3{1, 0, 0}}}); }, "");
}

TEST(LinesSource, PolylineAcrossAGapIsRefused) {
  // Two squares 10 apart: a polyline from one to the other has no surface to lie on.
  TriangleMesh m = jittered_square(3, 1);
  const TriangleMesh other = jittered_square(3, 2, Plane{{10.3, -1.2, 0.7}});
  const Index offset = Index(m.num_vertices());
  m.positions.insert(m.positions.end(), other.positions.begin(), other.positions.end());
  for (Triangle t : other.triangles) m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const Plane a, b{{10.3, -1.2, 0.7}};
  expect_error<InvalidInput>([&] { lines::polyline_source(m, {{a.at(0.5, 0.5), b.at(0.5, 0.5)}}); },
                             "closest points on the surface jump");
}

TEST(LinesSource, PiecesOfOneStraightSegmentFormOneRun) {
  const Plane pl;
  const TriangleMesh m = jittered_square(10, 3);
  const Vec3 a = pl.at(0.12, 0.2), b = pl.at(0.85, 0.7);
  const lines::LineSource src = lines::polyline_source(m, {{a, b}});
  ASSERT_GT(src.pieces.size(), 5u);
  for (const lines::SegmentPiece& p : src.pieces) {
    const Triangle& t = m.triangles[p.face];
    auto at = [&](const std::array<double, 3>& w) {
      return w[0] * m.positions[t[0]] + w[1] * m.positions[t[1]] + w[2] * m.positions[t[2]];
    };
    // before/after reach exactly the segment's ends.
    EXPECT_NEAR(p.before, distance(a, at(p.start)), 1e-12);
    EXPECT_NEAR(p.after, distance(at(p.end), b), 1e-12);
  }
}

TEST(LinesSource, BadPiecesAreRefused) {
  const TriangleMesh m = jittered_square(3, 1);
  lines::LineSource src;
  src.segments.push_back({Vec3{}, Vec3{}});
  src.pieces.push_back({99, {1, 0, 0}, {0, 1, 0}, 0});
  expect_error<InvalidInput>([&] { lines::line_distances(m, src); }, "face 99 does not exist");
  src.pieces[0] = {0, {1, 0, 0}, {0.5, 0.6, 0}, 0};
  expect_error<InvalidInput>([&] { lines::line_distances(m, src); }, "barycentric");
  src.pieces[0] = {0, {1, 0, 0}, {0, 1, 0}, 3};
  expect_error<InvalidInput>([&] { lines::line_distances(m, src); }, "segment 3 does not exist");
}

// Two unit squares touching at one corner only: the wave crosses at the shared vertex, so a
// vertex of the second square is 1 (from the bottom edge of the first up to the corner) plus its
// distance to the corner.
TEST(LinesSource, WavesCrossAVertexWhereFacesTouchWithoutAnEdge) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {2, 4, 5}, {2, 5, 6}};
  const lines::LineResult r = lines::line_distances(m, lines::edge_source(m, {{0, 1}}));
  EXPECT_NEAR(r.vertex_distance[2], 1.0, 1e-12);
  EXPECT_NEAR(r.vertex_distance[4], 2.0, 1e-12);
  EXPECT_NEAR(r.vertex_distance[5], 1.0 + std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(r.vertex_distance[6], 2.0, 1e-12);
  EXPECT_EQ(r.vertex_segment[5], 0u);
}

// A regression guard, not a timing: waves once circled vertices that are flat only to 1e-6 and
// came back a little shorter every round (370 million candidates on the bunny's boundary).
TEST(LinesSource, BunnyBoundaryCostsAFewCandidatesPerFace) {
  if (!have_shared_data()) GTEST_SKIP() << "shared meshes missing";
  const TriangleMesh m = io::read_mesh(shared_mesh("stanford_bunny.obj")).mesh;
  const lines::LineSource src = lines::boundary_source(m);
  EXPECT_EQ(src.num_segments(), 223u);
  const lines::LineResult r = lines::line_distances(m, src);
  EXPECT_LT(r.stats.candidates, 10 * m.num_faces());
  EXPECT_EQ(r.stats.faces_reached, m.num_faces());
  std::size_t reached = 0;
  for (double d : r.vertex_distance) reached += std::isfinite(d) ? 1 : 0;
  EXPECT_EQ(reached, m.num_vertices() - 1113);   // all but the unreferenced vertices
}

TEST(PolylineText, PlainPointsBlankLinesSeparate) {
  const auto lines = lines::parse_polylines("# two polylines\n0 0 0\n1 0 0\n\n\n1,1,1\n2\t2 2\n3 3 3\n", "p.txt");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].size(), 2u);
  ASSERT_EQ(lines[1].size(), 3u);
  EXPECT_EQ(lines[1][1], (Vec3{2, 2, 2}));
}

TEST(PolylineText, ObjLineElements) {
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nvn 0 0 1\nf 1 2 3\nl 1 2 3 1\nl -1 -2\n";
  const auto lines = lines::parse_polylines(obj, "p.obj");
  ASSERT_EQ(lines.size(), 2u);
  ASSERT_EQ(lines[0].size(), 4u);
  EXPECT_EQ(lines[0].front(), lines[0].back());   // closed
  EXPECT_EQ(lines[1][0], (Vec3{1, 1, 0}));
  EXPECT_EQ(lines[1][1], (Vec3{1, 0, 0}));
}

TEST(PolylineText, ErrorsNameTheLine) {
  expect_error<IoError>([] { lines::parse_polylines("", "e.txt"); }, "e.txt: no polyline");
  expect_error<IoError>([] { lines::parse_polylines("0 0 0\n1 nan 0\n", "e.txt"); }, "e.txt:line 2: \"nan\" is not a finite number");
  expect_error<IoError>([] { lines::parse_polylines("0 0 0\n1 0\n", "e.txt"); }, "line 2: expected three coordinates");
  expect_error<IoError>([] { lines::parse_polylines("0 0 0\n\n1 0 0\n2 0 0\n", "e.txt"); }, "line 2: a polyline needs at least two points");
  expect_error<IoError>([] { lines::parse_polylines("v 0 0 0\nl 1 5\n", "e.obj"); }, "line 2: vertex 5 does not exist");
  expect_error<IoError>([] { lines::parse_polylines("v 0 0 0\nv 1 0 0\nf 1 2 1\n", "e.obj"); }, "no `l` element");
}

}  // namespace
}  // namespace gsp::test
