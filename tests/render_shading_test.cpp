// What gsp::render draws on the surface: colour-map colours, iso-lines, wireframe, unreached
// grey, labels, overlays. Each test renders a small picture and checks pixel statistics.
#include "helpers/mesh_builders.hpp"
#include "render_support.hpp"

#include <gsp/io/colormap.hpp>
#include <gsp/render/render.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace gsp;
using gsp::test::count_if;
using gsp::test::luminance;
using gsp::test::near;
using gsp::test::same;

constexpr double kPi = 3.14159265358979323846;

render::RenderOptions options(int size, int iso) {
  render::RenderOptions o;
  o.width = o.height = size;
  o.iso_lines = iso;
  return o;
}

// The view (y up) whose centre ray runs through the unit-sphere point p towards the centre.
void look_at_point(render::RenderOptions& o, Vec3 p) {
  o.elevation = std::asin(p.y) * 180.0 / kPi;
  o.azimuth = std::atan2(p.x, p.z) * 180.0 / kPi;
}

std::vector<double> distance_from(const TriangleMesh& m, Vec3 s) {
  std::vector<double> d;
  for (const Vec3& p : m.positions) d.push_back(distance(p, s));
  return d;
}

std::vector<double> height(const TriangleMesh& m) {
  std::vector<double> h;
  for (const Vec3& p : m.positions) h.push_back(p.y);
  return h;
}

TEST(RenderShading, SourcePixelHasTheColourMapsZeroColour) {
  render::Scene scene;
  scene.mesh = test::icosphere(4);
  const Vec3 source = scene.mesh.positions[0];
  scene.vertex_field = distance_from(scene.mesh, source);
  for (auto map : {io::ColorMap::viridis, io::ColorMap::turbo}) {
    render::RenderOptions o = options(101, 20);   // odd: pixel 50's centre is the picture's centre
    o.colormap = map;
    look_at_point(o, source);
    const render::Image im = render::render(scene, o);
    // Head-on, the headlight gives full brightness: the colour is the map's own.
    const render::Rgba zero = io::colormap(map, 0.0);
    EXPECT_TRUE(near(im.pixel(50, 50), zero, 2)) << int(im.pixel(50, 50)[0]) << "," << int(im.pixel(50, 50)[1])
                                                 << "," << int(im.pixel(50, 50)[2]);
    // And the far side of the visible field is brighter in viridis' sense: not the zero colour.
    EXPECT_FALSE(near(im.pixel(50, 8), zero, 10));
  }
  // With the source marked, the same pixel shows the red marker.
  scene.sources = {source};
  render::RenderOptions o = options(101, 20);
  look_at_point(o, source);
  const render::Image im = render::render(scene, o);
  EXPECT_TRUE(near(im.pixel(50, 50), o.source_color, 2));
}

// Dark pixels: at least 15% darker than in the same picture without lines.
std::size_t darker_pixels(const render::Image& with, const render::Image& without) {
  std::size_t n = 0;
  for (int y = 0; y < with.height; ++y)
    for (int x = 0; x < with.width; ++x)
      n += luminance(with.pixel(x, y)) < 0.85 * luminance(without.pixel(x, y)) ? 1 : 0;
  return n;
}

TEST(RenderShading, IsoLinePixelsGrowWithTheNumberOfLevels) {
  render::Scene scene;
  scene.mesh = test::icosphere(5);
  scene.vertex_field = height(scene.mesh);
  render::RenderOptions o = options(256, 0);
  o.elevation = 0.0;
  o.azimuth = 0.0;
  const render::Image none = render::render(scene, o);
  std::size_t previous = 0;
  std::vector<std::size_t> counts;
  for (int levels : {2, 5, 10, 20}) {
    o.iso_lines = levels;
    const std::size_t n = darker_pixels(render::render(scene, o), none);
    EXPECT_GT(n, previous) << levels << " levels";
    counts.push_back(n);
    previous = n;
  }
  // Lines of constant width: 19 lines cover about 19/9 as much as 9 (less near the rim).
  EXPECT_GT(double(counts[3]) / double(counts[2]), 1.6);
  EXPECT_LT(double(counts[3]) / double(counts[2]), 2.4);
}

