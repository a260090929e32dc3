#include "virtual_source.hpp"

#include <gsp/geodesics.hpp>

#include <algorithm>
#include <cmath>

namespace gsp::detail {

Vec3 locate_virtual_source(const TriangleMesh& mesh, Index f, const double d2n[3], double unit) {
  const Triangle& t = mesh.triangles[f];
  const Vec3 p[3] = {mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
  double d2[3];
  for (int i = 0; i < 3; ++i) d2[i] = d2n[i] * unit * unit;
  // Base the frame on the longest edge: the best-conditioned choice on slivers.
  int k = 0;
  double best = -1;
  for (int i = 0; i < 3; ++i) {
    const double l = dot(p[(i + 1) % 3] - p[i], p[(i + 1) % 3] - p[i]);
    if (l > best) best = l, k = i;
  }
  const Vec3 a = p[k], b = p[(k + 1) % 3], c = p[(k + 2) % 3];
  const double da = d2[k], db = d2[(k + 1) % 3], dc = d2[(k + 2) % 3];
  const double e = std::sqrt(best);
  if (!(e > 0)) return a;   // all corners coincide
  const Vec3 ex = (1.0 / e) * (b - a);
  const Vec3 ac = c - a;
  Vec3 ey = ac - dot(ac, ex) * ex;
  const double ly = norm(ey);
  const double sx = (e * e + da - db) / (2 * e);
  const double sy = std::sqrt(std::max(0.0, da - sx * sx));
  if (!(ly > 0)) return a + sx * ex;   // zero-area face: the side is meaningless
  ey = (1.0 / ly) * ey;
  const double cx = dot(ac, ex), cy = ly;
  const double up = (cx - sx) * (cx - sx) + (cy - sy) * (cy - sy);
  const double down = (cx - sx) * (cx - sx) + (cy + sy) * (cy + sy);
  const double y = std::abs(up - dc) <= std::abs(down - dc) ? sy : -sy;
  return a + sx * ex + y * ey;
}

}  // namespace gsp::detail

namespace gsp {

double GeodesicResult::distance_at(const TriangleMesh& mesh, Index face,
                                   std::array<double, 3> bary) const {
  if (face >= face_sources.size() || !face_sources[face].reached())
    return std::numeric_limits<double>::infinity();
  const Triangle& t = mesh.triangles[face];
  const Vec3 q = bary[0] * mesh.positions[t[0]] + bary[1] * mesh.positions[t[1]] +
                 bary[2] * mesh.positions[t[2]];
  return face_sources[face].sigma + distance(q, face_sources[face].position);
}

}  // namespace gsp
