// gsp-sample end to end: output formats read back against the library, stats, the error
// contract (exit 1 for bad input, 2 for usage, nothing left behind).
#include "apps_support.hpp"

#include <gsp/io/mesh_io.hpp>
#include <gsp/sampling/sampler.hpp>

#include <gtest/gtest.h>

#include <cstdio>

namespace {

using namespace gsp;
using namespace gsp::test;

const std::string kMesh = std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off";
const std::string kApp = bin("gsp-sample");

TEST(SampleApp, PlyRoundTripMatchesLibrary) {
  ScratchDir dir("sample");
  const auto out = dir / "s.ply";
  const RunResult r = run(kApp + " " + quote(kMesh) + " --radius 4% --seed 3 -o " + quote(out.string()), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const io::ReadResult back = io::read_mesh(out.string());

  const TriangleMesh mesh = io::read_mesh(kMesh).mesh;
  sampling::Sampler sampler(mesh);
  sampling::SamplingOptions o;
  o.radius = 0.04 * sampler.diagonal();
  o.seed = 3;
  const auto lib = sampler.sample(o);
  ASSERT_EQ(back.mesh.num_vertices(), lib.samples.size());
  ASSERT_EQ(back.mesh.normals.size(), lib.samples.size());
  const std::vector<std::int32_t>* face = nullptr;
  const std::vector<float>*u = nullptr, *v = nullptr;
  for (auto& [name, values] : back.attributes.labels) if (name == "face") face = &values;
  for (auto& [name, values] : back.attributes.scalars) {
    if (name == "u") u = &values;
    if (name == "v") v = &values;
  }
  ASSERT_TRUE(face && u && v);
  for (std::size_t i = 0; i < lib.samples.size(); ++i) {
    EXPECT_EQ(Index((*face)[i]), lib.samples[i].point.element);
    EXPECT_NEAR((*u)[i], lib.samples[i].point.barycentric[1], 1e-6);
    EXPECT_NEAR((*v)[i], lib.samples[i].point.barycentric[2], 1e-6);
    EXPECT_NEAR(back.mesh.positions[i].x, lib.samples[i].position.x, 1e-4);
    EXPECT_NEAR(dot(back.mesh.normals[i], lib.samples[i].normal), 1.0, 1e-5);
  }
}

TEST(SampleApp, TxtAndStats) {
  ScratchDir dir("sample");
  const auto out = dir / "s.txt";
  const RunResult r =
      run(kApp + " " + quote(kMesh) + " --count 200 --mode farthest --stats - -o " + quote(out.string()), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const JsonValue stats = parse_json(r.out);
  EXPECT_EQ(stats["result"]["count"].num, 200);
  EXPECT_GE(stats["quality"]["min_distance_over_radius"].num, 0.995);   // see SamplingFarthest
  EXPECT_LE(stats["quality"]["coverage_over_radius"].num, 1.001);
  EXPECT_GT(stats["quality"]["normalized_radius"].num, 0.3);
  EXPECT_GT(stats["timings"]["compute"].num, 0.0);
  const auto rows = lines(slurp(out));
  ASSERT_EQ(rows.size(), 200u);
  std::istringstream first(rows[0]);
  double x, y, z, nx, ny, nz, uu, vv;
  unsigned f;
  ASSERT_TRUE(first >> x >> y >> z >> nx >> ny >> nz >> f >> uu >> vv);
  EXPECT_LT(f, 9000u);
  EXPECT_NEAR(nx * nx + ny * ny + nz * nz, 1.0, 1e-5);
}

TEST(SampleApp, PreviewPicture) {
  ScratchDir dir("sample");
  const RunResult r = run(kApp + " " + quote(kMesh) + " --radius 5% -o " + quote((dir / "s.glb").string()) +
                              " --png " + quote((dir / "s.png").string()) + " --png-size 64",
                          dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "s.png"));
  EXPECT_TRUE(fs::exists(dir / "s.glb"));
}

// --evaluate: the quality figures of a point set read from a file (e.g. MeshLab's). Our own
// samples read back give our own figures: same count, min distance >= r, coverage <= r.
TEST(SampleApp, EvaluateReadsAndMeasuresAPointSet) {
  ScratchDir dir("sample");
  const auto pts = dir / "s.ply";
  RunResult r = run(kApp + " " + quote(kMesh) + " --radius 4% --seed 5 --stats - -o " + quote(pts.string()), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const JsonValue made = parse_json(r.out);
  const double radius = made["result"]["radius"].num;
  char arg[64];
  std::snprintf(arg, sizeof arg, "%.17g", radius);
  r = run(kApp + " " + quote(kMesh) + " --evaluate " + quote(pts.string()) + " --radius " + arg + " --stats -", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const JsonValue measured = parse_json(r.out);
  EXPECT_EQ(measured["result"]["count"].num, made["result"]["count"].num);
  EXPECT_LT(measured["result"]["max_snap_distance"].num, 1e-4 * radius);   // PLY stores floats
  EXPECT_GE(measured["quality"]["min_distance_over_radius"].num, 0.999);
  // Read back from floats and snapped again (a point on an edge may land in the neighbour face,
  // whose GSP field differs slightly): coverage within 2% of r.
  EXPECT_LE(measured["quality"]["coverage_over_radius"].num, 1.02);
  EXPECT_NEAR(measured["quality"]["normalized_radius"].num, made["quality"]["normalized_radius"].num, 1e-9);
  // A sparse set (every fourth point) leaves holes: coverage beyond r.
  const io::ReadResult all = io::read_mesh(pts.string());
  TriangleMesh sparse;
  for (std::size_t i = 0; i < all.mesh.positions.size(); i += 4) sparse.positions.push_back(all.mesh.positions[i]);
  io::write_mesh((dir / "sparse.ply").string(), sparse);
  r = run(kApp + " " + quote(kMesh) + " --evaluate " + quote((dir / "sparse.ply").string()) + " --radius " + arg +
              " --stats -", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(parse_json(r.out)["quality"]["coverage_over_radius"].num, 1.2);
  // Usage: --evaluate needs --radius and takes no -o.
  EXPECT_EQ(run(kApp + " " + quote(kMesh) + " --evaluate " + quote(pts.string()), dir).exit_code, 2);
  EXPECT_EQ(run(kApp + " " + quote(kMesh) + " --evaluate " + quote(pts.string()) + " --radius 1 -o " +
                    quote((dir / "x.ply").string()), dir).exit_code, 2);
  EXPECT_EQ(run(kApp + " " + quote(kMesh) + " --evaluate " + quote((dir / "none.ply").string()) + " --radius 1", dir)
                .exit_code, 1);
}

TEST(SampleApp, ErrorContract) {
  ScratchDir dir("sample");
  const std::string out = quote((dir / "s.ply").string());
  auto expect = [&](const std::string& args, int code) {
    const RunResult r = run(kApp + " " + args, dir);
    EXPECT_EQ(r.exit_code, code) << args << ": " << r.err;
    // One line for bad input; a usage error adds the hint to --help.
    EXPECT_EQ(lines(r.err).size(), code == 1 ? 1u : 2u) << r.err;
    EXPECT_NE(r.err.find("gsp-sample"), std::string::npos) << r.err;
  };
  expect(quote(kMesh) + " --count 10 --radius 1 -o " + out, 2);   // both
  expect(quote(kMesh) + " -o " + out, 2);                          // neither
  expect(quote(kMesh) + " --radius x% -o " + out, 2);
  expect(quote(kMesh) + " --radius -1 -o " + out, 2);
  expect(quote(kMesh) + " --radius 1 --mode grid -o " + out, 2);
  expect(quote(kMesh) + " --radius 1 -o " + quote((dir / "s.stl").string()), 2);
  expect(quote((dir / "missing.off").string()) + " --radius 1 -o " + out, 1);
  write_file(dir / "bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  expect(quote((dir / "bad.off").string()) + " --radius 1 -o " + out, 1);
  const auto left = dir.entries();
  EXPECT_EQ(std::count(left.begin(), left.end(), "s.ply"), 0);
}

}  // namespace
