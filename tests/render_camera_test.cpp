// Framing and projection of gsp::render: what fills how much of the picture, where.
// Expected values are closed forms of a pinhole camera at distance D = margin R / sin(fov/2)
// from the bounding sphere's centre (R its radius).
#include "helpers/mesh_builders.hpp"
#include "render_support.hpp"

#include <gsp/errors.hpp>
#include <gsp/render/render.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace gsp;
using gsp::test::box_of;
using gsp::test::count_if;
using gsp::test::same;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

render::RenderOptions plain(int w, int h) {
  render::RenderOptions o;
  o.width = w;
  o.height = h;
  o.iso_lines = 0;
  return o;
}

// Unit square [-0.5, 0.5]^2 in the plane normal to the up axis, through the origin.
TriangleMesh floor_square(render::UpAxis up) {
  TriangleMesh m;
  if (up == render::UpAxis::y)
    m.positions = {{-0.5, 0, -0.5}, {0.5, 0, -0.5}, {0.5, 0, 0.5}, {-0.5, 0, 0.5}};
  else
    m.positions = {{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

TEST(RenderCamera, UnitSphereFillsTheClosedFormDisc) {
  render::Scene scene;
  scene.mesh = test::icosphere(5);   // 20480 faces: the silhouette is within 0.1% of the sphere's
  for (double fov : {30.0, 50.0}) {
    render::RenderOptions o = plain(256, 256);
    o.fov = fov;
    const render::Image im = render::render(scene, o);
    const double half = 0.5 * fov * kDeg;
    const double D = o.margin * 1.0 / std::sin(half);
    const double alpha = std::asin(1.0 / D);                       // the sphere's angular radius
    const double rho = std::tan(alpha) / std::tan(half);            // its radius in half-pictures
    const double expected = kPi * rho * rho / 4.0;                  // disc / picture area
    const double filled = double(count_if(im, [&](int, int, render::Rgba c) { return !same(c, o.background); })) /
                          (256.0 * 256.0);
    EXPECT_NEAR(filled, expected, 0.01 * expected) << "fov " << fov;
  }
}

// Seen straight from above, the square's image is a square box centred in the picture, with
// half-side 0.5 / (D tan(fov/2)) half-pictures, R = sqrt(1/2).
void expect_square_box(render::UpAxis up, int w, int h) {
  render::Scene scene;
  scene.mesh = floor_square(up);
  render::RenderOptions o = plain(w, h);
  o.up = up;
  o.elevation = 90.0;
  o.azimuth = 0.0;
  const render::Image im = render::render(scene, o);
  const double half = 0.5 * o.fov * kDeg;
  const double D = o.margin * std::sqrt(0.5) / std::sin(half);
  const double side_px = 0.5 / (D * std::tan(half)) * 0.5 * std::min(w, h);   // half-side in pixels
  const auto b = box_of(im, [&](render::Rgba c) { return !same(c, o.background); });
  ASSERT_FALSE(b.empty());
  // Pixel i is covered when its centre i + 0.5 lies inside.
  EXPECT_NEAR(b.x0, 0.5 * w - side_px, 2.0);
  EXPECT_NEAR(b.x1 + 1, 0.5 * w + side_px, 2.0);
  EXPECT_NEAR(b.y0, 0.5 * h - side_px, 2.0);
  EXPECT_NEAR(b.y1 + 1, 0.5 * h + side_px, 2.0);
  // And it is full: a plane seen head-on has no holes.
  const std::size_t inside = count_if(im, [&](int x, int y, render::Rgba c) {
    return x >= b.x0 && x <= b.x1 && y >= b.y0 && y <= b.y1 && !same(c, o.background);
  });
  EXPECT_EQ(inside, std::size_t(b.x1 - b.x0 + 1) * std::size_t(b.y1 - b.y0 + 1));
}

TEST(RenderCamera, FlatSquareFromAboveFillsTheExpectedBoxYUp) { expect_square_box(render::UpAxis::y, 200, 200); }
TEST(RenderCamera, FlatSquareFromAboveFillsTheExpectedBoxZUp) { expect_square_box(render::UpAxis::z, 200, 200); }
TEST(RenderCamera, WidePictureKeepsSquarePixels) { expect_square_box(render::UpAxis::y, 300, 180); }

TEST(RenderCamera, PointLandsWhereProjectSaysAndAxesPointTheDocumentedWay) {
  // From above (y up, azimuth 0): picture right is +x and picture up is -z.
  render::Scene scene;
  scene.mesh = floor_square(render::UpAxis::y);
  scene.points = {{0.35, 0.0, 0.0}, {0.0, 0.0, -0.35}};
  scene.point_radius = 0.04;
  render::RenderOptions o = plain(201, 201);
  o.elevation = 90.0;
  o.azimuth = 0.0;
  o.point_color = {255, 0, 255, 255};
  const render::Image im = render::render(scene, o);
  const render::Camera cam = render::frame_camera(render::bounding_sphere(scene), o);
  auto magenta = [](render::Rgba c) { return c[1] < 40 && c[0] > 120 && c[2] > 120; };
  for (int k = 0; k < 2; ++k) {
    double px = 0, py = 0;
    ASSERT_TRUE(cam.project(scene.points[k], px, py));
    // Centroid of the magenta pixels in this point's half of the picture.
    double sx = 0, sy = 0, n = 0;
    for (int y = 0; y < im.height; ++y)
      for (int x = 0; x < im.width; ++x)
        if (magenta(im.pixel(x, y)) && (k == 0 ? x > 110 : y < 90)) sx += x + 0.5, sy += y + 0.5, n += 1;
    ASSERT_GT(n, 10) << "point " << k;
    EXPECT_NEAR(sx / n, px, 1.0) << "point " << k;
    EXPECT_NEAR(sy / n, py, 1.0) << "point " << k;
  }
  double px = 0, py = 0;
  cam.project(scene.points[0], px, py);
  EXPECT_GT(px, 130.0);          // +x is to the right of the centre
  EXPECT_NEAR(py, 100.5, 0.5);
  cam.project(scene.points[1], px, py);
  EXPECT_LT(py, 70.0);           // -z is above the centre
  EXPECT_NEAR(px, 100.5, 0.5);
}

TEST(RenderCamera, FrameCameraIsOrthonormalAndLooksAtTheCentre) {
  render::BoundingSphere s{{1, 2, 3}, 2.0};
  for (auto up : {render::UpAxis::y, render::UpAxis::z})
    for (double az : {0.0, 37.0, -120.0})
      for (double el : {-90.0, -10.0, 0.0, 45.0, 90.0}) {
        render::RenderOptions o = plain(64, 48);
        o.up = up;
        o.azimuth = az;
        o.elevation = el;
        const render::Camera c = render::frame_camera(s, o);
        EXPECT_NEAR(norm(c.forward), 1.0, 1e-12);
        EXPECT_NEAR(norm(c.right), 1.0, 1e-12);
        EXPECT_NEAR(norm(c.up), 1.0, 1e-12);
        EXPECT_NEAR(dot(c.forward, c.right), 0.0, 1e-12);
        EXPECT_NEAR(dot(c.forward, c.up), 0.0, 1e-12);
        const double D = o.margin * s.radius / std::sin(0.5 * o.fov * kDeg);
        EXPECT_NEAR(distance(c.eye, s.center), D, 1e-9);
        double px = 0, py = 0;
        ASSERT_TRUE(c.project(s.center, px, py));
        EXPECT_NEAR(px, 32.0, 1e-9);
        EXPECT_NEAR(py, 24.0, 1e-9);
        const Vec3 up_axis = up == render::UpAxis::y ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
        EXPECT_NEAR(dot(c.right, up_axis), 0.0, 1e-12);          // horizon stays level
        EXPECT_NEAR(dot(-1.0 * c.forward, up_axis), std::sin(el * kDeg), 1e-12);
      }
}

TEST(RenderCamera, BoundingSphereIgnoresUnreferencedVerticesAndCountsOverlays) {
  render::Scene scene;
  scene.mesh = test::single_triangle();
  scene.mesh.positions.push_back({100, 100, 100});   // not used by any face
  const render::BoundingSphere a = render::bounding_sphere(scene);
  EXPECT_NEAR(a.center.x, 0.5, 1e-12);
  EXPECT_NEAR(a.center.y, 0.5, 1e-12);
  EXPECT_NEAR(a.radius, std::sqrt(0.5), 1e-12);
  scene.sources = {{3, 0, 0}};
  const render::BoundingSphere b = render::bounding_sphere(scene);
  EXPECT_NEAR(b.center.x, 1.5, 1e-12);
  EXPECT_NEAR(b.radius, std::sqrt(1.5 * 1.5 + 0.25), 1e-12);
}

TEST(RenderCamera, SinglePointIsFramedWithUnitRadius) {
  render::Scene scene;
  scene.points = {{5, -3, 1e6}};   // far from the origin: positions are taken relative to it
  scene.point_radius = 0.2;
  EXPECT_EQ(render::bounding_sphere(scene).radius, 1.0);
  render::RenderOptions o = plain(101, 101);
  const render::Image im = render::render(scene, o);
  EXPECT_FALSE(same(im.pixel(50, 50), o.background));
  // Radius 0.2 of a framed radius 1.05: about 0.2 / 1.05 of the half-picture, ~10 px.
  const auto b = box_of(im, [&](render::Rgba c) { return !same(c, o.background); });
  EXPECT_NEAR(0.5 * (b.x1 - b.x0 + 1), 50.5 * 0.2 / 1.05, 1.5);
}

TEST(RenderCamera, RejectsBadOptionsAndScenes) {
  render::Scene scene;
  EXPECT_THROW(render::render(scene, plain(8, 8)), InvalidInput);   // nothing to draw
  scene.mesh = test::quad();
  EXPECT_THROW(render::render(scene, plain(0, 8)), InvalidInput);
  render::RenderOptions o = plain(8, 8);
  o.fov = 180.0;
  EXPECT_THROW(render::render(scene, o), InvalidInput);
  o = plain(8, 8);
  o.supersample = 0;
  EXPECT_THROW(render::render(scene, o), InvalidInput);
  o = plain(8, 8);
  o.elevation = std::nan("");
  EXPECT_THROW(render::render(scene, o), InvalidInput);
  scene.vertex_field = {1.0, 2.0};   // 4 vertices
  EXPECT_THROW(render::render(scene, plain(8, 8)), InvalidInput);
  scene.vertex_field.clear();
  scene.face_labels = {1};           // 2 faces
  EXPECT_THROW(render::render(scene, plain(8, 8)), InvalidInput);
  scene.face_labels.clear();
  scene.mesh.triangles.push_back({0, 1, 9});
  EXPECT_THROW(render::render(scene, plain(8, 8)), InvalidInput);
}

}  // namespace
