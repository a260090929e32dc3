#include "ratio.hpp"

#include <gsp/anisotropic/metric_sources.hpp>

#include <gsp/errors.hpp>

#include <cmath>

namespace gsp::anisotropic {

MetricField direction_metric(const TriangleMesh& mesh, Vec3 direction, double ratio) {
  detail::check_ratio(ratio);
  const double length = norm(direction);
  if (!(length > 0) || !std::isfinite(length)) throw InvalidInput("metric direction must be finite and non-zero");
  const Vec3 d = (1 / length) * direction;
  MetricField field{MetricLocation::per_face, std::vector<SymmetricTensor>(mesh.num_faces())};
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 p0 = mesh.positions[t[0]];
    const Vec3 n = cross(mesh.positions[t[1]] - p0, mesh.positions[t[2]] - p0);
    const double area2 = norm(n);
    if (!(area2 > 0)) continue;   // no plane to project into: the identity
    const Vec3 unit_n = (1 / area2) * n;
    const Vec3 in_plane = d - dot(d, unit_n) * unit_n;
    const double l = norm(in_plane);
    if (!(l > 1e-9)) continue;    // the plane is perpendicular to the direction
    field.tensors[f] = SymmetricTensor::stretch((1 / l) * in_plane, ratio);
  }
  return field;
}

}  // namespace gsp::anisotropic
