#include <gsp/errors.hpp>
#include <gsp/surface_point.hpp>

namespace gsp {

bool SurfacePoint::exists_in(const TriangleMesh& mesh) const {
  return element < (is_vertex() ? mesh.num_vertices() : mesh.num_faces());
}

std::string SurfacePoint::missing_from(const TriangleMesh& mesh) const {
  if (is_vertex())
    return "vertex " + std::to_string(element) + " does not exist (" + std::to_string(mesh.num_vertices()) +
           " vertices)";
  return "face " + std::to_string(element) + " does not exist (" + std::to_string(mesh.num_faces()) + " faces)";
}

Vec3 SurfacePoint::position(const TriangleMesh& mesh) const {
  if (!exists_in(mesh)) throw InvalidInput(missing_from(mesh));
  if (is_vertex()) return mesh.positions[element];
  const Triangle& t = mesh.triangles[element];
  const auto& b = barycentric;
  return b[0] * mesh.positions[t[0]] + b[1] * mesh.positions[t[1]] + b[2] * mesh.positions[t[2]];
}

bool affine_coordinates(const TriangleMesh& mesh, Index face, Vec3 x, double min_sine2, std::array<double, 3>& out) {
  const Triangle& t = mesh.triangles[face];
  const Vec3 a = mesh.positions[t[0]], e0 = mesh.positions[t[1]] - a, e1 = mesh.positions[t[2]] - a, e2 = x - a;
  // From cross products (the sub-triangles' signed areas), not from the Gram determinant
  // d00 d11 - d01^2: on a needle of aspect A that difference has a relative error of about
  // eps A^2, all of its digits at the aspect 7e7 of a CAD STL's needles; the cross product's
  // is about eps A.
  const Vec3 n = cross(e0, e1);
  const double nn = dot(n, n);
  if (!(nn > min_sine2 * dot(e0, e0) * dot(e1, e1))) return false;
  const double b1 = dot(cross(e2, e1), n) / nn, b2 = dot(cross(e0, e2), n) / nn;
  out = {1 - b1 - b2, b1, b2};
  return true;
}

std::array<double, 3> affine_coordinates(const TriangleMesh& mesh, Index face, Vec3 x) {
  std::array<double, 3> b{0, 0, 0};
  affine_coordinates(mesh, face, x, 0.0, b);
  return b;
}

}  // namespace gsp
