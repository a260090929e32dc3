#include <gsp/pathfinding/path.hpp>

#include <cmath>
#include <string>

namespace gsp::pathfinding {

Vec3 endpoint_position(const TriangleMesh& mesh, const Endpoint& end) {
  if (end.is_vertex()) {
    if (end.vertex >= mesh.num_vertices())
      throw InvalidInput("vertex " + std::to_string(end.vertex) + " does not exist (" +
                         std::to_string(mesh.num_vertices()) + " vertices)");
    return mesh.positions[end.vertex];
  }
  if (end.face >= mesh.num_faces())
    throw InvalidInput("face " + std::to_string(end.face) + " does not exist (" + std::to_string(mesh.num_faces()) +
                       " faces)");
  const auto& b = end.barycentric;
  if (!(b[0] >= 0 && b[1] >= 0 && b[2] >= 0) || std::abs(b[0] + b[1] + b[2] - 1) > 1e-6)
    throw InvalidInput("barycentric coordinates must be >= 0 and sum to 1");
  const Triangle& t = mesh.triangles[end.face];
  return b[0] * mesh.positions[t[0]] + b[1] * mesh.positions[t[1]] + b[2] * mesh.positions[t[2]];
}

double polyline_length(const std::vector<PathPoint>& points) {
  double sum = 0;
  for (std::size_t i = 1; i < points.size(); ++i) sum += distance(points[i - 1].position, points[i].position);
  return sum;
}

}  // namespace gsp::pathfinding
