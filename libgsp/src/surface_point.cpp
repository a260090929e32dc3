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

std::array<double, 3> affine_coordinates(const TriangleMesh& mesh, Index face, Vec3 x) {
  const Triangle& t = mesh.triangles[face];
  const Vec3 a = mesh.positions[t[0]], e0 = mesh.positions[t[1]] - a, e1 = mesh.positions[t[2]] - a, e2 = x - a;
  const double d00 = dot(e0, e0), d01 = dot(e0, e1), d11 = dot(e1, e1), d20 = dot(e2, e0), d21 = dot(e2, e1);
  const double den = d00 * d11 - d01 * d01;
  if (!(den > 0)) return {0, 0, 0};
  const double b1 = (d11 * d20 - d01 * d21) / den, b2 = (d00 * d21 - d01 * d20) / den;
  return {1 - b1 - b2, b1, b2};
}

}  // namespace gsp
