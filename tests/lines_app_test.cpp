// gsp-geodesic's line sources end to end: --source-edges, --source-boundary and
// --source-polyline agree with gsp::lines and with closed forms on a plane, write the nearest
// segment as the `source` label, report their counts in --stats, and refuse bad input with
// exit 1 (one line naming the file) or 2 (usage).
#include "apps_support.hpp"
#include "lines_support.hpp"

#include <gsp/io/mesh_io.hpp>
#include <gsp/lines/line_distances.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>

namespace gsp::test {
namespace {

const std::string kApp = "gsp-geodesic";

std::string sample() { return std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off"; }

// The vertex columns of an ASCII PLY by property name.
std::map<std::string, std::vector<double>> ply_columns(const fs::path& path) {
  std::stringstream in(slurp(path));
  std::vector<std::string> names;
  std::size_t count = 0;
  bool in_vertex = false;
  for (std::string line; std::getline(in, line) && line != "end_header";) {
    std::stringstream w(line);
    std::string a, b, c, d;
    w >> a >> b >> c >> d;
    if (a == "element") in_vertex = b == "vertex", count = in_vertex ? std::stoul(c) : count;
    if (a == "property" && in_vertex) names.push_back(b == "list" ? "" : c);
  }
  std::map<std::string, std::vector<double>> cols;
  for (std::size_t v = 0; v < count; ++v)
    for (const std::string& n : names) {
      double x;
      in >> x;
      cols[n].push_back(x);
    }
  return cols;
}

std::string xyz(Vec3 p) {
  std::ostringstream s;
  s << std::setprecision(17) << p.x << " " << p.y << " " << p.z;
  return s.str();
}

TEST(LinesApp, EdgesMatchTheLibraryAndReportStats) {
  ScratchDir dir("lines");
  const TriangleMesh m = io::read_mesh(sample()).mesh;
  const Triangle t = m.triangles[0];
  const std::string edges = std::to_string(t[0]) + "-" + std::to_string(t[1]) + "," + std::to_string(t[1]) + "-" +
                            std::to_string(t[2]);
  const auto r = run(bin(kApp) + " " + quote(sample()) + " --source-edges " + edges + " -o " +
                         quote((dir / "d.txt").string()) + " --stats -", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<double> got = io::read_values_txt((dir / "d.txt").string());
  const lines::LineResult lib = lines::line_distances(m, lines::vertex_chain_source(m, {t[0], t[1], t[2]}, false));
  ASSERT_EQ(got.size(), m.num_vertices());
  for (std::size_t v = 0; v < got.size(); ++v) ASSERT_NEAR(got[v], lib.vertex_distance[v], 1e-6 * (1 + got[v])) << v;
  EXPECT_EQ(got[t[0]], 0.0);
  const JsonValue stats = JsonParser(r.out).parse();
  EXPECT_EQ(stats["result"]["segments"].num, 2);
  EXPECT_EQ(stats["result"]["faces_seeded"].num, 3);   // the first face and one across each edge
  EXPECT_EQ(stats["result"]["vertices_reached"].num, 4494);
  EXPECT_GT(stats["operations"]["waves_accepted"].num, 9000);
  EXPECT_EQ(stats["settings"]["method"].str, "gsp-lines");
}

TEST(LinesApp, EdgeErrors) {
  ScratchDir dir("lines");
  const std::string base = bin(kApp) + " " + quote(sample()) + " -o " + quote((dir / "d.txt").string());
  const auto r = run(base + " --source-edges 0-4000", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--source-edges: 0-4000 is not an edge of the mesh"), std::string::npos) << r.err;
  EXPECT_EQ(lines(r.err).size(), 1u);
  EXPECT_EQ(run(base + " --source-edges 0-99999", dir).exit_code, 1);
  EXPECT_EQ(run(base + " --source-edges 0-x", dir).exit_code, 2);
  EXPECT_EQ(run(base + " --source-edges 0", dir).exit_code, 2);
  EXPECT_FALSE(fs::exists(dir / "d.txt"));
}

TEST(LinesApp, BoundaryOfASquareIsTheDistanceToItsSidesWithLabels) {
  ScratchDir dir("lines");
  const Plane pl;
  const TriangleMesh m = jittered_square(12, 9);
  io::write_mesh((dir / "square.obj").string(), m);
  const auto r = run(bin(kApp) + " " + quote((dir / "square.obj").string()) + " --source-boundary --ascii -o " +
                         quote((dir / "d.ply").string()), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto cols = ply_columns(dir / "d.ply");
  ASSERT_EQ(cols["distance"].size(), m.num_vertices());
  ASSERT_EQ(cols["source"].size(), m.num_vertices());
  const lines::LineSource src = lines::boundary_source(m);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3 d = m.positions[v] - pl.origin;
    const double x = dot(d, pl.u), y = dot(d, pl.v);
    const double expected = std::max(0.0, std::min({x, 1 - x, y, 1 - y}));
    ASSERT_NEAR(cols["distance"][v], expected, 1e-5 * expected + 1e-6) << v;   // float in the file
    const double label = cols["source"][v];
    ASSERT_GE(label, 0);
    ASSERT_LT(label, 48);
    const auto& seg = src.segments[std::size_t(label)];
    ASSERT_NEAR(point_segment_distance(m.positions[v], seg[0], seg[1]), expected, 1e-6) << v;
  }
}

TEST(LinesApp, BoundaryOfAClosedMeshIsAnError) {
  ScratchDir dir("lines");
  const auto r = run(bin(kApp) + " " + quote(sample()) + " --source-boundary -o " + quote((dir / "d.txt").string()), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("mesh has no boundary"), std::string::npos) << r.err;
}

TEST(LinesApp, PolylineFilesPlainAndObj) {
  ScratchDir dir("lines");
  const Plane pl;
  const TriangleMesh m = jittered_square(15, 4);
  io::write_mesh((dir / "square.obj").string(), m);
  const std::vector<Vec3> a{pl.at(0.2, 0.2), pl.at(0.5, 0.7), pl.at(0.8, 0.3)};
  const std::vector<Vec3> b{pl.at(0.9, 0.9), pl.at(0.6, 0.95)};
  write_file(dir / "one.txt", "# x y z\n" + xyz(a[0]) + "\n" + xyz(a[1]) + "\n" + xyz(a[2]) + "\n");
  write_file(dir / "two.obj", "v " + xyz(a[0]) + "\nv " + xyz(a[1]) + "\nv " + xyz(a[2]) + "\nv " + xyz(b[0]) +
                                  "\nv " + xyz(b[1]) + "\nl 1 2 3\nl 4 5\n");
  const std::string base = bin(kApp) + " " + quote((dir / "square.obj").string());
  ASSERT_EQ(run(base + " --source-polyline " + quote((dir / "one.txt").string()) + " -o " + quote((dir / "one.out.txt").string()), dir).exit_code, 0);
  const std::vector<double> one = io::read_values_txt((dir / "one.out.txt").string());
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const double d = std::min(point_segment_distance(m.positions[v], a[0], a[1]), point_segment_distance(m.positions[v], a[1], a[2]));
    ASSERT_NEAR(one[v], d, 1e-5 * d + 1e-9) << v;
  }
  const auto r = run(base + " --source-polyline " + quote((dir / "two.obj").string()) + " --ascii --stats - -o " +
                         quote((dir / "two.ply").string()), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(JsonParser(r.out).parse()["result"]["segments"].num, 3);
  auto cols = ply_columns(dir / "two.ply");
  const std::array<std::array<Vec3, 2>, 3> segs{{{a[0], a[1]}, {a[1], a[2]}, {b[0], b[1]}}};
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    std::array<double, 3> d;
    for (int s = 0; s < 3; ++s) d[s] = point_segment_distance(m.positions[v], segs[s][0], segs[s][1]);
    const int best = int(std::min_element(d.begin(), d.end()) - d.begin());
    ASSERT_NEAR(cols["distance"][v], d[best], 1e-5 * d[best] + 1e-6) << v;
    std::array<double, 3> sorted = d;
    std::sort(sorted.begin(), sorted.end());
    if (sorted[1] - sorted[0] > 1e-6) ASSERT_EQ(int(cols["source"][v]), best) << v;
  }
}

TEST(LinesApp, BadPolylineFilesExitOneNamingTheFile) {
  ScratchDir dir("lines");
  const std::string base = bin(kApp) + " " + quote(sample()) + " -o " + quote((dir / "d.txt").string()) + " --source-polyline ";
  write_file(dir / "empty.txt", "");
  write_file(dir / "nan.txt", "0 0 0\n1 nan 2\n");
  write_file(dir / "one.txt", "0 0 0\n");
  struct Case {
    std::string file, message;
  } cases[] = {{"empty.txt", "empty.txt: no polyline"},
               {"nan.txt", "nan.txt:line 2: \"nan\" is not a finite number"},
               {"one.txt", "one.txt:line 1: a polyline needs at least two points"},
               {"missing.txt", "missing.txt: cannot open the polyline file"}};
  for (const Case& c : cases) {
    const auto r = run(base + quote((dir / c.file).string()), dir);
    EXPECT_EQ(r.exit_code, 1) << c.file;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "d.txt"));
}

TEST(LinesApp, UsageErrors) {
  ScratchDir dir("lines");
  const std::string base = bin(kApp) + " " + quote(sample()) + " -o " + quote((dir / "d.txt").string());
  EXPECT_EQ(run(base + " --source-edges 0-1 --source-vertex 3", dir).exit_code, 2);
  EXPECT_EQ(run(base + " --source-edges 0-1 --method dijkstra", dir).exit_code, 2);
  EXPECT_EQ(run(base + " --source-edges 0-1 --metric curvature:ratio=2", dir).exit_code, 2);
}

}  // namespace
}  // namespace gsp::test
