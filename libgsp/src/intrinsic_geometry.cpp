#include "intrinsic_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace gsp::detail {

double mean_edge_length(const TriangleMesh& mesh) {
  double sum = 0;   // in double: millions of float lengths would lose digits
  std::size_t n = 0;
  for (const Triangle& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) continue;
    for (int i = 0; i < 3; ++i) sum += distance(mesh.positions[t[i]], mesh.positions[t[(i + 1) % 3]]);
    n += 3;
  }
  return (n > 0 && sum > 0) ? sum / double(n) : 1.0;
}

std::vector<double> halfedge_lengths(const TriangleMesh& mesh) {
  std::vector<double> length(3 * mesh.num_faces());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f)
    for (int i = 0; i < 3; ++i)
      length[3 * f + i] = distance(mesh.positions[mesh.triangles[f][i]], mesh.positions[mesh.triangles[f][(i + 1) % 3]]);
  return length;
}

void canonical_corners(const std::vector<double>& length, Index f, double scale, double out[3][2]) {
  const double l01 = scale * length[3 * f], l12 = scale * length[3 * f + 1], l20 = scale * length[3 * f + 2];
  out[0][0] = out[0][1] = 0;
  out[1][0] = l01, out[1][1] = 0;
  if (l01 > 0) {
    const double px = (l01 * l01 + l20 * l20 - l12 * l12) / (2 * l01);
    out[2][0] = px;
    out[2][1] = std::sqrt(std::max(0.0, l20 * l20 - px * px));   // clamped: slivers round below 0
  } else {
    out[2][0] = l20, out[2][1] = 0;   // corners 0 and 1 coincide
  }
}

std::vector<std::uint8_t> flat_vertices(const TriangleMesh& mesh, const std::vector<Index>& ring,
                                        const std::vector<bool>& skipped_face,
                                        const std::vector<Index>& nonmanifold_vertices) {
  constexpr double kPi = 3.14159265358979323846;
  const std::size_t nv = mesh.num_vertices();
  std::vector<double> angle(nv, 0.0);
  std::vector<std::uint8_t> boundary(nv, 0), used(nv, 0);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    if (skipped_face[f]) continue;
    const Triangle& t = mesh.triangles[f];
    for (int i = 0; i < 3; ++i) {
      const Vec3 a = mesh.positions[t[(i + 1) % 3]] - mesh.positions[t[i]];
      const Vec3 b = mesh.positions[t[(i + 2) % 3]] - mesh.positions[t[i]];
      angle[t[i]] += std::atan2(norm(cross(a, b)), dot(a, b));
      used[t[i]] = 1;
      const Index h = Index(3 * f + i);
      if ((ring[h] & 0x3fffffffu) == h) boundary[t[i]] = boundary[t[(i + 1) % 3]] = 1;
    }
  }
  // Tight on purpose: finely tessellated smooth surfaces stored in float (STL tyres) have many
  // vertices within 1e-5 of flat that geodesics must still bend around. Measured MRE on the
  // tyres: 1.6% at 1e-6, 2.3% at 1e-5, 2.7% at 1e-4.
  constexpr double tol = 1e-6;
  std::vector<std::uint8_t> flat(nv, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    if (!used[v]) continue;
    flat[v] = boundary[v] ? angle[v] <= kPi * (1 + tol)
                          : std::abs(angle[v] - 2 * kPi) <= 2 * kPi * tol;
  }
  for (Index v : nonmanifold_vertices) flat[v] = 0;
  return flat;
}

}  // namespace gsp::detail
