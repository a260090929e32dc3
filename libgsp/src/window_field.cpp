// Queries on a computed window field (gsp/window_geodesics.hpp): which window explains a point
// of a face, and from where the geodesic to it comes.
#include <gsp/errors.hpp>

#include "window_geodesics_impl.hpp"

#include <cmath>
#include <limits>

namespace gsp {

using namespace detail::windows;

namespace {

// An input face's plane: its first corner and the unit axes of the 2D frame the windows use
// (corner 1 on +x, corner 2 at y > 0).
struct Plane {
  Vec3 origin, ex, ey;
  V2 to2d(Vec3 x) const { return {gsp::dot(x - origin, ex), gsp::dot(x - origin, ey)}; }
  Vec3 to3d(V2 p) const { return origin + p.x * ex + p.y * ey; }
};

Plane plane_of(const WindowGeodesics::Impl& m, Index f) {
  const Triangle& t = m.triangles[f];
  const std::vector<Vec3>& p = *m.positions;
  Plane pl;
  pl.origin = p[t[0]];
  const Vec3 e1 = p[t[1]] - p[t[0]], e2 = p[t[2]] - p[t[0]];
  const double l1 = gsp::norm(e1);
  pl.ex = l1 > 0 ? (1 / l1) * e1 : Vec3{1, 0, 0};
  const Vec3 y = e2 - gsp::dot(e2, pl.ex) * pl.ex;
  const double ly = gsp::norm(y);
  pl.ey = ly > 0 ? (1 / ly) * y : Vec3{0, 1, 0};
  return pl;
}

void require_input_faces(const WindowGeodesics::Impl& m) {
  if (m.intrinsic)
    throw InvalidInput("a window field on intrinsic Delaunay faces has no input faces to query: build the "
                       "WindowGeodesics with intrinsic_delaunay = false");
}

}  // namespace

WindowField::WindowField() = default;
WindowField::~WindowField() = default;
WindowField::WindowField(WindowField&&) noexcept = default;
WindowField& WindowField::operator=(WindowField&&) noexcept = default;

bool WindowField::reached(Index face) const {
  return data_ && face < data_->count.size() && data_->count[face] > 0;
}

VirtualSource WindowField::source_at(Index face, Vec3 x) const {
  VirtualSource out;
  if (!reached(face)) return out;
  require_input_faces(*data_->mesh);
  const Plane pl = plane_of(*data_->mesh, face);
  const double unit = data_->mesh->unit;   // the windows' scale (window_geodesics_impl.hpp)
  const V2 p = unit * pl.to2d(x);
  double best = std::numeric_limits<double>::infinity();
  for (unsigned i = 0; i < data_->count[face]; ++i) {
    const Window& w = data_->win[data_->block[face] * data_->k + i];
    V2 from;
    double rest = 0;
    if (!origin_of(w, p, &from, &rest)) continue;
    const double v = norm(p - from) + rest;
    if (v < best) best = v, out.position = pl.to3d((1 / unit) * from), out.sigma = rest / unit, out.source = w.label;
  }
  return out;
}

double WindowField::distance_at(Index face, const std::array<double, 3>& b) const {
  if (!reached(face)) return std::numeric_limits<double>::infinity();
  require_input_faces(*data_->mesh);
  const auto& c = data_->mesh->frame[face];
  std::array<double, 3> w = b;
  data_->mesh->to_propagation_corners(face, w);
  const V2 p = w[0] * c[0] + w[1] * c[1] + w[2] * c[2];
  double best = std::numeric_limits<double>::infinity();
  for (unsigned i = 0; i < data_->count[face]; ++i) best = std::min(best, value_at(data_->win[data_->block[face] * data_->k + i], p));
  return best / data_->mesh->unit;
}

}  // namespace gsp
