// gsp-cvt end to end: the remesh and the regions file read back, the stats JSON, the error
// contract (exit 1 for bad input, 2 for usage errors, nothing left behind).
#include "apps_support.hpp"
#include "cvt_components.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/topology.hpp>

#include <gtest/gtest.h>

namespace {

using namespace gsp;
using namespace gsp::test;

const std::string kMesh = std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off";
const std::string kApp = bin("gsp-cvt");
constexpr int kRemeshLimit = 60;   // seconds: a hang guard for whole remeshes (2-5 s each)

TEST(CvtApp, RemeshRegionsAndStats) {
  ScratchDir dir("cvt");
  const auto out = dir / "r.obj", regions = dir / "regions.ply";
  const RunResult r = run(kApp + " " + quote(kMesh) + " --vertices 600 --iterations 15 --hausdorff-samples 5000 -o " +
                              quote(out.string()) + " --regions " + quote(regions.string()) + " --stats -",
                          dir, kRemeshLimit);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const JsonValue stats = parse_json(r.out);
  const double sites = stats["result"]["sites"].num;
  EXPECT_GE(sites, 600);
  EXPECT_LE(sites, 612);
  EXPECT_LE(stats["result"]["iterations"].num, 15);
  EXPECT_GT(stats["result"]["energy"].num, 0);
  EXPECT_EQ(stats["topology"]["output"]["euler_characteristic"].num, -6);
  EXPECT_TRUE(stats["topology"]["output"]["manifold"].b);
  EXPECT_GT(stats["quality"]["min_angle"].num, 10);
  EXPECT_LT(stats["quality"]["hausdorff"]["percent_of_diagonal"].num, 3);
  EXPECT_GT(stats["timings"]["compute"].num, 0);
  EXPECT_GT(stats["timings"]["remesh"].num, 0);

  // A closed surface: the post-pass neither collapses nor splits boundary edges.
  EXPECT_EQ(stats["remesh"]["boundary_collapses"].num, 0);
  EXPECT_EQ(stats["remesh"]["boundary_splits"].num, 0);
  EXPECT_GE(stats["remesh"]["smoothing_moves"].num, 0);
  EXPECT_TRUE(stats["settings"]["smooth"].b);
  EXPECT_EQ(stats["settings"]["smooth_below"].num, 40);

  const io::ReadResult mesh = io::read_mesh(out.string());
  // A closed surface: the sites plus the insertions at far input points (at most 2% of them;
  // 12 at 600 sites, where the whole remesh is coarse against the 0.4% bound).
  const double inserted = stats["remesh"]["far_point_insertions"].num;
  EXPECT_LE(inserted, 0.02 * sites);
  EXPECT_EQ(double(mesh.mesh.num_vertices()), sites + inserted);
  const TopologyReport t = analyze_topology(mesh.mesh, build_connectivity(mesh.mesh));
  EXPECT_EQ(t.euler_characteristic, -6);

  const io::ReadResult reg = io::read_mesh(regions.string());
  EXPECT_EQ(reg.mesh.num_vertices(), 4494u);
  EXPECT_EQ(reg.mesh.num_faces(), 9000u);
  ASSERT_EQ(reg.attributes.labels.size(), 1u);
  EXPECT_EQ(reg.attributes.labels[0].first, "label");
  std::vector<bool> used(std::size_t(sites), false);
  for (std::int32_t l : reg.attributes.labels[0].second) {
    ASSERT_GE(l, 0);
    ASSERT_LT(l, sites);
    used[std::size_t(l)] = true;
  }
  std::size_t count = 0;
  for (bool u : used) count += u;
  EXPECT_GT(count, std::size_t(0.8 * sites));   // most regions hold an input vertex
  EXPECT_EQ(reg.attributes.colors.size(), 4494u);
}

TEST(CvtApp, NoSmoothKeepsTheSites) {
  // --no-smooth: the dual as it is, every vertex a site; no post-pass counts.
  ScratchDir dir("cvt");
  const auto out = dir / "r.ply";
  const RunResult r = run(kApp + " " + quote(kMesh) + " --vertices 300 --iterations 5 --no-smooth --stats - -o " +
                              quote(out.string()),
                          dir, kRemeshLimit);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const JsonValue stats = parse_json(r.out);
  EXPECT_FALSE(stats["settings"]["smooth"].b);
  EXPECT_EQ(stats["remesh"]["smoothing_moves"].num, 0);
  EXPECT_EQ(stats["remesh"]["pulls"].num, 0);
  EXPECT_EQ(stats["remesh"]["vertices"].num, stats["result"]["sites"].num);
  EXPECT_EQ(run(kApp + " " + quote(kMesh) + " --vertices 300 --smooth-below 0 -o " + quote(out.string()), dir, kRemeshLimit).exit_code,
            2);   // out of range
}

TEST(CvtApp, EdgeLengthAndGlb) {
  ScratchDir dir("cvt");
  const auto out = dir / "r.glb";
  const RunResult r = run(kApp + " " + quote(kMesh) + " --edge-length 5% --iterations 3 -q -o " + quote(out.string()), dir, kRemeshLimit);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const io::ReadResult mesh = io::read_mesh(out.string());
  EXPECT_GT(mesh.mesh.num_faces(), 100u);
}

// --method edges: edge operations instead of the CVT, the count asked for within 10%, the
// component reported as remeshed by them, no CVT iterations.
TEST(CvtApp, MethodEdges) {
  ScratchDir dir("cvt");
  const auto out = dir / "r.ply";
  const RunResult r = run(kApp + " " + quote(kMesh) + " --vertices 600 --method edges --hausdorff-samples 5000 -o " +
                              quote(out.string()) + " --stats -",
                          dir, kRemeshLimit);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const JsonValue stats = parse_json(r.out);
  EXPECT_EQ(stats["settings"]["method"].str, "edges");
  EXPECT_EQ(stats["result"]["iterations"].num, 0);
  EXPECT_TRUE(stats["components"].items.at(0)["by_edge_operations"].b);
  EXPECT_EQ(stats["components"].items.at(0)["edge_failure"].str, "");
  EXPECT_EQ(stats["topology"]["output"]["euler_characteristic"].num, -6);
  EXPECT_TRUE(stats["topology"]["output"]["manifold"].b);
  EXPECT_GE(stats["quality"]["min_angle"].num, 20);
  const io::ReadResult mesh = io::read_mesh(out.string());
  EXPECT_NEAR(double(mesh.mesh.num_vertices()), 600.0, 60.0);
}

// --sizing-angle: the edge remesh with a sizing field, the setting in the stats, the topology and
// the count kept.
TEST(CvtApp, MethodEdgesWithASizingField) {
  ScratchDir dir("cvt");
  const auto out = dir / "r.ply";
  const RunResult r = run(kApp + " " + quote(kMesh) + " --vertices 600 --method edges --sizing-angle 57 " +
                              "--hausdorff-samples 5000 -o " + quote(out.string()) + " --stats -",
                          dir, kRemeshLimit);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const JsonValue stats = parse_json(r.out);
  EXPECT_EQ(stats["settings"]["sizing_angle"].num, 57);
  EXPECT_TRUE(stats["components"].items.at(0)["by_edge_operations"].b);
  EXPECT_EQ(stats["topology"]["output"]["euler_characteristic"].num, -6);
  EXPECT_TRUE(stats["topology"]["output"]["manifold"].b);
  EXPECT_NEAR(double(io::read_mesh(out.string()).mesh.num_vertices()), 600.0, 60.0);
}

// Fewer vertices than a component is remeshed with: the remesh has 20, and stderr says why.
TEST(CvtApp, TooFewVerticesAreRaisedAndSaid) {
  ScratchDir dir("cvt");
  const auto in = dir / "sphere.off", out = dir / "r.ply";
  io::write_mesh(in.string(), icosphere(3));
  const RunResult r = run(kApp + " " + quote(in.string()) + " --vertices 3 -o " + quote(out.string()), dir, kRemeshLimit);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("3 vertices asked for, 20 sites used: 1 component got 20 sites"), std::string::npos) << r.err;
  EXPECT_GE(io::read_mesh(out.string()).mesh.num_vertices(), 20u);
}

