// PNG output of gsp::render: exact round trip through libpng, atomic writes, errors, and the
// field preview that gsp-geodesic --png writes.
#include "helpers/mesh_builders.hpp"
#include "render_support.hpp"

#include <gsp/errors.hpp>
#include <gsp/render/render.hpp>

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace {

using namespace gsp;
namespace fs = std::filesystem;

class RenderPng : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("gsp-render-png-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::size_t files() const {
    return std::size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }
  fs::path dir_;
};

TEST_F(RenderPng, RoundTripKeepsEveryByteIncludingAlpha) {
  render::Image im(37, 23);   // odd sizes: no row padding assumptions
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      im.set(x, y, {std::uint8_t(7 * x + y), std::uint8_t(x * y), std::uint8_t(255 - 3 * y), std::uint8_t((x + 2 * y) % 256)});
  render::write_png(path("a.png"), im);
  const render::Image back = render::read_png(path("a.png"));
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 23);
  EXPECT_EQ(back.rgba, im.rgba);
  EXPECT_EQ(files(), 1u);   // no temporary left behind
}

TEST_F(RenderPng, RenderedPictureRoundTrips) {
  render::Scene scene;
  scene.mesh = test::icosphere(2);
  std::vector<double> f;
  for (const Vec3& p : scene.mesh.positions) f.push_back(p.x + p.y);
  scene.vertex_field = f;
  render::RenderOptions o;
  o.width = 64;
  o.height = 48;
  o.background = {0, 0, 0, 0};   // transparent
  const render::Image im = render::render(scene, o);
  EXPECT_EQ(im.pixel(0, 0)[3], 0);
  EXPECT_EQ(im.pixel(32, 24)[3], 255);
  render::write_png(path("b.png"), im);
  EXPECT_EQ(render::read_png(path("b.png")).rgba, im.rgba);
}

TEST_F(RenderPng, OverwritesWholeAndFailsWithoutLeavingFiles) {
  render::write_png(path("c.png"), render::Image(4, 4, {1, 2, 3, 255}));
  render::write_png(path("c.png"), render::Image(9, 5, {9, 8, 7, 255}));
  const render::Image back = render::read_png(path("c.png"));
  EXPECT_EQ(back.width, 9);
  EXPECT_TRUE(gsp::test::same(back.pixel(8, 4), {9, 8, 7, 255}));
  EXPECT_THROW(render::write_png(path("missing/d.png"), render::Image(2, 2)), IoError);
  EXPECT_THROW(render::write_png(path("e.png"), render::Image()), InvalidInput);
  EXPECT_EQ(files(), 1u);
}

TEST_F(RenderPng, ReadingSomethingElseIsAnIoError) {
  std::ofstream(path("not.png")) << "P6 1 1 255\nabc";
  EXPECT_THROW(render::read_png(path("not.png")), IoError);
  EXPECT_THROW(render::read_png(path("absent.png")), IoError);
  try {
    render::read_png(path("not.png"));
  } catch (const IoError& e) {
    EXPECT_EQ(e.path, path("not.png"));
  }
}

TEST_F(RenderPng, FieldPreviewShowsFieldAndSource) {
  const TriangleMesh mesh = test::icosphere(3);
  std::vector<double> d;
  for (const Vec3& p : mesh.positions) d.push_back(distance(p, mesh.positions[5]));
  render::RenderOptions o;
  o.width = o.height = 121;
  // Look straight at vertex 5 = (0, 1, t) / |.| : azimuth 0, elevation atan(1 / t).
  o.azimuth = 0.0;
  o.elevation = std::atan2(mesh.positions[5].y, mesh.positions[5].z) * 180.0 / 3.14159265358979323846;
  render::render_field_preview(path("p.png"), mesh, d, {mesh.positions[5]}, o);
  const render::Image im = render::read_png(path("p.png"));
  ASSERT_EQ(im.width, 121);
  ASSERT_EQ(im.height, 121);
  EXPECT_TRUE(gsp::test::near(im.pixel(60, 60), o.source_color, 2));
  // Away from the marker the field is coloured (not the plain surface grey, not red).
  const render::Rgba side = im.pixel(60, 100);
  EXPECT_FALSE(side[0] == side[1] && side[1] == side[2]);
  EXPECT_LT(side[0], 150);
}

}  // namespace
