// Accuracy against exact polyhedral geodesics (CGAL Surface_mesh_shortest_path) on real meshes:
// mean relative error (MRE) over all reachable vertices, averaged over random vertex sources,
// compared with Dijkstra on edges and the heat method (CGAL, direct) on the same sources.
#include "helpers/geodesic_fixtures.hpp"
#include "helpers/mesh_builders.hpp"
#include "test_data.hpp"

#include <gsp/dijkstra.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/reference/exact_geodesics.hpp>
#include <gsp/reference/heat_method.hpp>
#include <gsp/weld.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace gsp::test {
namespace {

// The bar for benign isotropic meshes (the paper reports 0.19% on its benign set).
constexpr double kBenignBound = 0.0025;

struct Errors {
  double gsp = 0, gsp_double = 0, gsp_input_faces = 0, dijkstra = 0, heat = 0;
};

Errors measure(const std::string& name, int sources, int midpoint_splits = 0) {
  TriangleMesh m = io::read_mesh(shared_mesh(name)).mesh;
  m = weld_vertices(m).mesh;
  for (int k = 0; k < midpoint_splits; ++k) m = midpoint_subdivide(m);
  reference::ExactGeodesicSolver exact(m);
  reference::HeatMethodSolver heat(m);
  const GeodesicSolver gsp(m);
  SolverOptions no_flips;
  no_flips.intrinsic_delaunay = false;
  const GeodesicSolver gsp_input(m, no_flips);
  const DijkstraSolver dijkstra(m);
  SplitMix rng{1234};
  Errors e;
  for (int s = 0; s < sources; ++s) {
    const Index v = Index(rng.next() % m.num_vertices());
    const std::vector<double> ex = exact.distances_from_vertex(v);
    GeodesicOptions dbl;
    dbl.precision = Precision::double_precision;
    e.gsp += mre(gsp.compute({Source::at_vertex(v)}).vertex_distance, ex) / sources;
    e.gsp_double += mre(gsp.compute({Source::at_vertex(v)}, dbl).vertex_distance, ex) / sources;
    e.gsp_input_faces += mre(gsp_input.compute({Source::at_vertex(v)}).vertex_distance, ex) / sources;
    e.dijkstra += mre(dijkstra.compute({Source::at_vertex(v)}).vertex_distance, ex) / sources;
    e.heat += mre(heat.solve({v}), ex) / sources;
  }
  std::printf("%-28s MRE  GSP %.3f%%  GSP(double) %.3f%%  GSP(input faces) %.3f%%  Dijkstra %.2f%%  heat %.2f%%\n",
              name.c_str(), 100 * e.gsp, 100 * e.gsp_double, 100 * e.gsp_input_faces, 100 * e.dijkstra, 100 * e.heat);
  return e;
}

TEST(GeodesicAccuracy, BenignMeshes) {
  if (!have_shared_data()) GTEST_SKIP() << "shared meshes not found";
  for (const char* name : {"fertility.off", "camelhead.off"}) {
    const Errors e = measure(name, 3);
    EXPECT_LT(e.gsp, kBenignBound) << name;
    EXPECT_LT(e.gsp, e.dijkstra / 10) << name;
    EXPECT_LT(e.gsp, e.heat) << name;
    // Single precision costs no accuracy worth mentioning (paper Section 5.5).
    EXPECT_NEAR(e.gsp, e.gsp_double, 1e-4) << name;
  }
}

// A midpoint split keeps the surface and makes every new vertex flat next to curved old ones.
// Lines carried straight past such vertices (the flat-corner rule) passed the curved ones on a
// side no surface path takes: 0.85% below exact on average here before the rule was limited
// to flat vertices whose neighbours are flat too (gsp-core.md, rule 4).
TEST(GeodesicAccuracy, MidpointSplitMesh) {
  if (!have_shared_data()) GTEST_SKIP() << "shared meshes not found";
  const Errors e = measure("fertility.off", 2, 1);
  EXPECT_LT(e.gsp, kBenignBound);
  EXPECT_LT(e.gsp, e.heat);
  EXPECT_LT(e.gsp, e.dijkstra / 10);
}

// Split twice, the first split's new vertices sit on straight creases (the old edges) of flat
// vertices that end at the old vertices, many of them saddles; lines carried past those flat
// vertices passed the saddles on a side no surface path takes: MRE 0.28% and 0.35% here, all
// of it below exact (1.36% on the bunny split twice), before such creases lost the flat-corner rule
// (gsp-core.md, rule 4). The surface is the input's, so its exact values at the input's
// vertices (the split mesh's first ones) are the reference.
TEST(GeodesicAccuracy, TwiceSplitMesh) {
  if (!have_shared_data()) GTEST_SKIP() << "shared meshes not found";
  const TriangleMesh m = weld_vertices(io::read_mesh(shared_mesh("fertility.off")).mesh).mesh;
  const TriangleMesh split = midpoint_subdivide(m, 2);
  reference::ExactGeodesicSolver exact(m);
  const GeodesicSolver gsp(split);
  SplitMix rng{1234};
  for (int s = 0; s < 2; ++s) {
    const Index v = Index(rng.next() % m.num_vertices());
    const std::vector<double> ex = exact.distances_from_vertex(v);
    const std::vector<double> d = gsp.compute({Source::at_vertex(v)}).vertex_distance;
    double signed_sum = 0;
    std::size_t n = 0;
    for (std::size_t u = 0; u < ex.size(); ++u)
      if (ex[u] > 0) signed_sum += (d[u] - ex[u]) / ex[u], ++n;
    std::printf("fertility split twice, source %u: MRE %.3f%%, signed %+.3f%%\n", v, 100 * mre(d, ex),
                100 * signed_sum / double(n));
    EXPECT_LT(mre(d, ex), kBenignBound) << v;
    EXPECT_GT(signed_sum / double(n), -0.001) << v;   // no longer short on average
  }
}

// Split once, a mesh's new vertices are flat and alone on creases (its old edges) between old
// vertices; where those are convex the new ones count as convex too (a bend there only
// over-estimates; gsp-core.md, rule 4, "alone on a crease"), instead of leaving the choice to
// the table, whose probe bends needles near their opposite corner. A CAD cookie cutter (104
// vertices welded, a corpus file) split once, against its exact values at its own vertices
// (four sources): 0.076% before, 0.054% since (the file as read: 0.079%).
TEST(GeodesicAccuracy, OnceSplitCadPart) {
  const std::string path = data_dir() + "/../corpus/thingi10k_68435_viper_cookie_cutter.stl";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "corpus not found";
  const TriangleMesh m = weld_vertices(io::read_mesh(path).mesh).mesh;
  const TriangleMesh split = midpoint_subdivide(m, 1);
  reference::ExactGeodesicSolver exact(m);
  const GeodesicSolver on_file(m), on_split(split);
  SplitMix rng{1234};
  double file = 0, once = 0;
  constexpr int kSources = 4;
  for (int s = 0; s < kSources; ++s) {
    const Index v = Index(rng.next() % m.num_vertices());
    const std::vector<double> ex = exact.distances_from_vertex(v);
    const double a = mre(on_file.compute({Source::at_vertex(v)}).vertex_distance, ex);
    const double b = mre(on_split.compute({Source::at_vertex(v)}).vertex_distance, ex);
    std::printf("cookie cutter, source %u: MRE %.3f%% as read, %.3f%% split once\n", v, 100 * a, 100 * b);
    file += a / kSources, once += b / kSources;
  }
  EXPECT_LT(once, 0.00065);
  EXPECT_LT(once, file);
}

TEST(GeodesicAccuracy, MalignCadMesh) {
  if (!have_shared_data()) GTEST_SKIP() << "shared meshes not found";
  // A CAD export: fans and slivers (46% of triangles with aspect ratio > 10).
  const Errors e = measure("adis16480_sensor.stl", 3);
  EXPECT_LT(e.gsp, 0.01);
  EXPECT_LT(e.gsp, e.dijkstra);
  EXPECT_LT(e.gsp, e.heat);
  // The intrinsic Delaunay flips are what make this work (7% on the input's slivers).
  EXPECT_LT(e.gsp, e.gsp_input_faces / 3);
}

}  // namespace
}  // namespace gsp::test
