#pragma once
// Validation of source sets shared by the exact solver and the heat method.
#include <gsp/errors.hpp>
#include <gsp/mesh.hpp>

#include <array>
#include <cmath>
#include <string>

namespace gsp::reference::detail {

inline void check_vertex_index(Index v, std::size_t num_vertices) {
  if (v >= num_vertices)
    throw InvalidInput("source vertex " + std::to_string(v) + " does not exist (the mesh has " +
                       std::to_string(num_vertices) + " vertices)");
}

// Barycentric weights must be finite, non-negative (a rounding error of 1e-9 is clamped) and
// sum to 1 within 1e-9; the returned weights are clamped and renormalised.
inline std::array<double, 3> checked_barycentric(Index face, std::size_t num_faces,
                                                 const std::array<double, 3>& w) {
  if (face >= num_faces)
    throw InvalidInput("source face " + std::to_string(face) + " does not exist (the mesh has " +
                       std::to_string(num_faces) + " faces)");
  const double sum = w[0] + w[1] + w[2];
  const bool ok = std::isfinite(sum) && w[0] >= -1e-9 && w[1] >= -1e-9 && w[2] >= -1e-9 &&
                  std::abs(sum - 1.0) <= 1e-9;
  if (!ok)
    throw InvalidInput("barycentric weights (" + std::to_string(w[0]) + ", " + std::to_string(w[1]) +
                       ", " + std::to_string(w[2]) + ") in face " + std::to_string(face) +
                       " are not non-negative weights summing to 1");
  std::array<double, 3> out{};
  double total = 0;
  for (int i = 0; i < 3; ++i) total += out[i] = std::max(0.0, w[i]);
  for (int i = 0; i < 3; ++i) out[i] /= total;
  return out;
}

}  // namespace gsp::reference::detail
