#include <gsp/pathfinding/path.hpp>

namespace gsp::pathfinding {

void check_endpoint(const TriangleMesh& mesh, const Endpoint& end) {
  if (!end.exists_in(mesh)) throw InvalidInput(end.missing_from(mesh));
  if (!end.is_vertex() && !are_barycentric(end.barycentric))
    throw InvalidInput("barycentric coordinates must be >= 0 and sum to 1");
}

double polyline_length(const std::vector<PathPoint>& points) {
  double sum = 0;
  for (std::size_t i = 1; i < points.size(); ++i) sum += distance(points[i - 1].position, points[i].position);
  return sum;
}

}  // namespace gsp::pathfinding
