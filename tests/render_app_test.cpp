// Integration tests of gsp-render, run as a user runs it: exit codes, error lines, the PNG it
// writes (size, what is where), --field vs --property agreement, stats.
#include "apps_support.hpp"
#include "render_support.hpp"
#include "test_data.hpp"

#include <gsp/io/mesh_io.hpp>
#include <gsp/render/image.hpp>

#include <cmath>

namespace {

using gsp::test::parse_json;
using gsp::test::quote;
using gsp::test::run;
using gsp::test::ScratchDir;
namespace fs = std::filesystem;

const std::string kRender = gsp::test::bin("gsp-render");

std::string fertility() { return gsp::test::shared_mesh("fertility.off"); }

// Euclidean distance from vertex 0, one value per vertex, as gsp-geodesic would write it.
std::vector<double> distance_field(const gsp::TriangleMesh& m) {
  std::vector<double> d;
  for (const gsp::Vec3& p : m.positions) d.push_back(gsp::distance(p, m.positions[0]));
  return d;
}

TEST(RenderApp, FieldPictureHasTheAskedSizeAndColours) {
  if (!gsp::test::have_shared_data()) GTEST_SKIP() << "shared meshes not found";
  ScratchDir dir("render-app");
  const gsp::TriangleMesh mesh = gsp::io::read_mesh(fertility()).mesh;
  gsp::io::write_values_txt((dir / "d.txt").string(), distance_field(mesh));
  const auto r = run(quote(kRender) + " " + quote(fertility()) + " --field " + quote((dir / "d.txt").string()) +
                         " -o " + quote((dir / "f.png").string()) + " --size 160x120 --iso 10 --view 0,20 --quiet",
                     dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "");
  const gsp::render::Image im = gsp::render::read_png((dir / "f.png").string());
  EXPECT_EQ(im.width, 160);
  EXPECT_EQ(im.height, 120);
  const std::size_t coloured = gsp::test::count_if(im, [](int, int, gsp::render::Rgba c) {
    return !(c[0] == c[1] && c[1] == c[2]);   // anything but white/grey
  });
  EXPECT_GT(coloured, 160u * 120u / 10);
  EXPECT_EQ(dir.entries().size(), 2u);   // d.txt and f.png, no temporaries
}

TEST(RenderApp, PlyPropertyGivesTheSamePictureAsTheTextField) {
  if (!gsp::test::have_shared_data()) GTEST_SKIP() << "shared meshes not found";
  ScratchDir dir("render-app");
  const gsp::TriangleMesh mesh = gsp::io::read_mesh(fertility()).mesh;
  const std::vector<double> d = distance_field(mesh);
  // Through float, as a PLY property stores it: the text file gets the same rounded values.
  std::vector<float> df(d.begin(), d.end());
  std::vector<double> dd(df.begin(), df.end());
  gsp::io::write_values_txt((dir / "d.txt").string(), dd);
  gsp::io::write_mesh((dir / "m.ply").string(), mesh, {{{"distance", df}}, {}, {}});
  const std::string common = " --size 96 --wireframe --colormap turbo --quiet";
  auto a = run(quote(kRender) + " " + quote((dir / "m.ply").string()) + " --property distance -o " +
                   quote((dir / "a.png").string()) + common,
               dir);
  auto b = run(quote(kRender) + " " + quote((dir / "m.ply").string()) + " --field " + quote((dir / "d.txt").string()) +
                   " -o " + quote((dir / "b.png").string()) + common,
               dir);
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(gsp::render::read_png((dir / "a.png").string()).rgba, gsp::render::read_png((dir / "b.png").string()).rgba);

  const auto missing = run(quote(kRender) + " " + quote((dir / "m.ply").string()) + " --property nope -o " +
                               quote((dir / "c.png").string()),
                           dir);
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("nope"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("distance"), std::string::npos) << missing.err;   // lists what there is
  EXPECT_FALSE(fs::exists(dir / "c.png"));
}

TEST(RenderApp, LabelPropertyColoursFacesByTheirCornersLabel) {
  // A quad strip in z = 0 whose left half is labelled 0 and right half 1 (per vertex, PLY int).
  ScratchDir dir("render-app");
  gsp::TriangleMesh m;
  for (int i = 0; i <= 4; ++i) {
    m.positions.push_back({double(i), 0, 0});
    m.positions.push_back({double(i), 1, 0});
  }
  for (gsp::Index i = 0; i < 4; ++i) {
    m.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3});
    m.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
  }
  std::vector<std::int32_t> label;
  for (const gsp::Vec3& p : m.positions) label.push_back(p.x < 2.5 ? 0 : 1);
  gsp::io::write_mesh((dir / "s.ply").string(), m, {{}, {{"region", label}}, {}});
  const auto r = run(quote(kRender) + " " + quote((dir / "s.ply").string()) +
                         " --label-property region --up z --view 0,90 --size 200 -o " + quote((dir / "s.png").string()),
                     dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const gsp::render::Image im = gsp::render::read_png((dir / "s.png").string());
  // Seen from above: x runs left to right, the strip over pixels ~11..189 (44.5 px per unit).
  // Faces between x = 2 and 3 mix labels; the outer quads are pure.
  const gsp::render::Rgba left = im.pixel(30, 100), right = im.pixel(170, 100);
  EXPECT_FALSE(gsp::test::near(left, right, 20));
  EXPECT_TRUE(gsp::test::near(left, im.pixel(50, 105), 2));
  EXPECT_TRUE(gsp::test::near(right, im.pixel(155, 95), 2));
  EXPECT_FALSE(gsp::test::same(left, {255, 255, 255, 255}));
  const auto bad = run(quote(kRender) + " " + quote((dir / "s.ply").string()) + " --label-property nope -o " +
                           quote((dir / "t.png").string()),
                       dir);
  EXPECT_EQ(bad.exit_code, 1);
}

