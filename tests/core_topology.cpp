// analyze_topology and degenerate_faces on meshes built in code, whose counts follow from
// their construction (see helpers/mesh_builders.hpp).
#include <gsp/topology.hpp>

#include <gtest/gtest.h>

#include "helpers/mesh_builders.hpp"

namespace gsp {
namespace {

TopologyReport report(const TriangleMesh& m) { return analyze_topology(m, build_connectivity(m)); }

// Six times the signed volume enclosed by a closed mesh: positive when faces point outwards.
double signed_volume6(const TriangleMesh& m) {
  double v = 0;
  for (const Triangle& t : m.triangles)
    v += dot(m.positions[t[0]], cross(m.positions[t[1]], m.positions[t[2]]));
  return v;
}

TEST(CoreTopology, EmptyMesh) {
  const TopologyReport r = report(TriangleMesh{});
  EXPECT_EQ(r.vertices, 0u);
  EXPECT_EQ(r.faces, 0u);
  EXPECT_EQ(r.components, 0u);
  EXPECT_EQ(r.euler_characteristic, 0);
  EXPECT_TRUE(r.is_manifold());
}

TEST(CoreTopology, PointCloudHasOnlyIsolatedVertices) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 2, 3}, {4, 5, 6}};
  const TopologyReport r = report(m);
  EXPECT_EQ(r.isolated_vertices, 3u);
  EXPECT_EQ(r.components, 0u);
  EXPECT_EQ(r.edges, 0u);
  EXPECT_EQ(r.euler_characteristic, 0);
}

TEST(CoreTopology, SingleTriangle) {
  const TopologyReport r = report(test::single_triangle());
  EXPECT_EQ(r.vertices, 3u);
  EXPECT_EQ(r.faces, 1u);
  EXPECT_EQ(r.edges, 3u);
  EXPECT_EQ(r.boundary_edges, 3u);
  EXPECT_EQ(r.boundary_loops, 1u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.euler_characteristic, 1);
  EXPECT_TRUE(r.is_manifold());
  EXPECT_FALSE(r.is_closed());
}

TEST(CoreTopology, Quad) {
  const TopologyReport r = report(test::quad());
  EXPECT_EQ(r.edges, 5u);
  EXPECT_EQ(r.boundary_edges, 4u);
  EXPECT_EQ(r.boundary_loops, 1u);
  EXPECT_EQ(r.inconsistent_edges, 0u);
  EXPECT_EQ(r.euler_characteristic, 1);
}

TEST(CoreTopology, GridIsADisk) {
  for (int n : {1, 2, 7, 20}) {
    const TopologyReport r = report(test::grid(n));
    const std::size_t nn = static_cast<std::size_t>(n);
    EXPECT_EQ(r.vertices, (nn + 1) * (nn + 1)) << n;
    EXPECT_EQ(r.faces, 2 * nn * nn) << n;
    EXPECT_EQ(r.edges, 3 * nn * nn + 2 * nn) << n;
    EXPECT_EQ(r.boundary_edges, 4 * nn) << n;
    EXPECT_EQ(r.boundary_loops, 1u) << n;
    EXPECT_EQ(r.components, 1u) << n;
    EXPECT_EQ(r.nonmanifold_vertices, 0u) << n;
    EXPECT_EQ(r.inconsistent_edges, 0u) << n;
    EXPECT_EQ(r.euler_characteristic, 1) << n;
  }
}

TEST(CoreTopology, TetrahedronIsAClosedSphere) {
  const TriangleMesh m = test::tetrahedron();
  const TopologyReport r = report(m);
  EXPECT_EQ(r.edges, 6u);
  EXPECT_TRUE(r.is_closed());
  EXPECT_TRUE(r.is_manifold());
  EXPECT_EQ(r.inconsistent_edges, 0u);
  EXPECT_EQ(r.boundary_loops, 0u);
  EXPECT_EQ(r.euler_characteristic, 2);
  EXPECT_GT(signed_volume6(m), 0.0);  // the builder's promise: outward faces
}

TEST(CoreTopology, IcosphereCounts) {
  for (int k = 0; k <= 3; ++k) {
    const TriangleMesh m = test::icosphere(k);
    const TopologyReport r = report(m);
    const std::size_t p = std::size_t{1} << (2 * k);  // 4^k
    EXPECT_EQ(r.vertices, 10 * p + 2) << k;
    EXPECT_EQ(r.faces, 20 * p) << k;
    EXPECT_EQ(r.edges, 30 * p) << k;
    EXPECT_TRUE(r.is_closed()) << k;
    EXPECT_TRUE(r.is_manifold()) << k;
    EXPECT_EQ(r.inconsistent_edges, 0u) << k;
    EXPECT_EQ(r.euler_characteristic, 2) << k;
    EXPECT_GT(signed_volume6(m), 0.0) << k;
  }
}

TEST(CoreTopology, CylinderHasTwoBoundaryLoops) {
  const TopologyReport r = report(test::cylinder(12, 5));
  EXPECT_EQ(r.vertices, 72u);
  EXPECT_EQ(r.faces, 120u);
  EXPECT_EQ(r.boundary_edges, 24u);
  EXPECT_EQ(r.boundary_loops, 2u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.euler_characteristic, 0);
  EXPECT_TRUE(r.is_manifold());
}

TEST(CoreTopology, StripIsADisk) {
  const TopologyReport r = report(test::strip(6));
  EXPECT_EQ(r.vertices, 14u);
  EXPECT_EQ(r.boundary_edges, 14u);
  EXPECT_EQ(r.boundary_loops, 1u);
  EXPECT_EQ(r.euler_characteristic, 1);
}

