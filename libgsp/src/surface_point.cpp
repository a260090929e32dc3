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

}  // namespace gsp
