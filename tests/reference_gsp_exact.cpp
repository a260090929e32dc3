// gsp-exact run as a user runs it: the built binary on meshes written by gsp::io, its
// output against the library and closed forms, its exit codes and messages.
#include "apps_support.hpp"
#include "helpers/mesh_builders.hpp"

#include <gsp/io/mesh_io.hpp>
#include <gsp/reference/exact_geodesics.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using gsp::test::quote;
using gsp::test::run;
using gsp::test::ScratchDir;

const std::string kExact = gsp::test::bin("gsp-exact");

// The values are written with 9 significant digits.
void expect_close(double got, double want, const std::string& what) {
  EXPECT_NEAR(got, want, 1e-8 * (1 + std::abs(want))) << what;
}

// An STL-like soup (every face its own vertices) of a flat grid: gsp-exact welds it, so the
// distances cross faces and are Euclidean, reported for every one of the file's vertices.
TEST(GspExact, WeldsSoupAndReportsInFileOrder) {
  ScratchDir dir("gsp-exact");
  const gsp::TriangleMesh soup = gsp::test::explode(gsp::test::grid(5));
  const std::string in = (dir / "soup.obj").string(), out = (dir / "d.txt").string();
  gsp::io::write_mesh(in, soup);
  const auto r = run(quote(kExact) + " " + quote(in) + " --source-vertex 4 -o " + quote(out), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto d = gsp::io::read_values_txt(out);
  ASSERT_EQ(d.size(), soup.num_vertices());
  for (std::size_t v = 0; v < d.size(); ++v)
    expect_close(d[v], gsp::distance(soup.positions[v], soup.positions[4]), "vertex " + std::to_string(v));

  // Without welding every face is its own component: only the source's face is reached.
  const auto r2 = run(quote(kExact) + " " + quote(in) + " --no-weld --source-vertex 4 -o " + quote(out), dir);
  ASSERT_EQ(r2.exit_code, 0) << r2.err;
  const auto d2 = gsp::io::read_values_txt(out);
  std::size_t finite = 0;
  for (double x : d2) finite += std::isfinite(x);
  EXPECT_EQ(finite, 3u);
}

TEST(GspExact, MatchesLibraryAndHeatIsClose) {
  ScratchDir dir("gsp-exact");
  const gsp::TriangleMesh sphere = gsp::test::icosphere(3);
  const std::string in = (dir / "sphere.ply").string(), out = (dir / "d.txt").string(),
                    heat = (dir / "h.txt").string(), stats = (dir / "stats.json").string();
  gsp::io::write_mesh(in, sphere);
  const auto r = run(quote(kExact) + " " + quote(in) + " --source-vertex 0,100 --stats " + quote(stats) +
                         " -o " + quote(out),
                     dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");  // not a terminal: no summary
  // The PLY is binary float: compare with the library on the float-rounded positions.
  const gsp::TriangleMesh stored = gsp::io::read_mesh(in).mesh;
  const auto want = gsp::reference::exact_geodesic_distances(
      stored, {gsp::reference::ExactSource::at_vertex(0), gsp::reference::ExactSource::at_vertex(100)});
  const auto got = gsp::io::read_values_txt(out);
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t v = 0; v < got.size(); ++v) expect_close(got[v], want[v], "vertex " + std::to_string(v));

  const auto json = gsp::test::parse_json(gsp::test::slurp(stats));
  EXPECT_EQ(json["input"]["vertices"].num, 642);
  EXPECT_EQ(json["settings"]["method"].str, "exact");
  EXPECT_GE(json["timings"]["compute"].num, 0.0);

  const auto h = run(quote(kExact) + " " + quote(in) + " --method heat-idt --source-vertex 0,100 -o " + quote(heat), dir);
  ASSERT_EQ(h.exit_code, 0) << h.err;
  const auto hd = gsp::io::read_values_txt(heat);
  double mre = 0;
  std::size_t n = 0;
  for (std::size_t v = 0; v < hd.size(); ++v)
    if (want[v] > 0.1) {
      mre += std::abs(hd[v] - want[v]) / want[v];
      ++n;
    }
  EXPECT_LT(mre / double(n), 0.05);
}

TEST(GspExact, UsageErrorsExitTwo) {
  ScratchDir dir("gsp-exact");
  const std::string in = (dir / "quad.obj").string();
  gsp::io::write_mesh(in, gsp::test::quad());
  const std::string out = quote((dir / "d.txt").string());
  const std::vector<std::string> bad_args = {
      " -o " + out,                                              // no source
      " --source-vertex 0",                                      // no output
      " --source-vertex x -o " + out,                            // not an index
      " --source-vertex 0 -o " + quote((dir / "d.ply").string()),  // output not .txt
      " --source-vertex 0 --method fast -o " + out,              // unknown method
      " --bogus -o " + out,                                      // unknown option
  };
  for (const std::string& args : bad_args) {
    const auto r = run(quote(kExact) + " " + quote(in) + args, dir);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(gsp::test::lines(r.err).size(), 1u) << args << ": " << r.err;
  }
  EXPECT_EQ(run(quote(kExact) + " --help", dir).exit_code, 0);
  EXPECT_EQ(run(quote(kExact) + " --version", dir).exit_code, 0);
  EXPECT_FALSE(std::filesystem::exists(dir / "d.txt"));
}

TEST(GspExact, BadInputExitsOneAndWritesNothing) {
  ScratchDir dir("gsp-exact");
  const std::string book = (dir / "book.obj").string(), quad = (dir / "quad.obj").string();
  gsp::io::write_mesh(book, gsp::test::book());
  gsp::io::write_mesh(quad, gsp::test::quad());
  const std::string out = (dir / "d.txt").string();
  const auto nonmanifold = run(quote(kExact) + " " + quote(book) + " --source-vertex 0 -o " + quote(out), dir);
  EXPECT_EQ(nonmanifold.exit_code, 1);
  ASSERT_EQ(gsp::test::lines(nonmanifold.err).size(), 1u) << nonmanifold.err;
  EXPECT_NE(nonmanifold.err.find("book.obj"), std::string::npos) << nonmanifold.err;
  EXPECT_NE(nonmanifold.err.find("non-manifold edge"), std::string::npos) << nonmanifold.err;

  const auto range = run(quote(kExact) + " " + quote(quad) + " --source-vertex 4 -o " + quote(out), dir);
  EXPECT_EQ(range.exit_code, 1);
  EXPECT_NE(range.err.find("does not exist"), std::string::npos) << range.err;

  const auto missing = run(quote(kExact) + " " + quote((dir / "none.obj").string()) + " --source-vertex 0 -o " + quote(out), dir);
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(gsp::test::lines(missing.err).size(), 1u) << missing.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
