// gsp::TriangleMesh <-> OpenMesh TriMesh (float and double kernels): round trips, refused
// faces, deleted elements.
#include <gsp/adapters/openmesh.hpp>
#include <gsp/errors.hpp>

#include "helpers/mesh_builders.hpp"

#include <OpenMesh/Core/System/omstream.hh>
#include <gtest/gtest.h>

#include <algorithm>

namespace {

using gsp::Index;
using gsp::Triangle;
using gsp::TriangleMesh;
using namespace gsp::adapters;

Triangle rotated_to_smallest(Triangle t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

void expect_same_faces(const TriangleMesh& a, const TriangleMesh& b) {
  ASSERT_EQ(a.num_faces(), b.num_faces());
  for (std::size_t f = 0; f < a.num_faces(); ++f)
    EXPECT_EQ(rotated_to_smallest(a.triangles[f]), rotated_to_smallest(b.triangles[f])) << "face " << f;
}

TEST(OpenMeshAdapter, DoubleRoundTripIsExact) {
  TriangleMesh m = gsp::test::icosphere(2);
  for (const auto& p : m.positions) m.normals.push_back(p);
  const auto converted = to_openmesh_double(m);
  EXPECT_TRUE(converted.skipped_faces.empty());
  EXPECT_EQ(converted.mesh.n_vertices(), 162u);
  EXPECT_EQ(converted.mesh.n_faces(), 320u);
  EXPECT_EQ(converted.mesh.n_edges(), 480u);
  ASSERT_TRUE(converted.mesh.has_vertex_normals());
  const TriangleMesh back = from_openmesh(converted.mesh);
  ASSERT_EQ(back.num_vertices(), m.num_vertices());
  ASSERT_EQ(back.normals.size(), m.num_vertices());
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    EXPECT_EQ(back.positions[v], m.positions[v]);
    EXPECT_EQ(back.normals[v], m.normals[v]);
  }
  expect_same_faces(m, back);
}

// Rounded through a float variable in memory: GCC 12 at -O3 was seen to drop an inline
// double(float(x)) round trip inside the comparison below.
double to_float_precision(double x) {
  volatile float f = static_cast<float>(x);
  return f;
}

TEST(OpenMeshAdapter, FloatRoundTripRoundsToFloat) {
  const TriangleMesh m = gsp::test::icosphere(1);
  const auto converted = to_openmesh(m);
  const TriangleMesh back = from_openmesh(converted.mesh);
  ASSERT_EQ(back.num_vertices(), m.num_vertices());
  EXPECT_TRUE(back.normals.empty());
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const auto& p = m.positions[v];
    EXPECT_EQ(back.positions[v],
              (gsp::Vec3{to_float_precision(p.x), to_float_precision(p.y), to_float_precision(p.z)}));
    EXPECT_LE(gsp::distance(back.positions[v], p), 1e-7);
  }
  expect_same_faces(m, back);
}

TEST(OpenMeshAdapter, ReportsRefusedFacesWithoutPrinting) {
  testing::internal::CaptureStderr();
  testing::internal::CaptureStdout();
  const auto book = to_openmesh(gsp::test::book());
  const auto messy = to_openmesh_double(gsp::test::duplicate_and_degenerate());
  const auto flipped = to_openmesh(gsp::test::flipped_face_tetrahedron());
  const std::string err = testing::internal::GetCapturedStderr();
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(book.skipped_faces, std::vector<Index>({2}));
  EXPECT_EQ(book.face_map, std::vector<Index>({0, 1}));
  EXPECT_EQ(messy.skipped_faces, std::vector<Index>({2, 3, 4}));
  EXPECT_EQ(messy.mesh.n_faces(), 2u);
  EXPECT_EQ(flipped.skipped_faces, std::vector<Index>({3}));
  EXPECT_EQ(err, "");
  EXPECT_EQ(out, "");
  EXPECT_TRUE(::omerr().is_enabled());  // muted only during the conversion
}

TEST(OpenMeshAdapter, IsolatedKeptDeletedSkipped) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {9, 9, 9}, {1, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 3}, {0, 3, 4}};
  auto converted = to_openmesh_double(m);
  EXPECT_EQ(converted.mesh.n_vertices(), 5u);
  EXPECT_EQ(from_openmesh(converted.mesh).num_vertices(), 5u);

  OpenMeshTriMeshD& om = converted.mesh;
  om.request_vertex_status();
  om.request_edge_status();
  om.request_face_status();
  om.delete_vertex(OpenMesh::VertexHandle(2));
  const TriangleMesh back = from_openmesh(om);
  ASSERT_EQ(back.num_vertices(), 4u);
  EXPECT_EQ(back.positions[2], m.positions[3]);
  TriangleMesh expected;
  expected.triangles = {{0, 1, 2}, {0, 2, 3}};
  expect_same_faces(expected, back);
}

TEST(OpenMeshAdapter, RejectsInvalidIndices) {
  TriangleMesh m = gsp::test::quad();
  m.triangles.push_back({0, 1, 4});
  EXPECT_THROW(to_openmesh(m), gsp::InvalidInput);
}

}  // namespace
