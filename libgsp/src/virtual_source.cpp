#include "virtual_source.hpp"

#include <gsp/closest_point.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/intrinsic/face_frame.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace gsp::detail {

Vec3 canonical_to_3d(const TriangleMesh& mesh, Index f, double x, double y) {
  const Triangle& t = mesh.triangles[f];
  const Vec3 p0 = mesh.positions[t[0]];
  Vec3 ex = mesh.positions[t[1]] - p0;
  const Vec3 e2 = mesh.positions[t[2]] - p0;
  if (!(norm(ex) > 0)) ex = e2;   // corners 0 and 1 coincide: the frame's x runs to corner 2
  const double lx = norm(ex);
  if (!(lx > 0)) return p0;
  ex = (1.0 / lx) * ex;
  Vec3 ey = e2 - dot(e2, ex) * ex;
  const double ly = norm(ey);
  ey = ly > 0 ? (1.0 / ly) * ey : Vec3{0, 0, 0};   // zero-area face: y is meaningless
  return p0 + x * ex + y * ey;
}

bool unfolded_to_3d(const Vec3 corners3d[3], const double corners2d[3][2], double x, double y, Vec3& out) {
  const double ux = corners2d[1][0] - corners2d[0][0], uy = corners2d[1][1] - corners2d[0][1];
  const double vx = corners2d[2][0] - corners2d[0][0], vy = corners2d[2][1] - corners2d[0][1];
  const double area = ux * vy - uy * vx;
  const double scale = std::max({ux * ux + uy * uy, vx * vx + vy * vy, (ux - vx) * (ux - vx) + (uy - vy) * (uy - vy)});
  if (!(std::abs(area) > 1e-12 * scale)) return false;
  const double px = x - corners2d[0][0], py = y - corners2d[0][1];
  const double b1 = (px * vy - py * vx) / area, b2 = (ux * py - uy * px) / area;
  // Affine in the face's plane: the same weights on the 3D corners.
  out = corners3d[0] + b1 * (corners3d[1] - corners3d[0]) + b2 * (corners3d[2] - corners3d[0]);
  return true;
}

void across_edge(const double mine[3], Index i, const double theirs[3], Index j, bool same_dir, double x, double y,
                 double out[2]) {
  // Into the neighbour's edge frame (its face on +y), over the edge (y flips; x runs from the
  // other end unless both walk the edge the same way), out of this face's edge frame: as the
  // update step unfolds a source (update_step.hpp, unfold).
  using intrinsic::canonical_frame;
  using intrinsic::edge_view;
  const intrinsic::EdgeView<double> vt = edge_view(theirs, j), vm = edge_view(mine, i);
  double ex, ey;
  canonical_frame(theirs, j, vt).to_edge(x, y, ex, ey);
  canonical_frame(mine, i, vm).to_canonical(same_dir ? ex : vm.e1 - ex, -ey, out[0], out[1]);
}

double line_shortfall(const Vec3 corners3d[3], Vec3 s, double sigma, Vec3 p, double offset) {
  // |x - p| <= |x - s| + |s - p|: a path behind s at least the straight line to s reads at or
  // above the line everywhere (bends at a vertex, and most carried sources).
  if (sigma >= offset + distance(s, p)) return 0;
  double raise = 0;
  auto test = [&](const Vec3& x) {
    raise = std::max(raise, offset + distance(x, p) - (sigma + distance(x, s)));
  };
  for (int i = 0; i < 3; ++i) {
    const Vec3 o = corners3d[i], e = corners3d[(i + 1) % 3] - o;
    test(o);
    const double len = norm(e);
    if (!(len > 0)) continue;
    const Vec3 u = e * (1 / len);
    const double a = dot(s - o, u), b = norm(s - o - u * a), c = dot(p - o, u), d = norm(p - o - u * c);
    for (const double sign : {1.0, -1.0}) {
      const double den = d + sign * b;
      if (!(std::abs(den) > 1e-12 * len)) continue;
      const double t = (a * d + sign * c * b) / den;
      if (std::isfinite(t)) test(o + u * std::clamp(t, 0.0, len));
    }
  }
  const std::array<double, 3> w = closest_point_on_triangle(s, corners3d[0], corners3d[1], corners3d[2]);
  test(corners3d[0] * w[0] + corners3d[1] * w[1] + corners3d[2] * w[2]);
  return raise;
}

}  // namespace gsp::detail

namespace gsp {

double GeodesicResult::distance_at(const TriangleMesh& mesh, Index face,
                                   std::array<double, 3> bary) const {
  if (face >= face_sources.size()) return std::numeric_limits<double>::infinity();
  const Vec3 q = SurfacePoint::in_face(face, bary).position(mesh);
  const VirtualSource& vs = face_sources[face];
  const double through_source = vs.reached() ? vs.sigma + distance(q, vs.position) : std::numeric_limits<double>::infinity();
  if (vertex_distance.size() != mesh.num_vertices()) return through_source;
  return std::min(through_source, corner_paths(mesh, face, q, vertex_distance));
}

double corner_paths(const TriangleMesh& mesh, Index face, Vec3 p, const std::vector<double>& d) {
  double best = std::numeric_limits<double>::infinity();
  for (Index v : mesh.triangles[face])
    if (d[v] < best) best = std::min(best, d[v] + distance(p, mesh.positions[v]));
  return best;
}

}  // namespace gsp