// Two spheres and a non-manifold book as a soup (welded by the app): the spheres are
// remeshed apart, the book is kept and named on stderr; nothing remeshable at all is an error.
TEST(CvtApp, ComponentsRemeshedApartOrKeptWithAReason) {
  ScratchDir dir("cvt");
  TriangleMesh m = icosphere(2);
  add(m, icosphere(2), 0.5, {3, 0, 0});
  add(m, book(), 1.0, {-4, 0, 0});
  io::write_mesh((dir / "in.obj").string(), explode(m));
  const auto out = dir / "r.ply";
  const RunResult r = run(kApp + " " + quote((dir / "in.obj").string()) + " --weld" +
                              " --vertices 250 --iterations 5 --no-smooth --stats - -o " + quote(out.string()),
                          dir, kRemeshLimit);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("kept as it is: component 2 (3 faces): 1 non-manifold edges, 2 non-manifold vertices"),
            std::string::npos)
      << r.err;
  const JsonValue stats = parse_json(r.out);
  EXPECT_EQ(stats["remesh"]["components_remeshed"].num, 2);
  EXPECT_EQ(stats["remesh"]["components_kept"].num, 1);
  const JsonValue& c = stats["components"];
  ASSERT_EQ(c.items.size(), 3u);
  EXPECT_EQ(c.items[0]["outcome"].str, "remeshed");
  EXPECT_EQ(c.items[1]["outcome"].str, "remeshed");
  EXPECT_EQ(c.items[2]["outcome"].str, "kept_nonmanifold");
  // The budget by area (4 : 1 : the book's 1.5 of 6.5 pi + 1.5 in all).
  EXPECT_NEAR(c.items[0]["sites"].num, 250 * 4 * M_PI / (5 * M_PI + 1.5), 1.0);
  EXPECT_EQ(stats["topology"]["output"]["components"].num, 3);
  EXPECT_EQ(stats["topology"]["output"]["euler_characteristic"].num, 2 + 2 + 1);
  EXPECT_EQ(stats["topology"]["output"]["nonmanifold_edges"].num, 1);   // the book's spine, kept

  io::write_mesh((dir / "book.obj").string(), book());
  const RunResult bad =
      run(kApp + " " + quote((dir / "book.obj").string()) + " --vertices 50 -o " + quote((dir / "b.ply").string()), dir, kRemeshLimit);
  EXPECT_EQ(bad.exit_code, 1);
  ASSERT_EQ(lines(bad.err).size(), 1u) << bad.err;
  EXPECT_NE(bad.err.find("no component could be remeshed; component 0 (3 faces): 1 non-manifold edges"),
            std::string::npos)
      << bad.err;
  EXPECT_FALSE(fs::exists(dir / "b.ply"));
}

