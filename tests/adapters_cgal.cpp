// gsp::TriangleMesh <-> CGAL::Surface_mesh: round trips, refused faces, removed elements.
#include <gsp/adapters/cgal.hpp>
#include <gsp/errors.hpp>

#include "helpers/mesh_builders.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

using gsp::Index;
using gsp::Triangle;
using gsp::TriangleMesh;
using gsp::adapters::CgalSurfaceMesh;
using gsp::adapters::from_cgal;
using gsp::adapters::to_cgal;

// A halfedge structure may start a face at any corner: compare faces up to rotation (but not
// reflection, which would change the orientation).
Triangle rotated_to_smallest(Triangle t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

void expect_same_faces(const TriangleMesh& a, const TriangleMesh& b) {
  ASSERT_EQ(a.num_faces(), b.num_faces());
  for (std::size_t f = 0; f < a.num_faces(); ++f)
    EXPECT_EQ(rotated_to_smallest(a.triangles[f]), rotated_to_smallest(b.triangles[f])) << "face " << f;
}

TEST(CgalAdapter, RoundTripIsExact) {
  TriangleMesh m = gsp::test::icosphere(2);
  for (const auto& p : m.positions) m.normals.push_back(p);  // unit sphere: normal = position
  const auto converted = to_cgal(m);
  EXPECT_TRUE(converted.skipped_faces.empty());
  ASSERT_EQ(converted.face_map.size(), m.num_faces());
  for (std::size_t f = 0; f < m.num_faces(); ++f) EXPECT_EQ(converted.face_map[f], f);
  EXPECT_EQ(converted.mesh.number_of_vertices(), 162u);
  EXPECT_EQ(converted.mesh.number_of_faces(), 320u);
  EXPECT_EQ(converted.mesh.number_of_edges(), 480u);
  EXPECT_TRUE(CGAL::is_closed(converted.mesh));

  const TriangleMesh back = from_cgal(converted.mesh);
  ASSERT_EQ(back.positions.size(), m.positions.size());
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    EXPECT_EQ(back.positions[v], m.positions[v]);  // doubles both ways: bit-identical
    EXPECT_EQ(back.normals[v], m.normals[v]);
  }
  expect_same_faces(m, back);
}

TEST(CgalAdapter, BoundaryAndIsolatedVerticesKept) {
  TriangleMesh m = gsp::test::grid(3);
  m.positions.push_back({7, 7, 7});  // referenced by no face
  const auto converted = to_cgal(m);
  EXPECT_TRUE(converted.skipped_faces.empty());
  EXPECT_EQ(converted.mesh.number_of_vertices(), 17u);
  EXPECT_TRUE(converted.mesh.is_isolated(CgalSurfaceMesh::Vertex_index(16)));
  std::size_t border = 0;
  for (auto h : converted.mesh.halfedges()) border += converted.mesh.is_border(h);
  EXPECT_EQ(border, 12u);  // 4 n boundary edges
  const TriangleMesh back = from_cgal(converted.mesh);
  EXPECT_EQ(back.num_vertices(), 17u);
  EXPECT_TRUE(back.normals.empty());
  expect_same_faces(m, back);
}

// Faces a halfedge structure cannot hold are reported, not added, and do not break the rest.
TEST(CgalAdapter, ReportsRefusedFaces) {
  const auto book = to_cgal(gsp::test::book());
  EXPECT_EQ(book.skipped_faces, std::vector<Index>({2}));   // third face on the spine edge
  EXPECT_EQ(book.face_map, std::vector<Index>({0, 1}));
  EXPECT_TRUE(book.mesh.is_valid(false));

  // duplicate face 2 (reuses halfedge 0->2 of face 1), repeated index face 3, face 4 on the
  // already full halfedge 0->1 of face 0.
  const auto messy = to_cgal(gsp::test::duplicate_and_degenerate());
  EXPECT_EQ(messy.skipped_faces, std::vector<Index>({2, 3, 4}));
  EXPECT_EQ(messy.mesh.number_of_faces(), 2u);
  EXPECT_TRUE(messy.mesh.is_valid(false));

  // Inconsistent orientation: the reversed face's halfedges are all taken.
  const auto flipped = to_cgal(gsp::test::flipped_face_tetrahedron());
  EXPECT_EQ(flipped.skipped_faces, std::vector<Index>({3}));
}

TEST(CgalAdapter, SoupConvertsFaceByFace) {
  const TriangleMesh soup = gsp::test::explode(gsp::test::icosphere(1));
  const auto converted = to_cgal(soup);
  EXPECT_TRUE(converted.skipped_faces.empty());
  EXPECT_EQ(converted.mesh.number_of_faces(), 80u);
  EXPECT_EQ(converted.mesh.number_of_vertices(), 240u);
}

TEST(CgalAdapter, RemovedElementsAreSkippedAndRenumbered) {
  // Vertex 2 is isolated; removing it from the Surface_mesh (without collecting garbage)
  // leaves a hole in its indices that from_cgal must close.
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {9, 9, 9}, {1, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 3}, {0, 3, 4}};
  auto converted = to_cgal(m);
  converted.mesh.remove_vertex(CgalSurfaceMesh::Vertex_index(2));
  ASSERT_TRUE(converted.mesh.has_garbage());
  const TriangleMesh back = from_cgal(converted.mesh);
  ASSERT_EQ(back.num_vertices(), 4u);
  EXPECT_EQ(back.positions[2], m.positions[3]);
  TriangleMesh expected = m;
  expected.triangles = {{0, 1, 2}, {0, 2, 3}};
  expect_same_faces(expected, back);
}

TEST(CgalAdapter, QuadsAreFanTriangulated) {
  CgalSurfaceMesh sm;
  const auto a = sm.add_vertex({0, 0, 0}), b = sm.add_vertex({1, 0, 0}), c = sm.add_vertex({1, 1, 0}),
             d = sm.add_vertex({0, 1, 0});
  ASSERT_NE(sm.add_face(a, b, c, d), CgalSurfaceMesh::null_face());
  const TriangleMesh back = from_cgal(sm);
  ASSERT_EQ(back.num_faces(), 2u);
  double area = 0;
  for (const auto& t : back.triangles) {
    const auto n = gsp::cross(back.positions[t[1]] - back.positions[t[0]], back.positions[t[2]] - back.positions[t[0]]);
    EXPECT_GT(n.z, 0);  // orientation kept
    area += 0.5 * gsp::norm(n);
  }
  EXPECT_NEAR(area, 1.0, 1e-15);
}

TEST(CgalAdapter, RejectsInvalidIndices) {
  TriangleMesh m = gsp::test::quad();
  m.triangles.push_back({0, 1, 4});
  EXPECT_THROW(to_cgal(m), gsp::InvalidInput);
}

}  // namespace