TEST(RenderShading, SingleIsoLineOfHeightIsTheEquatorRow) {
  // Field = height on the unit sphere, range [-1, 1], 2 intervals: one line at y = 0. Seen from
  // the front the equator's plane contains the eye, so it projects onto the middle row.
  render::Scene scene;
  scene.mesh = test::icosphere(5);
  scene.vertex_field = height(scene.mesh);
  render::RenderOptions o = options(200, 0);
  o.elevation = 0.0;
  o.azimuth = 0.0;
  const render::Image none = render::render(scene, o);
  o.iso_lines = 2;
  const render::Image one = render::render(scene, o);
  int dark = 0, off_row = 0;
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x)
      if (luminance(one.pixel(x, y)) < 0.85 * luminance(none.pixel(x, y))) {
        ++dark;
        off_row += std::abs(y + 0.5 - 100.0) > 2.0 ? 1 : 0;
      }
  EXPECT_GT(dark, 150);   // the equator spans ~180 px
  EXPECT_EQ(off_row, 0);
}

TEST(RenderShading, WireframeOnlyDarkens) {
  render::Scene scene;
  scene.mesh = test::icosphere(1);   // 80 faces: edges far apart
  render::RenderOptions o = options(160, 0);
  const render::Image plain = render::render(scene, o);
  o.wireframe = true;
  const render::Image wire = render::render(scene, o);
  std::size_t surface = 0, darkened = 0, brighter = 0;
  for (int y = 0; y < 160; ++y)
    for (int x = 0; x < 160; ++x) {
      const render::Rgba a = plain.pixel(x, y), b = wire.pixel(x, y);
      if (same(a, o.background)) {
        EXPECT_TRUE(same(b, o.background));
        continue;
      }
      ++surface;
      darkened += luminance(b) < 0.7 * luminance(a) ? 1 : 0;
      for (int k = 0; k < 3; ++k) brighter += b[k] > a[k] ? 1 : 0;
    }
  EXPECT_EQ(brighter, 0u);
  // ~120 visible-ish edges of ~20 px, 1-2 px wide, over ~12000 surface pixels.
  EXPECT_GT(double(darkened) / double(surface), 0.05);
  EXPECT_LT(double(darkened) / double(surface), 0.5);
}

TEST(RenderShading, UnreachedValuesAreGrey) {
  render::Scene scene;
  scene.mesh = test::icosphere(4);
  scene.vertex_field = height(scene.mesh);
  for (std::size_t v = 0; v < scene.vertex_field.size(); ++v)
    if (scene.mesh.positions[v].y > 0.2)
      scene.vertex_field[v] = (v % 2) ? std::numeric_limits<double>::infinity() : std::nan("");
  render::RenderOptions o = options(128, 10);
  o.elevation = 0.0;
  const render::Image im = render::render(scene, o);
  auto grey = [](render::Rgba c) { return c[0] == c[1] && c[1] == c[2]; };
  // Upper part (y > 0.2 is above row ~ 64 - 0.2 * 60): grey; lower part: coloured.
  EXPECT_TRUE(grey(im.pixel(64, 20)));
  EXPECT_LT(im.pixel(64, 20)[0], 140);   // the grey, shaded: never the white background
  EXPECT_FALSE(grey(im.pixel(64, 100)));
}

TEST(RenderShading, FaceLabelsGetDistinctColours) {
  render::Scene scene;
  scene.mesh = test::icosphere(4);
  for (const Triangle& t : scene.mesh.triangles) {
    const double cx = scene.mesh.positions[t[0]].x + scene.mesh.positions[t[1]].x + scene.mesh.positions[t[2]].x;
    scene.face_labels.push_back(cx < 0 ? 0 : 1);
  }
  render::RenderOptions o = options(128, 0);
  o.azimuth = 0.0;
  o.elevation = 0.0;
  const render::Image im = render::render(scene, o);
  const render::Rgba left = im.pixel(40, 64), right = im.pixel(88, 64);
  // Normalised chromaticity differs (shading alone would scale all channels alike).
  auto chroma = [](render::Rgba c, int k) { return double(c[k]) / (double(c[0]) + c[1] + c[2] + 1e-9); };
  double diff = 0;
  for (int k = 0; k < 3; ++k) diff += std::abs(chroma(left, k) - chroma(right, k));
  EXPECT_GT(diff, 0.1);
}

