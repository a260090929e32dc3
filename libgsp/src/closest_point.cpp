#include <gsp/closest_point.hpp>
#include <gsp/errors.hpp>

#include <algorithm>
#include <limits>

namespace gsp {

namespace {

// The closest point of segment a -> b to p as its parameter (0 at a, 1 at b; 0 for a segment
// of zero length).
double segment_parameter(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 d = b - a;
  const double dd = dot(d, d);
  return dd > 0 ? std::clamp(dot(p - a, d) / dd, 0.0, 1.0) : 0.0;
}

}  // namespace

std::array<double, 3> closest_point_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  // p projected onto the triangle's plane, then each weight from the signed area of the
  // sub-triangle opposite its corner (a cross product of two vectors from the projection, each
  // at most a few edges long). Why not the textbook Voronoi-region tests (Ericson 5.1.5): they
  // take the areas as differences of products of dot products, terms of size |edge|^4 for an
  // answer of size area^2, which loses (longest edge / height)^2 of the 16 digits: on a CAD
  // needle of aspect 1e7 the weights came out wrong by 13% of a 40-unit edge, and a path lying
  // on such a face read as off the surface (docs/pathfinding.md, "Needles").
  const Vec3 n = cross(b - a, c - a);
  const double nn = dot(n, n);
  if (nn > 0) {
    const Vec3 q = p - (dot(p - a, n) / nn) * n;
    const double u = dot(cross(b - q, c - q), n), v = dot(cross(c - q, a - q), n), w = dot(cross(a - q, b - q), n);
    const double sum = u + v + w;
    if (u >= 0 && v >= 0 && w >= 0 && sum > 0) return {u / sum, v / sum, w / sum};
  }
  // Outside, on the boundary within rounding, or no area (two corners at one position, as
  // exporters leave at a sphere's poles, or three in a row): the nearest point of the three
  // edges. A zero-length edge answers with its one point and the other two edges, which then
  // lie on one segment, with the rest.
  const double s_ab = segment_parameter(p, a, b), s_bc = segment_parameter(p, b, c), s_ca = segment_parameter(p, c, a);
  const std::array<std::array<double, 3>, 3> w = {{{1 - s_ab, s_ab, 0}, {0, 1 - s_bc, s_bc}, {s_ca, 0, 1 - s_ca}}};
  std::size_t best = 0;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec3 x = w[k][0] * a + w[k][1] * b + w[k][2] * c;
    const double d2 = dot(p - x, p - x);
    if (d2 < best_d2) best = k, best_d2 = d2;
  }
  return w[best];
}

ClosestPoint closest_surface_point(const TriangleMesh& mesh, Vec3 p) {
  if (!is_finite(p)) throw InvalidInput("query point has a non-finite coordinate");
  ClosestPoint best;
  best.distance = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    if (repeats_vertex(t)) continue;
    const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const auto w = closest_point_on_triangle(p, a, b, c);
    const Vec3 q = w[0] * a + w[1] * b + w[2] * c;
    const double d = distance(p, q);
    if (d < best.distance) best = {SurfacePoint::in_face(Index(f), w), q, d};
  }
  if (best.point.element == kInvalidIndex) throw InvalidInput("the mesh has no face to snap a point to");
  return best;
}

}  // namespace gsp
