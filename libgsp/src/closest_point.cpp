#include <gsp/closest_point.hpp>
#include <gsp/errors.hpp>

#include <algorithm>
#include <limits>

namespace gsp {

std::array<double, 3> closest_point_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  // Voronoi regions of the triangle's features, tested from the vertices inwards; each test
  // uses dot products only, so degenerate (zero-area) triangles fall into an edge or vertex.
  // An edge of zero length (two corners at one position, as exporters leave at a sphere's
  // poles) has no region of its own (d1 - d3 is |ab|^2, and so on): the other two edges, which
  // then lie on one segment, answer, where its test alone would divide 0 by 0.
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0 && d1 - d3 > 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0 && d2 - d6 > 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0 && (d4 - d3) + (d5 - d6) > 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  // Inside: each weight from its own area term (1 - v - w rounds below 0 for points a hair
  // from edge bc: 2.7% of such points in a test, and the core refuses negative weights).
  const double u = std::max(0.0, va), v = std::max(0.0, vb), w = std::max(0.0, vc);
  const double sum = u + v + w;
  if (!(sum > 0)) return {1, 0, 0};   // unreachable for finite input; keeps NaN out
  return {u / sum, v / sum, w / sum};
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
