#include "boundary_curves.hpp"
#include "triangle_geometry.hpp"

#include <gsp/connectivity.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace gsp::cvt::detail {

BoundaryCurves::BoundaryCurves(const TriangleMesh& m) {
  const Connectivity conn = build_connectivity(m);
  std::unordered_map<Index, Index> leaving;   // vertex -> a boundary halfedge from it
  std::vector<Index> boundary;
  for (Index h = 0; h < conn.num_halfedges(); ++h)
    if (conn.halfedge_edge[h] != kInvalidIndex && conn.radial_next[h] == h) {
      leaving.emplace(from_vertex(m, h), h);
      boundary.push_back(h);
    }
  std::unordered_map<Index, bool> used;
  for (Index start : boundary) {
    if (used[start]) continue;
    Loop loop;
    Index h = start;
    while (!used[h]) {
      used[h] = true;
      loop.points.push_back(m.positions[from_vertex(m, h)]);
      const auto it = leaving.find(to_vertex(m, h));
      if (it == leaving.end()) break;
      h = it->second;
    }
    if (loop.points.size() < 3) continue;
    loop.s.push_back(0);
    for (std::size_t i = 0; i < loop.points.size(); ++i)
      loop.s.push_back(loop.s.back() + distance(loop.points[i], loop.points[(i + 1) % loop.points.size()]));
    loop.length = loop.s.back();
    if (loop.length > 0) loops.push_back(std::move(loop));
  }
}

double BoundaryCurves::wrap(std::size_t l, double s) const {
  const double L = loops[l].length;
  s = std::fmod(s, L);
  return s < 0 ? s + L : s;
}

Vec3 BoundaryCurves::at(std::size_t l, double s) const {
  const Loop& loop = loops[l];
  s = wrap(l, s);
  const std::size_t i = std::min<std::size_t>(
      std::upper_bound(loop.s.begin(), loop.s.end(), s) - loop.s.begin() - 1, loop.points.size() - 1);
  const double len = loop.s[i + 1] - loop.s[i];
  const double t = len > 0 ? (s - loop.s[i]) / len : 0.0;
  return (1 - t) * loop.points[i] + t * loop.points[(i + 1) % loop.points.size()];
}

bool BoundaryCurves::project(Vec3 p, std::size_t& loop_out, double& s_out, double& d_out) const {
  d_out = 1e300;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const Loop& loop = loops[l];
    const std::size_t n = loop.points.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 a = loop.points[i], b = loop.points[(i + 1) % n], d = b - a;
      const double dd = dot(d, d);
      const double t = dd > 0 ? std::clamp(dot(p - a, d) / dd, 0.0, 1.0) : 0.0;
      const double dist = distance(p, a + t * d);
      if (dist < d_out) d_out = dist, loop_out = l, s_out = loop.s[i] + t * (loop.s[i + 1] - loop.s[i]);
    }
  }
  return d_out < 1e300;
}

double BoundaryCurves::chord_deviation(std::size_t l, double s0, double span) const {
  const Loop& loop = loops[l];
  const Vec3 a = at(l, s0), b = at(l, s0 + span);
  const std::size_t n = loop.points.size();
  double worst = 0;
  const double start = wrap(l, s0);
  std::size_t i = std::upper_bound(loop.s.begin(), loop.s.end(), start) - loop.s.begin();
  for (std::size_t k = 0; k < n; ++k, ++i) {
    const std::size_t j = i % n;
    const double along = loop.s[j] - start + (i >= n ? loop.length : 0.0);
    if (along > span) break;
    worst = std::max(worst, segment_distance(loop.points[j], a, b));
  }
  return worst;
}

}  // namespace gsp::cvt::detail
