#include "smoothing_context.hpp"
#include "triangle_geometry.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/cvt/closest_point_index.hpp>

namespace gsp::cvt::detail {

SmoothingContext::SmoothingContext(TriangleMesh& mesh, const TriangleMesh& on, const ClosestPointIndex& on_index,
                                   const TriangleMesh& sampling, const BoundaryCurves& boundary)
    : m(mesh),
      surface(on),
      index(on_index),
      samples(sampling),
      curves(boundary),
      grid(sampling.positions, mean_edge_estimate(mesh)),
      sample_normal(vertex_normals(sampling)),
      rings(mesh),
      surf_n(mesh.num_vertices()),
      loop_of(mesh.num_vertices(), std::size_t(-1)),
      arc(mesh.num_vertices(), 0) {
  place_on_curves();
  for (std::size_t v = 0; v < m.num_vertices(); ++v) surf_n[v] = surface_normal(index.closest(m.positions[v]));
}

// Only a boundary vertex that lies on a curve can slide along it.
void SmoothingContext::place_on_curves() {
  if (curves.loops.empty()) return;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    if (rings.next_b[v] == kInvalidIndex) continue;
    std::size_t l = 0;
    double s = 0, d = 0;
    if (curves.project(m.positions[v], l, s, d) && d <= 1e-3 * distance(m.positions[v], m.positions[rings.next_b[v]]))
      loop_of[v] = l, arc[v] = s;
  }
}

Vec3 SmoothingContext::surface_normal(const ClosestPoint& sp) const {
  if (sp.point.element == kInvalidIndex) return Vec3{};
  const Triangle& st = surface.triangles[sp.point.element];
  const Vec3 n = normal(surface.positions[st[0]], surface.positions[st[1]], surface.positions[st[2]]);
  const double l = norm(n);
  return l > 0 ? (1.0 / l) * n : Vec3{};
}

Vec3 SmoothingContext::ring_normal(Index v) const {
  Vec3 n;
  for (Index c : rings.around(v)) {
    const Triangle& t = m.triangles[face_of(c)];
    n = n + normal(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
  }
  return n;
}

void SmoothingContext::move(Index v, Vec3 x) {
  m.positions[v] = x;
  surf_n[v] = surface_normal(index.closest(x));
}

}  // namespace gsp::cvt::detail
