#include "ratio.hpp"

#include <gsp/anisotropic/metric_sources.hpp>
#include <gsp/anisotropic/principal_curvature.hpp>

#include <gsp/errors.hpp>

#include <cmath>
#include <string>

namespace gsp::anisotropic {

void detail::check_ratio(double ratio) {
  if (!std::isfinite(ratio) || !(ratio > 0))
    throw InvalidInput("metric ratio must be finite and > 0 (got " + std::to_string(ratio) + ")");
}

MetricField curvature_metric(const TriangleMesh& mesh, double ratio) {
  detail::check_ratio(ratio);
  const std::vector<PrincipalCurvature> k = principal_curvatures(mesh);
  MetricField field{MetricLocation::per_vertex, std::vector<SymmetricTensor>(mesh.num_vertices())};
  for (std::size_t v = 0; v < k.size(); ++v) {
    const double a = std::abs(k[v].max_curvature), b = std::abs(k[v].min_curvature);
    // Flat or umbilic: the fitted directions are noise, so no direction is preferred.
    if (!k[v].valid || !(a - b > 1e-3 * a)) continue;
    field.tensors[v] = SymmetricTensor::stretch(k[v].max_direction, ratio);
  }
  return field;
}

}  // namespace gsp::anisotropic
