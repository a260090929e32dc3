#pragma once
// The remeshing check shared by cvt_remesh_test (closed meshes) and cvt_boundary_test: the
// restricted Delaunay dual is a consistently oriented manifold with the input's Euler
// characteristic, boundary loops and components, oriented like the input, with angles and
// Hausdorff distance within thresholds measured at ~2,000 vertices (docs/cvt.md).
#include "test_data.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/cvt/cvt.hpp>
#include <gsp/cvt/quality.hpp>
#include <gsp/cvt/remesh.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/topology.hpp>

#include <gtest/gtest.h>

#include <cstdio>

namespace gsp::test {

struct Expect {
  double min_angle;        // degrees, lower bound
  double below_30;         // fraction of angles, upper bound
  double hausdorff;        // relative to the bbox diagonal, upper bound
};

// Signed volume (closed) or the area-weighted mean normal (open): compared between input and
// output to check that the dual triangles took the input's orientation.
inline Vec3 moment(const TriangleMesh& m) {
  Vec3 s;
  for (const Triangle& t : m.triangles) s = s + cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
  return s;
}
inline double signed_volume(const TriangleMesh& m) {
  double v = 0;
  for (const Triangle& t : m.triangles) v += dot(m.positions[t[0]], cross(m.positions[t[1]], m.positions[t[2]])) / 6;
  return v;
}

inline void check_remesh(const TriangleMesh& mesh, std::size_t sites, const Expect& expect) {
  cvt::CvtOptions o;
  o.sites = sites;
  const cvt::CvtResult cvt = cvt::compute_cvt(mesh, o);
  for (std::size_t i = 1; i < cvt.energy_curve.size(); ++i) EXPECT_LE(cvt.energy_curve[i], cvt.energy_curve[i - 1]) << i;
  EXPECT_GE(cvt.stats.iterations, 5);
  EXPECT_LT(cvt.energy, 0.97 * cvt.energy_curve.front());
  EXPECT_LE(cvt.sites.size(), sites + sites / 50);   // region fixes add a few at most

  const cvt::RemeshResult r = cvt::restricted_delaunay(cvt);
  const TopologyReport in = analyze_topology(mesh, build_connectivity(mesh));
  const TopologyReport out = analyze_topology(r.mesh, build_connectivity(r.mesh));
  EXPECT_TRUE(out.is_manifold()) << out.nonmanifold_edges << " non-manifold edges, " << out.nonmanifold_vertices
                                 << " vertices";
  EXPECT_EQ(out.inconsistent_edges, 0u);
  EXPECT_EQ(out.euler_characteristic, in.euler_characteristic);
  EXPECT_EQ(out.boundary_loops, in.boundary_loops);
  EXPECT_EQ(out.components, in.components);
  EXPECT_EQ(out.duplicate_faces, 0u);
  EXPECT_EQ(r.stats.unused_sites, 0u);
  // Boundary collapses of the post-pass take a vertex each, boundary splits and insertions at
  // far input points add one (a few; insertions at most 2% of the sites).
  EXPECT_EQ(r.mesh.num_vertices() + r.stats.boundary_collapses,
            cvt.sites.size() + r.stats.boundary_splits + r.stats.far_point_insertions);
  EXPECT_LE(r.stats.far_point_insertions, cvt.sites.size() / 50);
  EXPECT_LE(r.stats.boundary_collapses + r.stats.boundary_splits, sites / 50);
  if (in.is_closed()) {
    const double vi = signed_volume(mesh), vo = signed_volume(r.mesh);
    EXPECT_GT(vo * vi, 0.0);
    EXPECT_NEAR(vo / vi, 1.0, 0.03);
  } else {
    const Vec3 a = moment(mesh), b = moment(r.mesh);
    EXPECT_GT(dot(a, b), 0.9 * norm(a) * norm(b));
  }

  const cvt::MeshQuality q = cvt::measure_mesh_quality(r.mesh);
  cvt::HausdorffOptions ho;
  ho.samples = 30000;
  const cvt::HausdorffDistance h = cvt::hausdorff_distance(mesh, r.mesh, ho);
  EXPECT_GE(q.min_angle, expect.min_angle);
  EXPECT_LE(q.below_30, expect.below_30);
  EXPECT_LE(h.relative, expect.hausdorff);
  EXPECT_EQ(q.degenerate, 0u);
  std::printf("[ measured ] sites %zu iterations %d min angle %.2f below 30 %.3f%% mean AR %.3f Hausdorff %.3f%%\n",
              cvt.sites.size(), cvt.stats.iterations, q.min_angle, 100 * q.below_30, q.mean_aspect_ratio,
              100 * h.relative);
}

}  // namespace gsp::test