TEST(CoreTopology, BookHasANonManifoldEdge) {
  const TopologyReport r = report(test::book());
  EXPECT_EQ(r.edges, 7u);
  EXPECT_EQ(r.nonmanifold_edges, 1u);
  EXPECT_EQ(r.nonmanifold_vertices, 2u);
  EXPECT_EQ(r.boundary_edges, 6u);
  EXPECT_EQ(r.boundary_loops, 1u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.euler_characteristic, 5 - 7 + 3);
  EXPECT_FALSE(r.is_manifold());
}

TEST(CoreTopology, BowtieHasANonManifoldVertexOnly) {
  const TopologyReport r = report(test::bowtie());
  EXPECT_EQ(r.nonmanifold_edges, 0u);
  EXPECT_EQ(r.nonmanifold_vertices, 1u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.boundary_loops, 1u);
  EXPECT_EQ(r.euler_characteristic, 5 - 6 + 2);
  EXPECT_FALSE(r.is_manifold());
}

TEST(CoreTopology, TwoTrianglesSharingAVertexFromTwoSidesOfAFan) {
  // A closed fan (the tetrahedron) around vertex 0 is one fan; removing the face opposite
  // keeps one open fan; a vertex with a closed fan plus an extra triangle has two.
  TriangleMesh m = test::tetrahedron();
  m.positions.push_back({3, 3, 3});
  m.positions.push_back({3, 4, 3});
  m.triangles.push_back({0, 4, 5});
  const TopologyReport r = report(m);
  EXPECT_EQ(r.nonmanifold_vertices, 1u);
  EXPECT_EQ(r.nonmanifold_edges, 0u);
  EXPECT_EQ(r.components, 1u);
}

TEST(CoreTopology, FlippedFaceGivesInconsistentEdges) {
  const TopologyReport r = report(test::flipped_face_tetrahedron());
  EXPECT_EQ(r.inconsistent_edges, 3u);
  EXPECT_TRUE(r.is_manifold());
  EXPECT_TRUE(r.is_closed());
  EXPECT_EQ(r.euler_characteristic, 2);
}

TEST(CoreTopology, DuplicateAndDegenerateFaces) {
  const TriangleMesh m = test::duplicate_and_degenerate();
  const TopologyReport r = report(m);
  EXPECT_EQ(r.vertices, 6u);
  EXPECT_EQ(r.faces, 5u);
  EXPECT_EQ(r.edges, 7u);
  EXPECT_EQ(r.boundary_edges, 3u);
  EXPECT_EQ(r.boundary_loops, 1u);
  EXPECT_EQ(r.nonmanifold_edges, 3u);
  EXPECT_EQ(r.nonmanifold_vertices, 4u);
  EXPECT_EQ(r.inconsistent_edges, 0u);
  EXPECT_EQ(r.duplicate_faces, 1u);
  EXPECT_EQ(r.repeated_index_faces, 1u);
  EXPECT_EQ(r.zero_area_faces, 1u);
  EXPECT_EQ(r.isolated_vertices, 1u);
  EXPECT_EQ(r.components, 1u);
  EXPECT_EQ(r.euler_characteristic, 3);
  EXPECT_EQ(degenerate_faces(m), (std::vector<bool>{false, false, false, true, true}));
}

TEST(CoreTopology, DuplicateFacesIgnoreOrderAndOrientation) {
  TriangleMesh m = test::single_triangle();
  m.triangles = {{0, 1, 2}, {1, 2, 0}, {2, 1, 0}, {0, 2, 1}};
  const TopologyReport r = report(m);
  EXPECT_EQ(r.duplicate_faces, 3u);
  EXPECT_EQ(r.nonmanifold_edges, 3u);
}

TEST(CoreTopology, ZeroAreaThresholdScalesWithTheModel) {
  // A sliver of base s and height h: area s h / 2, bbox diagonal^2 = s^2 + h^2, so the rule
  // area <= 1e-12 diag^2 holds for h = 1e-13 s and fails for h = 1e-11 s, at any scale s.
  for (double scale : {1e-6, 1.0, 1e6}) {
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {scale, 0, 0}, {0.5 * scale, 1e-13 * scale, 0}};
    m.triangles = {{0, 1, 2}};
    EXPECT_EQ(report(m).zero_area_faces, 1u) << scale;
    m.positions[2].y = 1e-11 * scale;
    EXPECT_EQ(report(m).zero_area_faces, 0u) << scale;
  }
}

TEST(CoreTopology, RepeatedIndexFacesAreNotZeroArea) {
  TriangleMesh m = test::single_triangle();
  m.triangles = {{0, 0, 1}, {2, 2, 2}};
  const TopologyReport r = report(m);
  EXPECT_EQ(r.repeated_index_faces, 2u);
  EXPECT_EQ(r.zero_area_faces, 0u);
  EXPECT_EQ(r.edges, 1u);  // 0-1; the loops 0-0 and 2-2 are not edges
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(degenerate_faces(m), (std::vector<bool>{true, true}));
}

TEST(CoreTopology, ComponentsCountSeparatePieces) {
  TriangleMesh m = test::tetrahedron();
  const TriangleMesh g = test::grid(3);
  const Index offset = static_cast<Index>(m.positions.size());
  m.positions.insert(m.positions.end(), g.positions.begin(), g.positions.end());
  for (Triangle t : g.triangles) m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const TopologyReport r = report(m);
  EXPECT_EQ(r.components, 2u);
  EXPECT_EQ(r.boundary_loops, 1u);
  EXPECT_EQ(r.euler_characteristic, 3);
}

}  // namespace
}  // namespace gsp
