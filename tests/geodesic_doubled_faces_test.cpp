// Doubled faces: a copy of a face (the same three vertices, any order or orientation, as STL
// exports and soups have them) is left out by every propagation, so the field is the one of the
// mesh without the copies. Before, each copy was glued to all three edges of its original and
// sources bounced between the two: a 9,874-vertex CAD part with 5% of its faces doubled ran out
// of memory after 156 s (22 GB).
#include "helpers/geodesic_fixtures.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/intrinsic/edge_lengths.hpp>
#include <gsp/lines/line_distances.hpp>
#include <gsp/window_geodesics.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace gsp::test {
namespace {

// m with every `step`-th face copied at the end: the copies in turn as they were, flipped and
// rotated, so every way of naming the same three vertices occurs.
TriangleMesh with_copies(const TriangleMesh& m, std::size_t step, std::size_t& copies) {
  TriangleMesh d = m;
  copies = 0;
  for (std::size_t f = 0; f < m.num_faces(); f += step, ++copies) {
    Triangle t = m.triangles[f];
    if (copies % 3 == 1) std::swap(t[1], t[2]);
    if (copies % 3 == 2) t = {t[1], t[2], t[0]};
    d.triangles.push_back(t);
  }
  return d;
}

TEST(DoubledFaces, AreFoundOnTheNonManifoldEdgesOnly) {
  const TriangleMesh m = icosphere(2);
  std::size_t copies = 0;
  TriangleMesh d = with_copies(m, 5, copies);
  d.triangles.push_back(d.triangles[0]);   // a third copy of face 0
  const Connectivity conn = build_connectivity(d);
  EXPECT_FALSE(conn.nonmanifold_edges.empty());
  EXPECT_TRUE(build_connectivity(m).nonmanifold_edges.empty());
  const std::vector<bool> skipped = intrinsic::skipped_faces(d, conn);
  EXPECT_EQ(std::size_t(std::count(skipped.begin(), skipped.end(), true)), copies + 1);
  for (std::size_t f = 0; f < m.num_faces(); ++f) EXPECT_FALSE(skipped[f]) << f;   // the originals stay
  // A point of a copy is the same point of the face kept.
  const Index copy = Index(m.num_faces() + 2);   // face 10, rotated
  std::array<double, 3> b{0.2, 0.3, 0.5};
  const Index kept = intrinsic::kept_copy(d.triangles, conn.vertex_corner_begin, conn.vertex_corners, skipped, copy, b);
  EXPECT_EQ(kept, 10u);
  const SurfacePoint in_copy = SurfacePoint::in_face(copy, {0.2, 0.3, 0.5});
  const SurfacePoint in_kept = SurfacePoint::in_face(kept, b);
  EXPECT_LT(distance(in_copy.position(d), in_kept.position(d)), 1e-15);
  // The solver says the same per input face, whatever its memory layout (sampling reads it).
  d.triangles.push_back({0, 0, 1});   // a face naming a vertex twice
  const std::vector<bool> all = intrinsic::skipped_faces(d, build_connectivity(d));
  for (bool layout : {false, true}) {
    SolverOptions so;
    so.optimize_layout = layout;
    const GeodesicSolver solver(d, so);
    for (std::size_t f = 0; f < d.num_faces(); ++f) EXPECT_EQ(solver.face_takes_part(Index(f)), !all[f]) << f;
    EXPECT_FALSE(solver.face_takes_part(Index(d.num_faces())));
  }
}

TEST(DoubledFaces, GiveTheFieldOfTheMeshWithoutThem) {
  const TriangleMesh m = icosphere(3);
  std::size_t copies = 0;
  const TriangleMesh d = with_copies(m, 7, copies);
  for (bool layout : {false, true}) {
    SolverOptions so;
    so.optimize_layout = layout;
    const GeodesicSolver a(m, so), b(d, so);
    EXPECT_EQ(a.duplicate_faces(), 0u);
    EXPECT_EQ(b.duplicate_faces(), copies);
    GeodesicOptions o;
    o.want_face_sources = true;
    o.threads = 1;
    const GeodesicResult ra = a.compute({Source::at_vertex(5)}, o), rb = b.compute({Source::at_vertex(5)}, o);
    ASSERT_EQ(rb.vertex_distance.size(), m.num_vertices());
    // Without a layout the same faces in the same order: the same arithmetic. A layout of the
    // longer face list may order the work differently (GSP's order effects, ~0.05%).
    const double tol = layout ? 1e-2 : 1e-12;
    for (std::size_t v = 0; v < m.num_vertices(); ++v)
      EXPECT_LE(std::abs(rb.vertex_distance[v] - ra.vertex_distance[v]), tol * ra.vertex_distance[v] + 1e-12) << v;
    // A copy reads as its original: its distance, label and virtual source.
    for (std::size_t k = 0; k < copies; ++k) {
      const std::size_t copy = m.num_faces() + k, original = 7 * k;
      EXPECT_EQ(rb.face_distance[copy], rb.face_distance[original]) << k;
      EXPECT_EQ(rb.face_source[copy], rb.face_source[original]) << k;
      EXPECT_EQ(rb.face_sources[copy].sigma, rb.face_sources[original].sigma) << k;
      EXPECT_EQ(distance(rb.face_sources[copy].position, rb.face_sources[original].position), 0.0) << k;
    }
    // A source in a copy is the same point in its original (it was dropped before).
    const Index copy = Index(m.num_faces() + 3);   // face 21, as it was
    const GeodesicResult in_copy = b.compute({Source::in_face(copy, {0.2, 0.3, 0.5})}, o);
    const GeodesicResult in_original = b.compute({Source::in_face(21, {0.2, 0.3, 0.5})}, o);
    for (std::size_t v = 0; v < m.num_vertices(); ++v) {
      ASSERT_TRUE(std::isfinite(in_copy.vertex_distance[v])) << v;
      EXPECT_EQ(in_copy.vertex_distance[v], in_original.vertex_distance[v]) << v;
    }
  }
}

TEST(DoubledFaces, AreLeftOutByTheWindowsAndTheLineSources) {
  const TriangleMesh m = icosphere(3);
  std::size_t copies = 0;
  const TriangleMesh d = with_copies(m, 7, copies);
  const std::vector<double> wa = WindowGeodesics(m).distances_from_vertex(5);
  const WindowGeodesics wd(d);
  const std::vector<double> wb = wd.distances_from_vertex(5);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) EXPECT_NEAR(wb[v], wa[v], 1e-12) << v;
  // The windows' face-point source in a copy (on the input faces): in its original.
  const WindowGeodesics on_input(d, false);
  const WindowField in_copy = on_input.field({Source::in_face(Index(m.num_faces() + 3), {0.2, 0.3, 0.5})});
  const WindowField in_original = on_input.field({Source::in_face(21, {0.2, 0.3, 0.5})});
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    EXPECT_NEAR(in_copy.vertex_distance[v], in_original.vertex_distance[v], 1e-12) << v;

  const Index e0 = m.triangles[0][0], e1 = m.triangles[0][1];   // an edge of a doubled face
  const lines::LineResult la = lines::line_distances(m, lines::edge_source(m, {{e0, e1}}));
  const lines::LineResult lb = lines::line_distances(d, lines::edge_source(d, {{e0, e1}}));
  for (std::size_t v = 0; v < m.num_vertices(); ++v) EXPECT_NEAR(lb.vertex_distance[v], la.vertex_distance[v], 1e-12) << v;
}

}  // namespace
}  // namespace gsp::test
