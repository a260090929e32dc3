#include "ratio.hpp"

#include <gsp/anisotropic/metric_sources.hpp>
#include <gsp/anisotropic/principal_curvature.hpp>

#include <gsp/errors.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <string>

namespace gsp::anisotropic {

void detail::check_ratio(double ratio) {
  if (!std::isfinite(ratio) || !(ratio > 0))
    throw InvalidInput("metric ratio must be finite and > 0 (got " + std::to_string(ratio) + ")");
}

namespace {

// Vertex -> neighbours (CSR), each once.
void vertex_neighbours(const TriangleMesh& mesh, std::vector<Index>& begin, std::vector<Index>& list) {
  std::vector<std::pair<Index, Index>> pairs;
  pairs.reserve(6 * mesh.num_faces());
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
      if (t[i] != t[(i + 1) % 3]) pairs.push_back({t[i], t[(i + 1) % 3]}), pairs.push_back({t[(i + 1) % 3], t[i]});
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  begin.assign(mesh.num_vertices() + 1, 0);
  for (const auto& p : pairs) ++begin[p.first + 1];
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) begin[v + 1] += begin[v];
  list.resize(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) list[k] = pairs[k].second;
}

// The directions as tensors w k k^T (sign-free, so opposite vectors agree), averaged over
// the one-ring `rounds` times; w = (|k_max| - |k_min|) / (|k_max| + |k_min|), the confidence of
// the direction, so umbilic and flat vertices take their neighbours' directions. Returns per
// vertex the dominant tangent direction, or zero where the smoothed tensor has none.
std::vector<Vec3> smoothed_directions(const TriangleMesh& mesh, const std::vector<PrincipalCurvature>& k,
                                      int rounds) {
  const std::size_t nv = mesh.num_vertices();
  std::vector<Eigen::Matrix3d> t(nv, Eigen::Matrix3d::Zero()), next(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const double a = std::abs(k[v].max_curvature), b = std::abs(k[v].min_curvature);
    if (!k[v].valid || !(a > 0)) continue;
    const Eigen::Vector3d d(k[v].max_direction.x, k[v].max_direction.y, k[v].max_direction.z);
    t[v] = ((a - b) / (a + b)) * d * d.transpose();
  }
  std::vector<Index> begin, list;
  vertex_neighbours(mesh, begin, list);
  for (int r = 0; r < rounds; ++r) {
    for (std::size_t v = 0; v < nv; ++v) {
      next[v] = t[v];
      for (Index j = begin[v]; j < begin[v + 1]; ++j) next[v] += t[list[j]];
      next[v] /= double(1 + begin[v + 1] - begin[v]);
    }
    t.swap(next);
  }
  std::vector<Vec3> out(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const Eigen::Vector3d n(k[v].normal.x, k[v].normal.y, k[v].normal.z);
    const Eigen::Matrix3d p = Eigen::Matrix3d::Identity() - n * n.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(p * t[v] * p);   // closed form for 3x3: far cheaper than the iterative solver
    const Eigen::Vector3d l = eig.eigenvalues();   // ascending; l[0] ~ 0 along the normal
    // No dominant direction: nothing to smooth from, or two directions equally strong.
    if (!(l[2] > 0) || !(l[2] - l[1] > 1e-3 * l[2])) continue;
    const Eigen::Vector3d d = eig.eigenvectors().col(2);
    out[v] = {d[0], d[1], d[2]};
  }
  return out;
}

}  // namespace

MetricField curvature_metric(const TriangleMesh& mesh, double ratio, int smoothing_rounds) {
  detail::check_ratio(ratio);
  if (smoothing_rounds < 0) throw InvalidInput("curvature metric: smoothing rounds must be >= 0");
  const std::vector<PrincipalCurvature> k = principal_curvatures(mesh);
  MetricField field{MetricLocation::per_vertex, std::vector<SymmetricTensor>(mesh.num_vertices())};
  if (smoothing_rounds > 0) {
    const std::vector<Vec3> d = smoothed_directions(mesh, k, smoothing_rounds);
    for (std::size_t v = 0; v < d.size(); ++v)
      if (norm(d[v]) > 0) field.tensors[v] = SymmetricTensor::stretch(d[v], ratio);
    return field;
  }
  for (std::size_t v = 0; v < k.size(); ++v) {
    const double a = std::abs(k[v].max_curvature), b = std::abs(k[v].min_curvature);
    // Flat or umbilic: the fitted directions are noise, so no direction is preferred.
    if (!k[v].valid || !(a - b > 1e-3 * a)) continue;
    field.tensors[v] = SymmetricTensor::stretch(k[v].max_direction, ratio);
  }
  return field;
}

}  // namespace gsp::anisotropic
