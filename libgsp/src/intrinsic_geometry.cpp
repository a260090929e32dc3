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

template <class Real>
std::vector<HalfedgeGeometry<Real>> build_halfedge_geometry(const TriangleMesh& mesh, double scale,
                                                            const VisibilityHeuristic& heuristic) {
  std::vector<HalfedgeGeometry<Real>> geo(3 * mesh.num_faces());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    double len[3];   // len[i]: edge from corner i to corner i+1
    for (int i = 0; i < 3; ++i)
      len[i] = scale * distance(mesh.positions[t[i]], mesh.positions[t[(i + 1) % 3]]);
    const double max_e = std::max({len[0], len[1], len[2]});
    const double min_e = std::min({len[0], len[1], len[2]});
    for (int j = 0; j < 3; ++j) {
      const double e1 = len[j], e2 = len[(j + 1) % 3], e3 = len[(j + 2) % 3];
      HalfedgeGeometry<Real>& g = geo[3 * f + j];
      double px, py, qx, qy;
      if (e1 > 0) {
        px = (e1 * e1 + e3 * e3 - e2 * e2) / (2 * e1);
        py = std::sqrt(std::max(0.0, e3 * e3 - px * px));
        const double cx = (px + e1) / 3, cy = py / 3;
        const double lambda = heuristic.blend(e1, max_e, min_e, py);
        qx = (1 - lambda) * px + lambda * cx;
        qy = (1 - lambda) * py + lambda * cy;
        g.inv_2e1 = Real(1 / (2 * e1));
      } else {
        // A and B coincide: the source is seen through a point. A probe left of A with qy = 0
        // makes the crossing test bend at A whenever the source is not at A itself.
        px = 0;
        py = e3;
        qx = -1;
        qy = 0;
        g.inv_2e1 = 0;
      }
      g.e1 = Real(e1);
      g.px = Real(px);
      g.py = Real(py);
      g.qx = Real(qx);
      g.qy = Real(qy);
    }
  }
  return geo;
}

template std::vector<HalfedgeGeometry<float>> build_halfedge_geometry<float>(
    const TriangleMesh&, double, const VisibilityHeuristic&);
template std::vector<HalfedgeGeometry<double>> build_halfedge_geometry<double>(
    const TriangleMesh&, double, const VisibilityHeuristic&);

}  // namespace gsp::detail