TEST(CvtApp, FeatureAngleKeepsTheBoxEdges) {
  // A box as 12 triangles: with --feature-angle its 12 edges are curves with fixed sites and
  // its 8 corners come out as vertices; the remesh is then the box itself.
  ScratchDir dir("cvt");
  const auto in = dir / "box.off", out = dir / "r.ply";
  write_file(in, "OFF\n8 12 0\n0 0 0\n2 0 0\n0 1 0\n2 1 0\n0 0 1\n2 0 1\n0 1 1\n2 1 1\n"
                 "3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n3 0 4 6\n3 0 6 2\n"
                 "3 1 3 7\n3 1 7 5\n");
  const RunResult r = run(kApp + " " + quote(in.string()) + " --vertices 300 --feature-angle 40 --hausdorff-samples 5000 --stats - -o " +
                              quote(out.string()),
                          dir, kRemeshLimit);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const JsonValue stats = parse_json(r.out);
  EXPECT_EQ(stats["settings"]["feature_angle"].num, 40);
  EXPECT_EQ(stats["operations"]["feature_curves"].num, 12);
  EXPECT_GT(stats["operations"]["feature_sites"].num, 8);
  EXPECT_LT(stats["quality"]["hausdorff"]["percent_of_diagonal"].num, 1e-6);
  ASSERT_EQ(stats["components"].items.size(), 1u);
  EXPECT_FALSE(stats["components"].items[0]["features_dropped"].b);
  const io::ReadResult mesh = io::read_mesh(out.string());
  std::size_t corners = 0;
  for (const Vec3& p : mesh.mesh.positions)
    corners += (p.x == 0 || p.x == 2) && (p.y == 0 || p.y == 1) && (p.z == 0 || p.z == 1);
  EXPECT_EQ(corners, 8u);
  EXPECT_EQ(run(kApp + " " + quote(in.string()) + " --vertices 300 --feature-angle 200 -o " + quote(out.string()), dir).exit_code,
            2);   // out of range
}

