#include <gsp/render/camera.hpp>

#include <algorithm>
#include <cmath>

namespace gsp::render {

Vec3 Camera::direction(double px, double py) const {
  const double sx = (2.0 * px / width - 1.0) * tan_half_x;
  const double sy = (1.0 - 2.0 * py / height) * tan_half_y;
  return forward + sx * right + sy * up;
}

bool Camera::project(Vec3 p, double& px, double& py) const {
  const Vec3 q = p - eye;
  const double z = dot(q, forward);
  if (!(z > 0.0)) return false;
  px = (dot(q, right) / (z * tan_half_x) + 1.0) * 0.5 * width;
  py = (1.0 - dot(q, up) / (z * tan_half_y)) * 0.5 * height;
  return true;
}

Camera frame_camera(const BoundingSphere& sphere, const RenderOptions& o) {
  constexpr double deg = 3.14159265358979323846 / 180.0;
  // (e1, e2, e3) is right-handed with e2 the up axis and e3 towards the front-view camera.
  Vec3 e1{1, 0, 0}, e2{0, 1, 0}, e3{0, 0, 1};
  if (o.up == UpAxis::z) {
    e2 = {0, 0, 1};
    e3 = {0, -1, 0};
  }
  const double az = o.azimuth * deg, el = o.elevation * deg;
  const Vec3 to_eye = std::cos(el) * std::sin(az) * e1 + std::sin(el) * e2 + std::cos(el) * std::cos(az) * e3;
  Camera c;
  c.width = o.width;
  c.height = o.height;
  c.forward = -1.0 * to_eye;
  // The horizontal direction perpendicular to the azimuth: well defined even straight above.
  c.right = std::cos(az) * e1 - std::sin(az) * e3;
  c.up = cross(c.right, c.forward);
  const double half = 0.5 * o.fov * deg;
  const double t = std::tan(half);
  const double shorter = std::min(o.width, o.height);
  c.tan_half_x = t * o.width / shorter;
  c.tan_half_y = t * o.height / shorter;
  const double distance = o.margin * sphere.radius / std::sin(half);
  c.eye = sphere.center + distance * to_eye;
  return c;
}

}  // namespace gsp::render
