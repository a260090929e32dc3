#include <gsp/errors.hpp>
#include <gsp/sampling/surface_points.hpp>

#include <algorithm>
#include <cmath>

namespace gsp::sampling {

double triangle_area(const TriangleMesh& mesh, Index face) {
  const Triangle& t = mesh.triangles[face];
  if (repeats_vertex(t)) return 0.0;
  const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
  return 0.5 * norm(cross(b - a, c - a));
}

Sample make_sample(const TriangleMesh& mesh, Index face, std::array<double, 3> barycentric) {
  const Triangle& t = mesh.triangles[face];
  const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
  Sample s;
  s.point = SurfacePoint::in_face(face, barycentric);
  s.position = s.point.position(mesh);
  const Vec3 n = cross(b - a, c - a);
  const double len = norm(n);
  if (len > 0) s.normal = (1.0 / len) * n;
  return s;
}

AreaSampler::AreaSampler(const TriangleMesh& mesh) : AreaSampler(mesh, std::vector<bool>(mesh.num_faces(), true)) {}

AreaSampler::AreaSampler(const TriangleMesh& mesh, const std::vector<bool>& faces) {
  prefix_.resize(mesh.num_faces());
  double sum = 0;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    if (faces[f]) sum += triangle_area(mesh, Index(f));
    prefix_[f] = sum;
  }
  if (!(sum > 0) || !std::isfinite(sum)) throw InvalidInput("the mesh has no face with a positive area");
}

Sample AreaSampler::draw(const TriangleMesh& mesh, Random& random) const {
  // upper_bound: a face of zero area has prefix_[f] == prefix_[f-1] and is never returned.
  const double x = random.uniform() * prefix_.back();
  const auto it = std::upper_bound(prefix_.begin(), prefix_.end(), x);
  const Index face = Index(std::min<std::size_t>(it - prefix_.begin(), prefix_.size() - 1));
  const double s = std::sqrt(random.uniform()), u = random.uniform();
  return make_sample(mesh, face, {1 - s, s * (1 - u), s * u});
}

}  // namespace gsp::sampling