// At 10,000 vertices fertility's working mesh has about 600k faces, where the propagations run
// on all cores by default and the remesh varies slightly from run to run (ties); --threads 1
// gives the same file every time.
TEST(CvtApp, OneThreadRemeshesTheSameEveryRun) {
  ScratchDir dir("cvt");
  std::string first;
  for (int run_index = 0; run_index < 2; ++run_index) {
    const auto out = dir / ("r" + std::to_string(run_index) + ".ply");
    const RunResult r = run(kApp + " " + quote(kMesh) + " --vertices 10000 --iterations 4 --threads 1 --stats - -o " +
                                quote(out.string()),
                            dir, kRemeshLimit);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const JsonValue stats = parse_json(r.out);
    EXPECT_EQ(stats["settings"]["threads"].num, 1);
    EXPECT_GT(stats["operations"]["working_faces"].num, 200000);   // kParallelMinFaces: threads would be used
    const std::string bytes = slurp(out);
    ASSERT_GT(bytes.size(), 10000u);
    if (run_index == 0) first = bytes;
    else EXPECT_TRUE(bytes == first) << "the two --threads 1 remeshes differ";
  }
}

// --faces-per-site sets the working mesh: the fewest 1-to-4 splits that reach the count (the
// long-edge bisection only adds faces), so at least that many faces per site and, for more,
// a finer working mesh than the default's.
TEST(CvtApp, FacesPerSiteSetsTheWorkingMesh) {
  ScratchDir dir("cvt");
  double faces[2] = {0, 0};
  const int per_site[2] = {12, 48};
  for (int i = 0; i < 2; ++i) {
    const std::string option = i == 0 ? "" : " --faces-per-site 48";
    const RunResult r = run(kApp + " " + quote(kMesh) + " --vertices 400 --iterations 2 --no-smooth --stats -" + option +
                                " -o " + quote((dir / "r.ply").string()),
                            dir, kRemeshLimit);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const JsonValue stats = parse_json(r.out);
    EXPECT_EQ(stats["settings"]["faces_per_site"].num, per_site[i]);
    faces[i] = stats["operations"]["working_faces"].num;
    EXPECT_GE(faces[i], per_site[i] * 400.0);
  }
  EXPECT_GT(faces[1], faces[0]);
}

TEST(CvtApp, UsageErrorsExit2) {
  ScratchDir dir("cvt");
  const std::string o = " -o " + quote((dir / "r.obj").string());
  EXPECT_EQ(run(kApp + " " + quote(kMesh) + o, dir).exit_code, 2);   // neither count nor length
  EXPECT_EQ(run(kApp + " " + quote(kMesh) + " --vertices 10 --edge-length 1" + o, dir).exit_code, 2);
  EXPECT_EQ(run(kApp + " " + quote(kMesh) + " --edge-length abc" + o, dir).exit_code, 2);
  EXPECT_EQ(run(kApp + " " + quote(kMesh) + " --vertices 10 -o " + quote((dir / "r.xyz").string()), dir).exit_code, 2);
  EXPECT_EQ(run(kApp + " " + quote(kMesh) + " --vertices 10 --regions r.txt" + o, dir).exit_code, 2);
  EXPECT_EQ(run(kApp + " " + quote(kMesh) + " --vertices 10 --method lloyd" + o, dir).exit_code, 2);
  EXPECT_EQ(run(kApp + " " + quote(kMesh) + " --vertices 10 --cone-angle 400" + o, dir).exit_code, 2);
  EXPECT_EQ(run(kApp + " " + quote(kMesh) + " --vertices 10 --sizing-angle 200" + o, dir).exit_code, 2);
  // Edge operations make no regions.
  EXPECT_EQ(run(kApp + " " + quote(kMesh) + " --vertices 10 --method edges --regions r.ply" + o, dir).exit_code, 2);
  EXPECT_FALSE(fs::exists(dir / "r.obj"));
}

TEST(CvtApp, BadInputExits1) {
  ScratchDir dir("cvt");
  const auto out = dir / "r.obj";
  RunResult r = run(kApp + " " + quote((dir / "missing.off").string()) + " --vertices 10 -o " + quote(out.string()), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
  write_file(dir / "broken.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  r = run(kApp + " " + quote((dir / "broken.off").string()) + " --vertices 10 -o " + quote(out.string()), dir);
  EXPECT_EQ(r.exit_code, 1);
  // More sites than the (split) mesh has vertices: one line naming the input.
  write_file(dir / "tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  r = run(kApp + " " + quote((dir / "tri.off").string()) + " --vertices 10000000 -o " + quote(out.string()), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("tri.off"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
