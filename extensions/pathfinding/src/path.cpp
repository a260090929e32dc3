#include <gsp/pathfinding/path.hpp>

#include <gsp/closest_point.hpp>

#include <algorithm>

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

std::array<double, 3> weights_in(const TriangleMesh& mesh, Index f, Vec3 x) {
  std::array<double, 3> b = affine_coordinates(mesh, f, x);
  if (b[0] == 0 && b[1] == 0 && b[2] == 0) {
    // A face of no area: x's weights on its nearest edge (closest_point_on_triangle's answer
    // there). Corner 0's alone, whatever x, put the log cabin STL's path end 33.6 units from
    // where its weights said.
    const Triangle& t = mesh.triangles[f];
    return closest_point_on_triangle(x, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
  }
  for (double& w : b) w = std::max(0.0, w);
  const double sum = b[0] + b[1] + b[2];
  for (double& w : b) w /= sum;
  return b;
}

std::vector<PathPoint> reversed_path(const TriangleMesh& mesh, const std::vector<PathPoint>& points) {
  const std::vector<PathPoint> plain(points.rbegin(), points.rend());
  std::vector<PathPoint> out = plain;
  for (std::size_t j = out.size(); j-- > 1;) {
    const Index f = plain[j - 1].point.element;   // the old order's face of the segment
    if (f >= mesh.num_faces()) return plain;
    const std::array<double, 3> w = weights_in(mesh, f, out[j].position);
    const Triangle& t = mesh.triangles[f];
    const Vec3 at = w[0] * mesh.positions[t[0]] + w[1] * mesh.positions[t[1]] + w[2] * mesh.positions[t[2]];
    const double size = std::max({distance(mesh.positions[t[0]], mesh.positions[t[1]]),
                                  distance(mesh.positions[t[1]], mesh.positions[t[2]]),
                                  distance(mesh.positions[t[2]], mesh.positions[t[0]])});
    // One convention for the whole path: a point its predecessor's face does not hold (the
    // path named the face after each point) leaves every name as it was.
    if (!(distance(at, out[j].position) <= 1e-7 * size)) return plain;
    out[j].point = SurfacePoint::in_face(f, w);
  }
  return out;
}

}  // namespace gsp::pathfinding
