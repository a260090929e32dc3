// gsp::cvt component helpers: the split into components, per-component topology and
// orientability, consistent orientation, duplicate vertices, the per-component comparison.
#include "cvt_components.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/cvt/components.hpp>
#include <gsp/topology.hpp>

#include <gtest/gtest.h>

namespace {

using namespace gsp;
using test::add;
using test::moebius;

TEST(CvtComponents, SplitCountsAndTopology) {
  TriangleMesh m = test::icosphere(1);
  add(m, test::grid(3), 1.0, {5, 0, 0});
  add(m, test::book(), 1.0, {-5, 0, 0});
  const cvt::ComponentSplit s = cvt::split_components(m);
  ASSERT_EQ(s.meshes.size(), 3u);
  EXPECT_EQ(s.meshes[0].num_faces(), 80u);
  EXPECT_EQ(s.meshes[1].num_vertices(), 16u);
  EXPECT_EQ(s.meshes[2].num_faces(), 3u);
  EXPECT_EQ(s.face_ids[2][0], 80u + 18u);
  EXPECT_EQ(s.vertex_ids[1][0], 42u);
  const cvt::ComponentTopology sphere = cvt::component_topology(s.meshes[0]);
  EXPECT_EQ(sphere.report.euler_characteristic, 2);
  EXPECT_TRUE(sphere.orientable);
  const cvt::ComponentTopology grid = cvt::component_topology(s.meshes[1]);
  EXPECT_EQ(grid.report.boundary_loops, 1u);
  EXPECT_NEAR(grid.area, 9.0, 1e-12);
  EXPECT_FALSE(cvt::component_topology(s.meshes[2]).report.is_manifold());
}

// Doubled faces (either orientation) and faces with a repeated vertex are left out, the first
// of equal faces kept, the others in order; the vertices stay as they were.
TEST(CvtComponents, DuplicateFacesDropped) {
  TriangleMesh m = test::tetrahedron();
  m.triangles.push_back(m.triangles[2]);                                       // face 4: a copy of 2
  m.triangles.push_back({m.triangles[0][0], m.triangles[0][2], m.triangles[0][1]});   // 5: 0 reversed
  m.triangles.push_back({1, 2, 1});                                            // 6: a repeated vertex
  m.triangles.push_back(m.triangles[3]);                                       // 7: a copy of 3
  const cvt::FaceCleanup c = cvt::drop_duplicate_faces(m);
  EXPECT_EQ(c.duplicate_faces, 3u);
  EXPECT_EQ(c.repeated_vertex_faces, 1u);
  EXPECT_EQ(c.face_source, (std::vector<Index>{0, 1, 2, 3}));
  ASSERT_EQ(c.mesh.num_faces(), 4u);
  for (std::size_t f = 0; f < 4; ++f) EXPECT_EQ(c.mesh.triangles[f], m.triangles[f]);
  EXPECT_EQ(c.mesh.positions.size(), m.positions.size());
  const TopologyReport t = analyze_topology(c.mesh, build_connectivity(c.mesh));
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.euler_characteristic, 2);
}

// A seam: the icosphere exploded into one vertex per corner (as an OBJ exporter splits at
// texture seams) is stitched back into the sphere; and two tetrahedra sharing a vertex
// position (interior vertices, no boundary) are left apart.
TEST(CvtComponents, BoundaryVerticesAtOnePositionAreStitched) {
  const TriangleMesh sphere = test::icosphere(1);
  TriangleMesh soup;
  for (const Triangle& t : sphere.triangles) {
    const Index base = Index(soup.positions.size());
    for (Index v : t) soup.positions.push_back(sphere.positions[v]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  const cvt::VertexStitch s = cvt::stitch_boundary_vertices(soup);
  EXPECT_EQ(s.stitched, soup.num_vertices() - sphere.num_vertices());
  ASSERT_EQ(s.mesh.num_vertices(), sphere.num_vertices());
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) EXPECT_EQ(s.mesh.positions[s.vertex_map[v]], soup.positions[v]);
  const TopologyReport t = analyze_topology(s.mesh, build_connectivity(s.mesh));
  EXPECT_TRUE(t.is_manifold());
  EXPECT_TRUE(t.is_closed());
  EXPECT_EQ(t.euler_characteristic, 2);

  TriangleMesh two = test::tetrahedron();
  const TriangleMesh other = test::tetrahedron();
  add(two, other, 1.0, two.positions[0] - other.positions[1]);   // its vertex 1 on the first's vertex 0
  ASSERT_EQ(two.positions[4 + 1], two.positions[0]);
  const cvt::VertexStitch apart = cvt::stitch_boundary_vertices(two);
  EXPECT_EQ(apart.stitched, 0u);
  EXPECT_EQ(apart.mesh.triangles, two.triangles);
  // What remesh_surface works on and gsp-cvt-compare measures against: the sphere again.
  const TriangleMesh d = cvt::described_surface(soup);
  EXPECT_EQ(d.num_vertices(), sphere.num_vertices());
  EXPECT_EQ(analyze_topology(d, build_connectivity(d)).euler_characteristic, 2);
}

TEST(CvtComponents, OrientationAndDuplicates) {
  TriangleMesh t = test::flipped_face_tetrahedron();
  EXPECT_EQ(cvt::orient_consistently(t), 1);   // the reversed face, against the first face's choice
  EXPECT_EQ(analyze_topology(t, build_connectivity(t)).inconsistent_edges, 0u);
  TriangleMesh mo = moebius(12);
  const TriangleMesh before = mo;
  EXPECT_EQ(cvt::orient_consistently(mo), -1);
  EXPECT_EQ(mo.triangles, before.triangles);   // left as it was
  EXPECT_FALSE(cvt::component_topology(mo).orientable);

  TriangleMesh d = test::quad();
  EXPECT_EQ(cvt::duplicate_vertices(d), 0u);
  d.positions.push_back(d.positions[2]);   // a second component with a corner on vertex 2
  d.positions.push_back({3, 0, 0});
  d.positions.push_back({3, 1, 0});
  d.triangles.push_back({4, 5, 6});
  EXPECT_EQ(cvt::duplicate_vertices(d), 1u);
  std::string why;
  EXPECT_FALSE(cvt::same_topology_per_component(test::quad(), d, &why));
  EXPECT_EQ(why, "1 duplicate vertices");
  EXPECT_TRUE(cvt::same_topology_per_component(test::quad(), test::grid(2), &why));
  EXPECT_FALSE(cvt::same_topology_per_component(test::icosphere(1), test::grid(2), &why));
}

}  // namespace
