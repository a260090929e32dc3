#include <gsp/render/scene.hpp>

#include <gsp/errors.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace gsp::render {

namespace {

template <class F>
void for_each_drawn_point(const Scene& s, F&& f) {
  for (const Vec3& p : s.mesh.positions) f(p);
  for (const Vec3& p : s.points) f(p);
  for (const auto& line : s.polylines)
    for (const Vec3& p : line) f(p);
  for (const Vec3& p : s.sources) f(p);
}

}  // namespace

void validate(const Scene& s) {
  auto fail = [](const std::string& what) { throw InvalidInput("render scene: " + what); };
  const std::size_t nv = s.mesh.num_vertices(), nf = s.mesh.num_faces();
  for (std::size_t f = 0; f < nf; ++f)
    for (Index v : s.mesh.triangles[f])
      if (v >= nv)
        fail("triangle " + std::to_string(f) + " names vertex " + std::to_string(v) + " of " + std::to_string(nv));
  if (!s.vertex_field.empty() && s.vertex_field.size() != nv)
    fail("the field has " + std::to_string(s.vertex_field.size()) + " values for " + std::to_string(nv) +
         " vertices");
  if (!s.face_labels.empty() && s.face_labels.size() != nf)
    fail("there are " + std::to_string(s.face_labels.size()) + " face labels for " + std::to_string(nf) + " faces");
  bool finite = true;
  std::size_t count = 0;
  for_each_drawn_point(s, [&](const Vec3& p) {
    finite = finite && is_finite(p);
    ++count;
  });
  if (!finite) fail("a position is not finite");
  if (count == 0) fail("nothing to draw");
  for (double r : {s.point_radius, s.line_radius, s.source_radius})
    if (!(r >= 0.0) || !std::isfinite(r)) fail("radii must be finite and >= 0");
}

BoundingSphere bounding_sphere(const Scene& s) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  // Only referenced mesh vertices count: a file's stray vertices would shrink the picture.
  auto grow = [&](const Vec3& p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  };
  const auto& P = s.mesh.positions;
  if (s.mesh.triangles.empty()) {
    for (const Vec3& p : P) grow(p);
  } else {
    for (const Triangle& t : s.mesh.triangles)
      for (Index v : t) grow(P[v]);
  }
  for (const Vec3& p : s.points) grow(p);
  for (const auto& line : s.polylines)
    for (const Vec3& p : line) grow(p);
  for (const Vec3& p : s.sources) grow(p);
  BoundingSphere b;
  if (!(lo.x <= hi.x)) return b;   // nothing drawn
  b.center = 0.5 * (lo + hi);
  double r2 = 0.0;
  auto reach = [&](const Vec3& p) { r2 = std::max(r2, dot(p - b.center, p - b.center)); };
  if (s.mesh.triangles.empty()) {
    for (const Vec3& p : P) reach(p);
  } else {
    for (const Triangle& t : s.mesh.triangles)
      for (Index v : t) reach(P[v]);
  }
  for (const Vec3& p : s.points) reach(p);
  for (const auto& line : s.polylines)
    for (const Vec3& p : line) reach(p);
  for (const Vec3& p : s.sources) reach(p);
  // A single point (or all at one place) has no size: frame one model unit around it.
  b.radius = r2 > 0.0 ? std::sqrt(r2) : 1.0;
  return b;
}

}  // namespace gsp::render
