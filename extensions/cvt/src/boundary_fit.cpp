#include "boundary_fit.hpp"
#include "locked_vertices.hpp"
#include "triangle_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <vector>

namespace gsp::cvt::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

std::size_t snap_boundary_vertices(TriangleMesh& m, const BoundaryCurves& curves, double min_angle_deg,
                                   const std::vector<bool>* locked) {
  if (curves.loops.empty()) return 0;
  const double floor_angle = min_angle_deg * kPi / 180.0;
  const std::size_t V = m.num_vertices();
  std::unordered_set<std::uint64_t> directed;
  for (const Triangle& t : m.triangles)
    for (Index i = 0; i < 3; ++i) directed.insert(edge_key(t[i], t[(i + 1) % 3]));
  std::vector<double> boundary_length(V, 0);   // of the boundary edges at the vertex
  std::vector<std::vector<Index>> faces_of(V);
  for (Index f = 0; f < m.num_faces(); ++f) {
    const Triangle& t = m.triangles[f];
    for (Index i = 0; i < 3; ++i) {
      faces_of[t[i]].push_back(f);
      if (directed.count(edge_key(t[(i + 1) % 3], t[i]))) continue;
      const double len = distance(m.positions[t[i]], m.positions[t[(i + 1) % 3]]);
      boundary_length[t[i]] = std::max(boundary_length[t[i]], len);
      boundary_length[t[(i + 1) % 3]] = std::max(boundary_length[t[(i + 1) % 3]], len);
    }
  }
  auto worst_angle = [&](Index v, Vec3 x, bool& folds) {
    double worst = 10;
    folds = false;
    for (Index f : faces_of[v]) {
      const Triangle& t = m.triangles[f];
      Vec3 q[3], o[3];
      for (int k = 0; k < 3; ++k) o[k] = q[k] = m.positions[t[k]];
      for (int k = 0; k < 3; ++k)
        if (t[k] == v) q[k] = x;
      const Vec3 n0 = cross(o[1] - o[0], o[2] - o[0]), n1 = cross(q[1] - q[0], q[2] - q[0]);
      if (dot(n0, n1) <= 0) folds = true;
      worst = std::min(worst, min_angle(q[0], q[1], q[2]));
    }
    return worst;
  };
  std::size_t snapped = 0;
  for (Index v = 0; v < V; ++v) {
    if (boundary_length[v] == 0 || is_locked(locked, v)) continue;
    std::size_t l = 0;
    double s = 0, d = 0;
    if (!curves.project(m.positions[v], l, s, d) || d <= 1e-3 * boundary_length[v]) continue;
    const Vec3 x = curves.at(l, s);
    bool folds = false;
    const double before = worst_angle(v, m.positions[v], folds);
    const double after = worst_angle(v, x, folds);
    if (folds || after < std::min(before, floor_angle)) continue;
    m.positions[v] = x;
    ++snapped;
  }
  return snapped;
}

std::size_t split_boundary_edges(TriangleMesh& m, const BoundaryCurves& curves, double max_chord, double min_angle_deg,
                                 int passes, const std::vector<bool>* locked) {
  if (curves.loops.empty() || !(max_chord > 0)) return 0;
  const double floor_angle = min_angle_deg * kPi / 180.0;
  std::size_t total = 0;
  for (int pass = 0; pass < passes; ++pass) {
    std::unordered_set<std::uint64_t> directed;
    for (const Triangle& t : m.triangles)
      for (Index i = 0; i < 3; ++i) directed.insert(edge_key(t[i], t[(i + 1) % 3]));
    std::size_t splits = 0;
    const std::size_t faces = m.num_faces();
    for (Index f = 0; f < faces; ++f)
      for (Index i = 0; i < 3; ++i) {
        const Triangle t = m.triangles[f];
        const Index a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
        if (directed.count(edge_key(b, a)) || is_locked_edge(locked, a, b)) continue;
        std::size_t la = 0, lb = 0;
        double sa = 0, sb = 0, da = 0, db = 0;
        const double len = distance(m.positions[a], m.positions[b]);
        if (!curves.project(m.positions[a], la, sa, da) || !curves.project(m.positions[b], lb, sb, db) || la != lb ||
            !(da < len) || !(db < len))
          continue;
        const bool dent = da > 1e-3 * len || db > 1e-3 * len;   // an end the snaps left inside
        const BoundaryCurves::Loop& loop = curves.loops[la];
        const double span = curves.wrap(la, sb - sa);
        if (span > 0.5 * loop.length) continue;   // not in the curve's order
        // The curve's vertex between a and b farthest from the chord.
        const Vec3 pa = m.positions[a], pb = m.positions[b], pc = m.positions[c];
        const std::size_t n = loop.points.size();
        std::size_t j = std::upper_bound(loop.s.begin(), loop.s.end(), sa) - loop.s.begin();
        double worst = 0;
        Vec3 split;
        for (std::size_t k = 0; k < n; ++k, ++j) {
          const std::size_t q = j % n;
          const double along = loop.s[q] - sa + (j >= n ? loop.length : 0.0);
          if (along >= span) break;
          const double d = segment_distance(loop.points[q], pa, pb);
          if (d > worst) worst = d, split = loop.points[q];
        }
        if (worst <= max_chord) continue;
        const Vec3 n0 = cross(pb - pa, pc - pa), n1 = cross(split - pa, pc - pa), n2 = cross(pb - split, pc - split);
        if (dot(n0, n1) <= 0 || dot(n0, n2) <= 0) continue;
        const double need = std::min(min_angle(pa, pb, pc), dent ? kDentFloorDeg * kPi / 180.0 : floor_angle);
        if (std::min(min_angle(pa, split, pc), min_angle(split, pb, pc)) < need) continue;
        const Index mid = Index(m.positions.size());
        m.positions.push_back(split);
        m.triangles[f] = {a, mid, c};
        m.triangles.push_back({mid, b, c});
        ++splits;
        break;   // this face changed; its other edges wait for the next pass
      }
    total += splits;
    if (splits == 0) break;
  }
  return total;
}

}  // namespace gsp::cvt::detail
