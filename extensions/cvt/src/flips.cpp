#include "flips.hpp"
#include "locked_vertices.hpp"
#include "triangle_geometry.hpp"


#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace gsp::cvt::detail {

namespace {

// Directed edge (a, b) -> 3 * face + corner of a, kept up to date through flips.
struct DirectedEdges {
  std::unordered_map<std::uint64_t, Index> map;

  explicit DirectedEdges(const TriangleMesh& m) {
    map.reserve(3 * m.num_faces());
    for (Index f = 0; f < m.num_faces(); ++f)
      for (Index i = 0; i < 3; ++i) map[edge_key(m.triangles[f][i], m.triangles[f][(i + 1) % 3])] = 3 * f + i;
  }
  bool exists(Index a, Index b) const { return map.count(edge_key(a, b)) || map.count(edge_key(b, a)); }
  // Faces f = (a, b, c) and g = (b, a, d) become (a, d, c) and (d, b, c).
  void flip(TriangleMesh& m, Index f, Index g, Index a, Index b, Index c, Index d) {
    for (Index k = 0; k < 3; ++k) {
      map.erase(edge_key(m.triangles[f][k], m.triangles[f][(k + 1) % 3]));
      map.erase(edge_key(m.triangles[g][k], m.triangles[g][(k + 1) % 3]));
    }
    m.triangles[f] = {a, d, c};
    m.triangles[g] = {d, b, c};
    for (Index k = 0; k < 3; ++k) {
      map[edge_key(m.triangles[f][k], m.triangles[f][(k + 1) % 3])] = 3 * f + k;
      map[edge_key(m.triangles[g][k], m.triangles[g][(k + 1) % 3])] = 3 * g + k;
    }
  }
};

}  // namespace

std::size_t improve_by_flips(TriangleMesh& m, double max_normal_angle_deg, int max_passes,
                             const std::vector<bool>* locked) {
  const double cos_limit = std::cos(max_normal_angle_deg * 3.14159265358979323846 / 180.0);
  DirectedEdges directed(m);
  std::size_t flips = 0;
  for (int pass = 0; pass < max_passes; ++pass) {
    std::size_t this_pass = 0;
    for (Index f = 0; f < m.num_faces(); ++f)
      for (Index i = 0; i < 3; ++i) {
        const Triangle t = m.triangles[f];
        const Index a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
        if (is_locked_edge(locked, a, b)) continue;
        const auto it = directed.map.find(edge_key(b, a));
        if (it == directed.map.end()) continue;   // boundary or inconsistently oriented
        const Index g = it->second / 3, j = it->second % 3;
        if (g == f) continue;
        const Index d = m.triangles[g][(j + 2) % 3];
        if (d == c || directed.exists(c, d)) continue;
        const Vec3 pa = m.positions[a], pb = m.positions[b], pc = m.positions[c], pd = m.positions[d];
        if (angle_at(pc, pa, pb) + angle_at(pd, pb, pa) <= 3.14159265358979323846 + 1e-12) continue;
        const double before = std::min(min_angle(pa, pb, pc), min_angle(pb, pa, pd));
        const double after = std::min(min_angle(pa, pd, pc), min_angle(pd, pb, pc));
        if (after <= before) continue;
        // No fold: both new triangles face the way the old pair faces, and the old pair is
        // nearly flat (not a crease, where a flip would change the shape).
        const Vec3 n1 = normal(pa, pb, pc), n2 = normal(pb, pa, pd);
        const Vec3 m1 = normal(pa, pd, pc), m2 = normal(pd, pb, pc);
        if (dot(n1, n2) < cos_limit * norm(n1) * norm(n2)) continue;
        const Vec3 n = n1 + n2;
        if (dot(m1, n) <= 0 || dot(m2, n) <= 0) continue;
        directed.flip(m, f, g, a, b, c, d);
        ++this_pass;
      }
    flips += this_pass;
    if (this_pass == 0) break;
  }
  return flips;
}

std::size_t remove_caps(TriangleMesh& m, double cap_angle_deg,
                        const std::function<bool(Index, Index, Index, Index, Index, Index)>& keeps_surface,
                        const std::function<void()>& flipped) {
  const double cap = cap_angle_deg * 3.14159265358979323846 / 180.0;
  DirectedEdges directed(m);
  std::size_t flips = 0;
  for (Index f = 0; f < m.num_faces(); ++f)
    for (Index i = 0; i < 3; ++i) {
      const Triangle t = m.triangles[f];
      const Index a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
      const Vec3 pa = m.positions[a], pb = m.positions[b], pc = m.positions[c];
      if (angle_at(pc, pa, pb) <= cap) continue;
      const auto it = directed.map.find(edge_key(b, a));
      if (it == directed.map.end()) continue;
      const Index g = it->second / 3, j = it->second % 3;
      if (g == f) continue;
      const Index d = m.triangles[g][(j + 2) % 3];
      if (d == c || directed.exists(c, d)) continue;
      const Vec3 pd = m.positions[d];
      const double before = std::min(min_angle(pa, pb, pc), min_angle(pb, pa, pd));
      const double after = std::min(min_angle(pa, pd, pc), min_angle(pd, pb, pc));
      if (after <= before) continue;
      const Vec3 n = normal(pa, pb, pc) + normal(pb, pa, pd);
      if (dot(normal(pa, pd, pc), n) <= 0 || dot(normal(pd, pb, pc), n) <= 0) continue;
      if (!keeps_surface(f, g, a, b, c, d)) continue;
      directed.flip(m, f, g, a, b, c, d);
      ++flips;
      flipped();
      break;
    }
  return flips;
}

}  // namespace gsp::cvt::detail