TEST(RenderApp, BadInputIsExitOneAndNamesTheFile) {
  if (!gsp::test::have_shared_data()) GTEST_SKIP() << "shared meshes not found";
  ScratchDir dir("render-app");
  gsp::test::write_file(dir / "short.txt", "1\n2\n3\n");
  auto r = run(quote(kRender) + " " + quote(fertility()) + " --field " + quote((dir / "short.txt").string()) + " -o " +
                   quote((dir / "x.png").string()),
               dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("short.txt"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("4494"), std::string::npos) << r.err;
  EXPECT_EQ(gsp::test::lines(r.err).size(), 1u);
  EXPECT_FALSE(fs::exists(dir / "x.png"));

  gsp::test::write_file(dir / "path.txt", "0 0 0\n1 1 oops\n");
  r = run(quote(kRender) + " " + quote(fertility()) + " --polylines " + quote((dir / "path.txt").string()) + " -o " +
              quote((dir / "x.png").string()),
          dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("path.txt:line 2"), std::string::npos) << r.err;

  r = run(quote(kRender) + " " + quote((dir / "absent.obj").string()) + " -o " + quote((dir / "x.png").string()), dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("absent.obj"), std::string::npos) << r.err;
}

TEST(RenderApp, UsageErrorsAreExitTwo) {
  ScratchDir dir("render-app");
  const std::string mesh = quote(gsp::test::shared_mesh("fertility.off"));
  const std::string out = " -o " + quote((dir / "x.png").string());
  for (const std::string& args :
       {mesh + out + " --size 0", mesh + out + " --size 10x", mesh + out + " --view 10", mesh + out + " --view a,b",
        mesh + " -o " + quote((dir / "x.jpg").string()), mesh + out + " --colormap jet", mesh + out + " --iso -1",
        mesh + out + " --range 2,1", mesh + out + " --background pink", mesh + out + " --field a.txt --property q", mesh + out + " --labels a.txt --label-property q",
        mesh}) {
    const auto r = run(quote(kRender) + " " + args, dir);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(RenderApp, PointCloudPolylinesSourcesAndStats) {
  if (!gsp::test::have_shared_data()) GTEST_SKIP() << "shared meshes not found";
  ScratchDir dir("render-app");
  gsp::test::write_file(dir / "path.txt", "# two polylines\n0 0 0\n0.1, 0.1, 0.1\n\n0 0 0\n-0.1 0 0\n");
  const auto r = run(quote(kRender) + " " + quote(gsp::test::shared_mesh("kitten_points.xyz")) + " --polylines " +
                         quote((dir / "path.txt").string()) + " --source-point 0,0,0 --size 128 --up z --aa -o " +
                         quote((dir / "k.png").string()) + " --stats -",
                     dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto stats = parse_json(r.out);
  EXPECT_EQ(stats["input"]["vertices"].num, 5210);
  EXPECT_GE(stats["timings"]["compute"].num, 0.0);
  EXPECT_GE(stats["timings"]["build"].num, 0.0);
  EXPECT_EQ(stats["operations"]["rays"].num, 128 * 128 * 4);
  const gsp::render::Image im = gsp::render::read_png((dir / "k.png").string());
  EXPECT_EQ(im.width, 128);
  const std::size_t drawn = gsp::test::count_if(im, [](int, int, gsp::render::Rgba c) { return c[0] < 250; });
  EXPECT_GT(drawn, 128u * 128u / 20);
}

}  // namespace
