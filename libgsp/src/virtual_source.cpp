#include "virtual_source.hpp"

#include <gsp/geodesics.hpp>

#include <cmath>

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

}  // namespace gsp::detail

namespace gsp {

double GeodesicResult::distance_at(const TriangleMesh& mesh, Index face,
                                   std::array<double, 3> bary) const {
  if (face >= face_sources.size() || !face_sources[face].reached())
    return std::numeric_limits<double>::infinity();
  const Vec3 q = SurfacePoint::in_face(face, bary).position(mesh);
  return face_sources[face].sigma + distance(q, face_sources[face].position);
}

}  // namespace gsp
