// The angle-raising post-pass of the dual (RemeshOptions::smooth: boundary collapses, vertex
// moves along the input surface, flips): on the same CVT it never lowers the minimum angle,
// keeps every vertex on the input surface and boundary vertices on its boundary, keeps the
// topology, and does not move the surface away from the input.
#include "cvt_meshes.hpp"
#include "test_data.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/cvt/closest_point_index.hpp>
#include <gsp/cvt/cvt.hpp>
#include <gsp/cvt/quality.hpp>
#include <gsp/cvt/remesh.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/topology.hpp>

#include <gtest/gtest.h>

#include <cstdio>

namespace {

using namespace gsp;

struct Measured {
  double min_angle_before, min_angle_after, hausdorff_before, hausdorff_after;
  std::size_t insertions;
};

Measured check_smoothing(const TriangleMesh& mesh, std::size_t sites) {
  cvt::CvtOptions o;
  o.sites = sites;
  const cvt::CvtResult cvt = cvt::compute_cvt(mesh, o);
  cvt::RemeshOptions plain;
  plain.smooth = false;
  const cvt::RemeshResult a = cvt::restricted_delaunay(cvt, plain);
  const cvt::RemeshResult b = cvt::restricted_delaunay(cvt);
  const TopologyReport ta = analyze_topology(a.mesh, build_connectivity(a.mesh));
  const TopologyReport tb = analyze_topology(b.mesh, build_connectivity(b.mesh));
  EXPECT_TRUE(tb.is_manifold());
  EXPECT_EQ(tb.inconsistent_edges, 0u);
  EXPECT_EQ(tb.euler_characteristic, ta.euler_characteristic);
  EXPECT_EQ(tb.boundary_loops, ta.boundary_loops);
  EXPECT_EQ(tb.isolated_vertices, 0u);
  EXPECT_EQ(b.mesh.num_vertices() + b.stats.boundary_collapses,
            a.mesh.num_vertices() + b.stats.boundary_splits + b.stats.far_point_insertions);
  EXPECT_LE(b.stats.far_point_insertions, cvt.sites.size() / 50);
  EXPECT_LE(b.stats.boundary_collapses + b.stats.boundary_splits, sites / 50);
  EXPECT_EQ(b.vertex_site.size(), b.mesh.num_vertices());

  // Every vertex on the input surface (moves end with a closest-point projection, boundary
  // slides on the boundary polyline).
  const cvt::ClosestPointIndex index(mesh);
  double worst = 0;
  for (const Vec3& p : b.mesh.positions) worst = std::max(worst, index.closest(p).distance);
  EXPECT_LE(worst, 1e-6 * cvt.diagonal);

  const cvt::MeshQuality qa = cvt::measure_mesh_quality(a.mesh), qb = cvt::measure_mesh_quality(b.mesh);
  cvt::HausdorffOptions ho;
  ho.samples = 30000;
  const double ha = cvt::hausdorff_distance(mesh, a.mesh, ho).relative;
  const double hb = cvt::hausdorff_distance(mesh, b.mesh, ho).relative;
  EXPECT_GE(qb.min_angle, qa.min_angle);
  EXPECT_LE(qb.below_30, qa.below_30);
  EXPECT_EQ(qb.degenerate, 0u);
  // The moves keep the surface within max(before, 0.2% of the diagonal) locally.
  EXPECT_LE(hb, std::max(ha, 0.002) * 1.05);
  std::printf("[ measured ] min angle %.2f -> %.2f, below 30 %.3f%% -> %.3f%%, Hausdorff %.3f%% -> %.3f%%, "
              "%zu moves (%zu boundary), %zu collapses, %zu splits, %zu snaps, %zu insertions\n",
              qa.min_angle, qb.min_angle, 100 * qa.below_30, 100 * qb.below_30, 100 * ha, 100 * hb,
              b.stats.smoothing_moves, b.stats.smoothing_boundary_moves, b.stats.boundary_collapses,
              b.stats.boundary_splits, b.stats.boundary_snaps, b.stats.far_point_insertions);
  return {qa.min_angle, qb.min_angle, ha, hb, b.stats.far_point_insertions};
}

TEST(CvtSmoothing, CamelheadRaisesTheMinimumAngle) {
  if (!test::have_shared_data()) GTEST_SKIP() << "no shared meshes";
  const Measured m = check_smoothing(io::read_mesh(test::shared_mesh("camelhead.off")).mesh, 2000);
  // At 2,000 sites the worst triangles sit in the mouth slit, whose two sheets are closer than
  // an edge; measured 11.3 -> 13.4, 10.1 -> 18.0 and 10.1 -> 17.7 degrees (the sites moved with the core);
  // 10.6 -> 19.2 (Hausdorff 0.94% -> 0.79%) since the cap flips check all the input under the pair.
  EXPECT_GT(m.min_angle_after, m.min_angle_before + 1.0);
  EXPECT_GE(m.min_angle_after, 12.0);
}

TEST(CvtSmoothing, BunnyHoles) {
  if (!test::have_shared_data()) GTEST_SKIP() << "no shared meshes";
  check_smoothing(io::read_mesh(test::shared_mesh("stanford_bunny.obj")).mesh, 2000);
}

TEST(CvtSmoothing, FalconThinFoldsLoseTheirCaps) {
  // Closed genus 0 with thin talons: the dual folds over them in caps (angles near 180
  // degrees) that the cap flips and the moves that turn slivers over remove.
  if (!test::have_shared_data()) GTEST_SKIP() << "no shared meshes";
  // Measured 2.7 -> 7.7 degrees at 2,000 sites (2.2 -> 19.9 at 10,000, docs/cvt.md); 2.3 -> 5.4
  // since the core carries sources straight past convex vertices (other sites, other caps);
  // 2.48 -> 18.78 since the moves may turn slivers and folded triangles over (a fold along the
  // base's bottom rim that the cap flips cannot remove: four nearly collinear vertices).
  // Its talon tips (one input vertex each, 0.03 beyond a neck 0.006 wide) are cut by the dual:
  // the insertions at far input points (RemeshOptions::refine_distance) put vertices on them.
  // Hausdorff (30,000 samples) 1.166% -> 1.135% without them, -> 1.012% with them (40
  // insertions, the cap of 2% of the sites; 20.34 degrees).
  // Since the long edges are bisected on the input before the uniform split, the dual itself
  // has no caps left here (21.0 degrees before the post-pass, 20.9 after: the insertions may
  // lower the minimum by their slack), so this checks that the post-pass keeps it.
  const Measured m = check_smoothing(io::read_mesh(test::shared_mesh("falconstatue.obj")).mesh, 2000);
  EXPECT_GE(m.min_angle_after, 15.0);
  EXPECT_GE(m.min_angle_after, m.min_angle_before - 1.0);
  EXPECT_GT(m.insertions, 0u);
  EXPECT_LT(m.hausdorff_after, 0.0108);
}

TEST(CvtSmoothing, FlatSquareKeepsItsBoundary) {
  // Boundary vertices slide along the square's sides; the corners the dual cut stay cut but
  // no more (the chord check).
  check_smoothing(test::square_grid(30), 200);
}

// RemeshOptions::accept_dual sees the dual before the flips and the post-pass; refused, the
// dual comes back as it is (the same triangles as with both off), accepted, the post-pass runs.
TEST(CvtSmoothing, RefusedDualSkipsTheFlipsAndThePostPass) {
  const TriangleMesh m = test::square_grid(30);
  cvt::CvtOptions o;
  o.sites = 200;
  o.max_iterations = 5;
  const cvt::CvtResult cvt = cvt::compute_cvt(m, o);
  cvt::RemeshOptions raw;
  raw.flip_edges = false;
  raw.smooth = false;
  const cvt::RemeshResult plain = cvt::restricted_delaunay(cvt, raw);

  std::size_t seen_faces = 0, calls = 0;
  cvt::RemeshOptions refuse;
  refuse.accept_dual = [&](const TriangleMesh& dual) {
    ++calls;
    seen_faces = dual.num_faces();
    return false;
  };
  const cvt::RemeshResult refused = cvt::restricted_delaunay(cvt, refuse);
  EXPECT_EQ(calls, 1u);
  EXPECT_EQ(seen_faces, plain.mesh.num_faces());
  EXPECT_EQ(refused.mesh.triangles, plain.mesh.triangles);
  EXPECT_EQ(refused.mesh.positions.size(), plain.mesh.positions.size());
  EXPECT_EQ(refused.stats.flips + refused.stats.smoothing_moves, 0u);

  cvt::RemeshOptions accept;
  accept.accept_dual = [&](const TriangleMesh&) { return true; };
  const cvt::RemeshResult full = cvt::restricted_delaunay(cvt, accept), usual = cvt::restricted_delaunay(cvt);
  EXPECT_EQ(full.mesh.triangles, usual.mesh.triangles);
  EXPECT_GT(full.stats.flips + full.stats.smoothing_moves, 0u);   // five iterations leave work for the post-pass
}

}  // namespace