TEST(RenderShading, IsoLinesAreDrawnOverLabels) {
  // Voronoi regions with distance lines: the labels give the colour, the field the lines.
  render::Scene scene;
  scene.mesh = test::icosphere(4);
  scene.face_labels.assign(scene.mesh.num_faces(), 3);
  render::RenderOptions o = options(128, 10);
  const render::Image labels_only = render::render(scene, o);
  scene.vertex_field = height(scene.mesh);
  const render::Image with_field = render::render(scene, o);
  o.iso_lines = 0;
  const render::Image no_lines = render::render(scene, o);
  EXPECT_EQ(no_lines.rgba, labels_only.rgba);        // the field does not change the colour
  EXPECT_GT(darker_pixels(with_field, labels_only), 300u);
}

TEST(RenderShading, PolylineTubeIsDrawnInTheLineColour) {
  render::Scene scene;
  scene.polylines = {{{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}}};
  scene.line_radius = 0.05;
  render::RenderOptions o = options(200, 0);
  o.azimuth = 0.0;
  o.elevation = 0.0;
  const render::Image im = render::render(scene, o);
  auto tube = [&](render::Rgba c) { return !same(c, o.background); };
  const auto b = gsp::test::box_of(im, tube);
  ASSERT_FALSE(b.empty());
  // Spans the picture's width minus the margin, and is thin: 2 r = 0.1 of a length-2 line.
  EXPECT_GT(b.x1 - b.x0, 150);
  EXPECT_LT(b.y1 - b.y0, 16);
  EXPECT_NEAR(0.5 * (b.y0 + b.y1 + 1), 100.0, 1.5);
  const render::Rgba c = im.pixel(100, 100);
  EXPECT_GT(c[0], c[1]);
  EXPECT_GT(c[1], c[2]);
}

TEST(RenderShading, ThreadCountDoesNotChangeThePicture) {
  render::Scene scene;
  scene.mesh = test::icosphere(3);
  scene.vertex_field = height(scene.mesh);
  scene.points = {{0, 1.1, 0}};
  render::RenderOptions o = options(96, 8);
  o.wireframe = true;
  o.threads = 1;
  const render::Image one = render::render(scene, o);
  o.threads = 3;
  EXPECT_EQ(render::render(scene, o).rgba, one.rgba);
}

TEST(RenderShading, SupersamplingSoftensOnlyTheSilhouette) {
  render::Scene scene;
  scene.mesh = test::icosphere(4);
  render::RenderOptions o = options(96, 0);
  const render::Image hard = render::render(scene, o);
  o.supersample = 2;
  const render::Image soft = render::render(scene, o);
  std::size_t partial = 0;
  for (int y = 2; y < 94; ++y)
    for (int x = 2; x < 94; ++x) {
      // Pixels whose 5x5 neighbourhood is all surface or all background change little.
      int fg = 0;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) fg += same(hard.pixel(x + dx, y + dy), o.background) ? 0 : 1;
      if (fg == 0 || fg == 25) {
        EXPECT_TRUE(near(hard.pixel(x, y), soft.pixel(x, y), 6)) << x << "," << y;
      } else if (!same(soft.pixel(x, y), o.background) && luminance(soft.pixel(x, y)) > luminance(hard.pixel(x, y)) + 8 &&
                 same(hard.pixel(x, y), o.background) == false) {
        ++partial;   // a surface pixel blended with the background
      }
    }
  EXPECT_GT(partial, 20u);
}

}  // namespace
