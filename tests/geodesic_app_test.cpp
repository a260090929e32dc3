// gsp-geodesic end to end: the binary's outputs agree value by value with the library, in the
// file's own vertex order, in every format; errors follow the CLI contract.
#include "apps_support.hpp"
#include "helpers/geodesic_fixtures.hpp"
#include "helpers/mesh_builders.hpp"
#include "test_data.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/layout.hpp>
#include <gsp/render/image.hpp>
#include <gsp/weld.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace gsp::test {
namespace {

const std::string kApp = "gsp-geodesic";

std::string sample() { return std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off"; }

TEST(GeodesicApp, TxtMatchesTheLibraryInInputOrder) {
  ScratchDir dir("geodesic");
  const auto r = run(bin(kApp) + " " + quote(sample()) + " --source-vertex 12 -o " + quote((dir / "d.txt").string()), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<double> got = io::read_values_txt((dir / "d.txt").string());
  const TriangleMesh m = io::read_mesh(sample()).mesh;
  const std::vector<double> lib = geodesic_distances(m, {Source::at_vertex(12)}).vertex_distance;
  ASSERT_EQ(got.size(), lib.size());
  for (std::size_t v = 0; v < lib.size(); ++v) ASSERT_NEAR(got[v], lib[v], 1e-6 * (1 + lib[v])) << v;
  EXPECT_EQ(got[12], 0.0);
}

TEST(GeodesicApp, EveryOutputFormatKeepsTheFilesVertices) {
  ScratchDir dir("geodesic");
  for (const char* ext : {"ply", "glb", "gltf", "obj", "off"}) {
    const std::string out = (dir / (std::string("d.") + ext)).string();
    const auto r = run(bin(kApp) + " " + quote(sample()) + " --source-vertex 0,100 -o " + quote(out), dir);
    ASSERT_EQ(r.exit_code, 0) << ext << ": " << r.err;
    const io::ReadResult back = io::read_mesh(out);
    EXPECT_EQ(back.mesh.num_vertices(), 4494u) << ext;
    EXPECT_EQ(back.mesh.num_faces(), 9000u) << ext;
  }
}

TEST(GeodesicApp, StlIsWeldedAndWrittenInTheFilesOrder) {
  if (!have_shared_data()) GTEST_SKIP();
  ScratchDir dir("geodesic");
  const std::string stl = shared_mesh("thingi10k_88566_fence_panels.stl");
  const auto r = run(bin(kApp) + " " + quote(stl) + " --source-vertex 0 -o " + quote((dir / "d.txt").string()), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<double> got = io::read_values_txt((dir / "d.txt").string());
  const TriangleMesh raw = io::read_mesh(stl).mesh;
  ASSERT_EQ(got.size(), raw.num_vertices());   // 16,032 file vertices, not the 2,624 welded ones
  // Copies of one welded vertex carry one value, and distances cross the seams: far more
  // vertices are reached than the source's own triangle.
  const WeldResult w = weld_vertices(raw);
  std::vector<double> welded_value(w.mesh.num_vertices(), -1);
  std::size_t reached = 0;
  for (std::size_t v = 0; v < raw.num_vertices(); ++v) {
    double& seen = welded_value[w.vertex_map[v]];
    if (seen >= 0 || std::isinf(seen)) EXPECT_EQ(got[v], seen) << "copies of one point differ";
    seen = got[v];
    if (std::isfinite(got[v])) ++reached;
  }
  EXPECT_GT(reached, 100u);
}

// Doubled triangles (an export that wrote some faces twice): left out and reported, the field
// that of the mesh without them. (Before: the copies' sources bounced between them and the
// originals until memory ran out.)
TEST(GeodesicApp, DoubledFacesAreLeftOutAndReported) {
  ScratchDir dir("geodesic");
  const TriangleMesh m = io::read_mesh(sample()).mesh;
  TriangleMesh doubled = m;
  std::size_t copies = 0;
  for (std::size_t f = 0; f < m.num_faces(); f += 10, ++copies) {
    Triangle t = m.triangles[f];
    if (copies % 2) std::swap(t[1], t[2]);   // some copies reversed
    doubled.triangles.push_back(t);
  }
  const std::string in = (dir / "doubled.off").string();
  io::write_mesh(in, doubled);
  const auto r = run(bin(kApp) + " " + quote(in) + " --source-vertex 12 -o " + quote((dir / "d.txt").string()) +
                         " --stats -",
                     dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(std::to_string(copies) + " faces repeat another face's three vertices"), std::string::npos)
      << r.err;
  EXPECT_EQ(parse_json(r.out)["operations"]["duplicate_faces_skipped"].num, double(copies));
  const std::vector<double> got = io::read_values_txt((dir / "d.txt").string());
  const std::vector<double> lib = geodesic_distances(m, {Source::at_vertex(12)}).vertex_distance;
  ASSERT_EQ(got.size(), lib.size());
  for (std::size_t v = 0; v < lib.size(); ++v) ASSERT_NEAR(got[v], lib[v], 1e-6 * (1 + lib[v])) << v;
}

TEST(GeodesicApp, SourcePointSnapsToTheSurface) {
  ScratchDir dir("geodesic");
  const TriangleMesh m = io::read_mesh(sample()).mesh;
  const Vec3 p = m.positions[7];
  const std::string xyz = std::to_string(p.x) + "," + std::to_string(p.y) + "," + std::to_string(p.z);
  const auto r = run(bin(kApp) + " " + quote(sample()) + " --source-point " + xyz + " -o " +
                         quote((dir / "d.txt").string()) + " --stats -", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<double> got = io::read_values_txt((dir / "d.txt").string());
  EXPECT_LT(got[7], 1e-4);
  const JsonValue stats = JsonParser(r.out).parse();
  EXPECT_EQ(stats["result"]["vertices_reached"].num, 4494);
  EXPECT_GT(stats["operations"]["update_steps"].num, 0);
}

TEST(GeodesicApp, MaxDistanceAndDijkstra) {
  ScratchDir dir("geodesic");
  const auto full = run(bin(kApp) + " " + quote(sample()) + " --source-vertex 3 -o " + quote((dir / "full.txt").string()), dir);
  const auto cut = run(bin(kApp) + " " + quote(sample()) + " --source-vertex 3 --max-distance 20 -o " +
                           quote((dir / "cut.txt").string()), dir);
  const auto dij = run(bin(kApp) + " " + quote(sample()) + " --source-vertex 3 --method dijkstra -o " +
                           quote((dir / "dij.txt").string()), dir);
  ASSERT_EQ(full.exit_code, 0);
  ASSERT_EQ(cut.exit_code, 0);
  ASSERT_EQ(dij.exit_code, 0);
  const auto a = io::read_values_txt((dir / "full.txt").string());
  const auto b = io::read_values_txt((dir / "cut.txt").string());
  const auto d = io::read_values_txt((dir / "dij.txt").string());
  std::size_t inside = 0;
  for (std::size_t v = 0; v < a.size(); ++v) {
    if (a[v] < 19) {
      ++inside;
      EXPECT_NEAR(b[v], a[v], 1e-5 * (1 + a[v]));
    }
    if (a[v] > 21) EXPECT_TRUE(std::isinf(b[v]));
    EXPECT_GE(d[v], a[v] * 0.99);   // edge paths are never much shorter than geodesics
  }
  EXPECT_GT(inside, 20u);
}

TEST(GeodesicApp, ErrorsFollowTheContract) {
  ScratchDir dir("geodesic");
  const std::string out = (dir / "x.ply").string();
  // No source: usage error.
  EXPECT_EQ(run(bin(kApp) + " " + quote(sample()) + " -o " + quote(out), dir).exit_code, 2);
  // Vertex out of range: input error, one line naming the file, nothing written.
  const auto r = run(bin(kApp) + " " + quote(sample()) + " --source-vertex 99999 -o " + quote(out), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("fertility.off"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // Broken input file.
  write_file(dir / "broken.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n");
  const auto b = run(bin(kApp) + " " + quote((dir / "broken.ply").string()) + " --source-vertex 0 -o " + quote(out), dir);
  EXPECT_EQ(b.exit_code, 1);
  EXPECT_EQ(lines(b.err).size(), 1u) << b.err;
  EXPECT_FALSE(fs::exists(out));
  // Unknown output extension: usage error before any work.
  EXPECT_EQ(run(bin(kApp) + " " + quote(sample()) + " --source-vertex 0 -o " + quote((dir / "x.xyz1").string()), dir).exit_code, 2);
  // Bad strategy name.
  EXPECT_EQ(run(bin(kApp) + " " + quote(sample()) + " --source-vertex 0 --strategy fast -o " + quote(out), dir).exit_code, 2);
}

}  // namespace
}  // namespace gsp::test

namespace gsp::test {
namespace {

// --layout auto (the default): one field on a file whose order is coherent runs in the
// file's order (a layout costs more than it saves there, docs/scale.md); one field on a
// shuffled file gets the Z-order; several fields, or --layout on, the clustering. A plane is
// exact either way.
TEST(GeodesicApp, LayoutAutoSkipsItForOneFieldOnACoherentFile) {
  ScratchDir dir("geodesic");
  const TriangleMesh rows = grid(60);   // row-major: neighbours 1 or 61 apart
  io::write_mesh((dir / "rows.off").string(), rows);
  io::write_mesh((dir / "shuffled.off").string(), apply_layout(rows, random_layout(rows, 3)));
  // The faces in four blocks (libigl's upsample writes its children so), on a grid of 2^19
  // faces (from kSortFacesFrom faces the sort pays back), and the same few faces in blocks.
  const TriangleMesh big = grid(512);
  auto in_blocks = [](const TriangleMesh& m) {
    TriangleMesh b = m;
    b.triangles.clear();
    for (std::size_t r = 0; r < 4; ++r)
      for (std::size_t f = r; f < m.num_faces(); f += 4) b.triangles.push_back(m.triangles[f]);
    return b;
  };
  io::write_mesh((dir / "blocks.ply").string(), in_blocks(big));
  io::write_mesh((dir / "small_blocks.off").string(), in_blocks(rows));
  auto layout_of = [&](const std::string& file, const std::string& options, std::string out = "d.txt") {
    const auto r = run(quote(bin(kApp)) + " " + quote((dir / file).string()) + " " + options + " -o " +
                           quote((dir / out).string()) + " --stats -",
                       dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const JsonValue j = parse_json(r.out);
    return j["settings"]["layout"].str;
  };
  EXPECT_EQ(layout_of("rows.off", "--source-vertex 0", "auto.txt"), "input order");
  EXPECT_EQ(layout_of("shuffled.off", "--source-vertex 0"), "z-order");
  // One thread: on two, GSP's order effects reach 2e-5 at a few vertices of this plane
  // whatever the layout (the faces as stored too).
  EXPECT_EQ(layout_of("blocks.ply", "--source-vertex 0 --threads 1", "blocks.txt"), "faces by smallest vertex");
  EXPECT_EQ(layout_of("small_blocks.off", "--source-vertex 0"), "input order");
  EXPECT_EQ(layout_of("rows.off", "--source-vertex 0 --layout on", "on.txt"), "bottom-up clustering");
  EXPECT_EQ(layout_of("rows.off", "--source-vertex 0,5 --separate", "sep.txt"), "bottom-up clustering");
  EXPECT_EQ(layout_of("shuffled.off", "--source-vertex 0 --layout off"), "input order");
  EXPECT_EQ(layout_of("shuffled.off", "--source-vertex 0 --no-layout"), "input order");
  const auto a = io::read_values_txt((dir / "auto.txt").string()), b = io::read_values_txt((dir / "on.txt").string());
  ASSERT_EQ(a.size(), rows.num_vertices());
  for (std::size_t v = 0; v < a.size(); ++v) {
    EXPECT_NEAR(a[v], norm(rows.positions[v]), 1e-5 * (1 + a[v])) << v;
    EXPECT_NEAR(a[v], b[v], 1e-5 * (1 + a[v])) << v;
  }
  // In the file's vertex order (the vertices kept theirs) and exact on the plane.
  const auto c = io::read_values_txt((dir / "blocks.txt").string());
  ASSERT_EQ(c.size(), big.num_vertices());
  for (std::size_t v = 0; v < c.size(); ++v) EXPECT_NEAR(c[v], norm(big.positions[v]), 1e-5 * (1 + c[v])) << v;
  EXPECT_EQ(run(quote(bin(kApp)) + " " + quote((dir / "rows.off").string()) + " --source-vertex 0 --layout maybe -o " +
                    quote((dir / "x.txt").string()),
                dir)
                .exit_code,
            2);
}

// `base` (the app and its input) with --separate and --matrix from vertices 5, 77 and 300: each
// separate field equals the single run of its source (`single` added to those runs), the
// matrix holds those fields at the three sources.
void check_separate_and_matrix(const std::string& base, const std::string& single, const ScratchDir& dir) {
  ASSERT_EQ(run(base + " --source-vertex 5,77,300 --separate --threads 2 -o " + quote((dir / "f.txt").string()), dir).exit_code, 0);
  ASSERT_EQ(run(base + " --source-vertex 5,77,300 --matrix -o " + quote((dir / "m.csv").string()), dir).exit_code, 0);
  const Index vs[3] = {5, 77, 300};
  const std::vector<std::string> rows = lines(slurp(dir / "m.csv"));
  ASSERT_EQ(rows.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(run(base + " --source-vertex " + std::to_string(vs[i]) + single + " -o " + quote((dir / "one.txt").string()), dir).exit_code, 0);
    const auto one = io::read_values_txt((dir / "one.txt").string());
    const auto sep = io::read_values_txt((dir / ("f-" + std::to_string(i) + ".txt")).string());
    ASSERT_EQ(sep, one) << "field " << i;
    EXPECT_EQ(one[vs[i]], 0.0);
    std::stringstream row(rows[i]);
    for (int j = 0; j < 3; ++j) {
      std::string cell;
      std::getline(row, cell, ',');
      EXPECT_NEAR(std::stod(cell), one[vs[j]], 1e-6 * (1 + one[vs[j]]));
      if (j != i) EXPECT_GT(std::stod(cell), 0.0);
    }
  }
}

TEST(GeodesicApp, SeparateFieldsAndMatrixMatchSingleRuns) {
  ScratchDir dir("geodesic");
  const std::string base = quote(bin(kApp)) + " " + quote(sample());
  // --layout on: the clustering the batch runs use (auto may pick the Z-order for one field).
  check_separate_and_matrix(base, " --layout on", dir);
  // The modes exclude each other, need vertex sources and a text output.
  EXPECT_EQ(run(base + " --source-vertex 1,2 --separate --matrix -o " + quote((dir / "x.txt").string()), dir).exit_code, 2);
  EXPECT_EQ(run(base + " --source-point 0,0,0 --matrix -o " + quote((dir / "x.txt").string()), dir).exit_code, 2);
  EXPECT_EQ(run(base + " --source-vertex 1,2 --matrix -o " + quote((dir / "x.ply").string()), dir).exit_code, 2);
}

}  // namespace
}  // namespace gsp::test

namespace gsp::test {
namespace {

TEST(GeodesicApp, PointCloudDomain) {
  ScratchDir dir("geodesic");
  const std::string app = quote(bin(kApp));
  // The mesh's vertices as a cloud: close to the mesh's own field.
  ASSERT_EQ(run(app + " " + quote(sample()) + " --domain points --source-vertex 0 -o " + quote((dir / "p.txt").string()), dir).exit_code, 0);
  ASSERT_EQ(run(app + " " + quote(sample()) + " --source-vertex 0 -o " + quote((dir / "m.txt").string()), dir).exit_code, 0);
  ASSERT_EQ(run(app + " " + quote(sample()) + " --domain points --method graph-gsp --source-vertex 0 -o " +
                    quote((dir / "g.txt").string()), dir).exit_code, 0);
  const auto p = io::read_values_txt((dir / "p.txt").string());
  const auto g = io::read_values_txt((dir / "g.txt").string());
  const auto m = io::read_values_txt((dir / "m.txt").string());
  ASSERT_EQ(p.size(), m.size());
  ASSERT_EQ(g.size(), m.size());
  double sum = 0, sum_graph = 0;
  for (std::size_t v = 1; v < p.size(); ++v) {
    sum += std::abs(p[v] - m[v]) / m[v];
    sum_graph += std::abs(g[v] - m[v]) / m[v];
  }
  // Measured: 0.3% on the local triangles, 0.5% over the links (docs/pointcloud.md).
  EXPECT_LT(sum / double(p.size() - 1), 0.01);
  EXPECT_LT(sum_graph / double(p.size() - 1), 0.03);
  EXPECT_EQ(run(app + " " + quote(sample()) + " --method graph-gsp --source-vertex 0 -o " + quote((dir / "x.txt").string()), dir)
                .exit_code,
            2);   // a method of point clouds only
  // A file without faces is a cloud by itself; --source-face makes no sense there.
  if (have_shared_data()) {
    const std::string kitten = quote(shared_mesh("kitten_points.xyz"));
    const auto r = run(app + " " + kitten + " --source-point 0,0,0 -o " + quote((dir / "k.ply").string()) + " --stats -", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const JsonValue stats = parse_json(r.out);
    EXPECT_EQ(stats["cloud"]["points"].num, 5210);
    EXPECT_EQ(stats["result"]["points_reached"].num, 5210);
    EXPECT_GT(stats["cloud"]["local_triangles"].num, 5210);   // about two per point
    EXPECT_GE(stats["operations"]["points_reached_over_links"].num, 0);
    EXPECT_EQ(io::read_mesh((dir / "k.ply").string()).mesh.num_vertices(), 5210u);
    // A preview of a cloud is drawn on its local triangles (also with the graph methods).
    for (const char* method : {"gsp", "dijkstra"}) {
      const std::filesystem::path png = dir / (std::string(method) + ".png");
      const auto p = run(app + " " + kitten + " --source-vertex 0 --method " + method + " -o " +
                             quote((dir / "kp.txt").string()) + " --png " + quote(png.string()) + " --png-size 200",
                         dir);
      ASSERT_EQ(p.exit_code, 0) << p.err;
      const render::Image image = render::read_png(png.string());
      ASSERT_EQ(image.width, 200);
      std::size_t drawn = 0;
      for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
          const auto px = image.pixel(x, y);
          drawn += !(px[0] == 255 && px[1] == 255 && px[2] == 255);
        }
      EXPECT_GT(drawn, 200u * 200u / 10) << method;   // the kitten, not an empty frame
      EXPECT_LT(drawn, 200u * 200u * 9 / 10) << method;
    }
    EXPECT_EQ(run(app + " " + kitten + " --source-face 0:0.2,0.2 -o " + quote((dir / "x.txt").string()), dir).exit_code, 2);
    EXPECT_EQ(run(app + " " + kitten + " --domain mesh --source-vertex 0 -o " + quote((dir / "x.txt").string()), dir).exit_code, 1);
  }
}

}  // namespace
}  // namespace gsp::test

namespace gsp::test {
namespace {

// A cloud's --separate fields equal its single-source runs, and its --matrix holds them at the
// source points (both were a usage error before: meshes only).
TEST(GeodesicApp, PointCloudSeparateAndMatrix) {
  ScratchDir dir("geodesic");
  const std::string base = quote(bin(kApp)) + " " + quote(sample()) + " --domain points";
  check_separate_and_matrix(base, "", dir);
  EXPECT_EQ(run(base + " --source-point 0,0,0 --matrix -o " + quote((dir / "x.txt").string()), dir).exit_code, 2);
}

}  // namespace
}  // namespace gsp::test

namespace gsp::test {
namespace {

// --method windows: exact on a plane from two sources (distance to the nearer), never below the
// straight line on fertility, and the options it does not take refused with a usage error.
TEST(GeodesicApp, MethodWindows) {
  ScratchDir dir("geodesic");
  const TriangleMesh plane = grid(30);
  io::write_mesh((dir / "plane.off").string(), plane);
  const Index a = 0, b = Index(plane.num_vertices() - 1);
  const auto r = run(quote(bin(kApp)) + " " + quote((dir / "plane.off").string()) + " --source-vertex " +
                         std::to_string(a) + "," + std::to_string(b) + " --method windows -o " +
                         quote((dir / "w.txt").string()),
                     dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto d = io::read_values_txt((dir / "w.txt").string());
  ASSERT_EQ(d.size(), plane.num_vertices());
  for (std::size_t v = 0; v < d.size(); ++v) {
    const double exact = std::min(distance(plane.positions[v], plane.positions[a]), distance(plane.positions[v], plane.positions[b]));
    EXPECT_NEAR(d[v], exact, 1e-7 * (1 + exact)) << v;   // the .txt keeps 9 digits
  }
  const auto f = run(quote(bin(kApp)) + " " + quote(sample()) + " --source-vertex 12 --method windows -o " +
                         quote((dir / "f.txt").string()),
                     dir);
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const TriangleMesh m = io::read_mesh(sample()).mesh;
  const auto w = io::read_values_txt((dir / "f.txt").string());
  for (std::size_t v = 0; v < w.size(); ++v) EXPECT_GE(w[v], distance(m.positions[v], m.positions[12]) * (1 - 1e-7)) << v;
  EXPECT_EQ(run(quote(bin(kApp)) + " " + quote(sample()) + " --source-vertex 1 --metric direction=1,0,0:ratio=2 --method windows -o " +
                    quote((dir / "x.txt").string()),
                dir)
                .exit_code,
            2);
}

// --method windows takes what GSP's fields take (session 26): a point in a face (on the
// input's triangles: exact on a plane), --max-distance (the field cut there), --separate and
// --matrix (equal to the single runs).
TEST(GeodesicApp, MethodWindowsFacePointsLimitsAndBatches) {
  ScratchDir dir("geodesic");
  const TriangleMesh plane = jittered_grid(20, 0.3, 5);
  io::write_mesh((dir / "plane.off").string(), plane);
  const std::string app = quote(bin(kApp)) + " " + quote((dir / "plane.off").string()) + " --method windows";
  const Index f = 100;
  const std::array<double, 3> b{0.5, 0.2, 0.3};   // --source-face F:U,V takes corners 1 and 2
  const Vec3 p = SurfacePoint::in_face(f, b).position(plane);
  ASSERT_EQ(run(app + " --source-face " + std::to_string(f) + ":0.2,0.3 -o " + quote((dir / "p.txt").string()), dir).exit_code, 0);
  const auto d = io::read_values_txt((dir / "p.txt").string());
  ASSERT_EQ(d.size(), plane.num_vertices());
  for (std::size_t v = 0; v < d.size(); ++v) EXPECT_NEAR(d[v], distance(plane.positions[v], p), 1e-7 * (1 + d[v])) << v;
  ASSERT_EQ(run(app + " --source-face " + std::to_string(f) + ":0.2,0.3 --max-distance 0.3 -o " + quote((dir / "c.txt").string()), dir)
                .exit_code,
            0);
  const auto c = io::read_values_txt((dir / "c.txt").string());
  std::size_t cut = 0;
  for (std::size_t v = 0; v < c.size(); ++v) {
    if (d[v] <= 0.3 * (1 - 1e-6)) EXPECT_EQ(c[v], d[v]) << v;
    if (d[v] > 0.3 * (1 + 1e-6)) {
      EXPECT_TRUE(std::isinf(c[v])) << v;
      ++cut;
    }
  }
  EXPECT_GT(cut, 0u);
  check_separate_and_matrix(quote(bin(kApp)) + " " + quote(sample()) + " --method windows", "", dir);
}

}  // namespace
}  // namespace gsp::test
