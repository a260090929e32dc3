#include "measures.hpp"

#include <gsp/topology.hpp>

#include <algorithm>
#include <cmath>

namespace gsp::info {

namespace {
double percentile_sorted(const std::vector<double>& v, double q) {
  const double pos = q * static_cast<double>(v.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}
}  // namespace

Summary summarize(std::vector<double> values) {
  Summary s;
  s.count = values.size();
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  s.min = values.front();
  s.max = values.back();
  double sum = 0;
  for (double v : values) sum += v;
  s.mean = sum / static_cast<double>(values.size());
  double sq = 0;  // second pass: the one-pass formula loses digits when stddev << mean
  for (double v : values) sq += (v - s.mean) * (v - s.mean);
  s.stddev = std::sqrt(sq / static_cast<double>(values.size()));
  s.median = percentile_sorted(values, 0.5);
  s.p99 = percentile_sorted(values, 0.99);
  return s;
}

ShapeMeasures shape_measures(const TriangleMesh& mesh) {
  ShapeMeasures m;
  const std::vector<bool> degenerate = degenerate_faces(mesh);
  std::vector<double> ar;
  ar.reserve(mesh.num_faces());
  double anisotropy_sum = 0;
  std::size_t above_10 = 0;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    if (degenerate[f]) {
      ++m.degenerate_faces;
      continue;
    }
    const Triangle& t = mesh.triangles[f];
    const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const double la = distance(b, c), lb = distance(c, a), lc = distance(a, b);
    const double lmax = std::max({la, lb, lc}), lmin = std::min({la, lb, lc});
    const double area = 0.5 * norm(cross(b - a, c - a));
    const double r = lmax * (la + lb + lc) / (4.0 * std::sqrt(3.0) * area);
    anisotropy_sum += lmax / lmin;
    if (r > 10.0) ++above_10;
    ar.push_back(r);
  }
  const std::size_t n = ar.size();
  if (n > 0) {
    m.anisotropy = anisotropy_sum / static_cast<double>(n);
    m.aspect_ratio_above_10 = static_cast<double>(above_10) / static_cast<double>(n);
  }
  m.aspect_ratio = summarize(std::move(ar));
  return m;
}

Summary edge_lengths(const TriangleMesh& mesh, const Connectivity& conn) {
  std::vector<double> lengths;
  lengths.reserve(conn.num_edges());
  for (Index h : conn.edge_halfedge)
    lengths.push_back(distance(mesh.positions[from_vertex(mesh, h)], mesh.positions[to_vertex(mesh, h)]));
  return summarize(std::move(lengths));
}

std::size_t max_valence(const Connectivity& conn) {
  std::size_t best = 0;
  for (std::size_t v = 0; v + 1 < conn.vertex_corner_begin.size(); ++v)
    best = std::max<std::size_t>(best, conn.vertex_corner_begin[v + 1] - conn.vertex_corner_begin[v]);
  return best;
}

}  // namespace gsp::info
