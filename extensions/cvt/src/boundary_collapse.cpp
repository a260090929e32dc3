#include "boundary_collapse.hpp"
#include "locked_vertices.hpp"
#include "triangle_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace gsp::cvt::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

std::size_t collapse_boundary_edges(TriangleMesh& m, const BoundaryCurves& curves, double below_angle_deg,
                                    double max_deviation, int passes, const std::vector<bool>* fixed) {
  if (curves.loops.empty()) return 0;
  const double below = below_angle_deg * kPi / 180.0;
  const double fold_cos = std::cos(40.0 * kPi / 180.0);
  const std::size_t V = m.num_vertices();
  std::size_t total = 0;
  for (int pass = 0; pass < passes; ++pass) {
    std::vector<std::vector<Index>> faces_of(V);
    std::unordered_map<std::uint64_t, Index> directed;
    for (Index f = 0; f < m.num_faces(); ++f)
      for (Index i = 0; i < 3; ++i) {
        faces_of[m.triangles[f][i]].push_back(f);
        directed[edge_key(m.triangles[f][i], m.triangles[f][(i + 1) % 3])] = f;
      }
    BoundaryLinks links = boundary_links(m, directed);
    std::vector<Index>& next_b = links.next;
    std::vector<Index>& prev_b = links.prev;
    const std::vector<int>& out_count = links.out_count;
    std::vector<std::size_t> loop_of(V, std::size_t(-1));
    std::vector<double> arc(V, 0);
    for (std::size_t v = 0; v < V; ++v) {
      if (out_count[v] != 1) continue;
      std::size_t l = 0;
      double s = 0, d = 0;
      if (curves.project(m.positions[v], l, s, d) && d <= 1e-3 * distance(m.positions[v], m.positions[next_b[v]]))
        loop_of[v] = l, arc[v] = s;
    }
    auto neighbours = [&](Index v) {
      std::vector<Index> n;
      for (Index f : faces_of[v])
        for (Index w : m.triangles[f])
          if (w != v) n.push_back(w);
      std::sort(n.begin(), n.end());
      n.erase(std::unique(n.begin(), n.end()), n.end());
      return n;
    };
    std::vector<bool> locked(V, false), removed(m.num_faces(), false);
    std::size_t collapses = 0;
    for (Index f = 0; f < m.num_faces(); ++f)
      for (Index i = 0; i < 3; ++i) {
        if (removed[f]) break;
        const Triangle t = m.triangles[f];
        const Index a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
        if (next_b[a] != b || locked[a] || locked[b] || locked[c] || out_count[c] != 0) continue;
        if (is_locked(fixed, a) || is_locked(fixed, b)) continue;   // a feature curve's sample
        const Vec3 pa = m.positions[a], pb = m.positions[b], pc = m.positions[c];
        const double at_c = angle_at(pc, pa, pb);
        if (at_c >= below || at_c > angle_at(pa, pb, pc) || at_c > angle_at(pb, pc, pa)) continue;
        const std::size_t l = loop_of[a];
        const Index pa_ = prev_b[a], nb_ = next_b[b];
        if (l == std::size_t(-1) || loop_of[b] != l || pa_ == kInvalidIndex || nb_ == kInvalidIndex || nb_ == pa_ ||
            loop_of[pa_] != l || loop_of[nb_] != l)
          continue;
        const double L = curves.loops[l].length;
        const double back = curves.wrap(l, arc[a] - arc[pa_]), span = curves.wrap(l, arc[b] - arc[a]),
                     ahead = curves.wrap(l, arc[nb_] - arc[b]);
        if (back + span + ahead > 0.75 * L) continue;   // not in the curve's order
        // Link condition: a and b share no neighbour but c.
        std::vector<Index> na = neighbours(a), nbv = neighbours(b), common;
        std::set_intersection(na.begin(), na.end(), nbv.begin(), nbv.end(), std::back_inserter(common));
        if (common.size() != 1 || common[0] != c) continue;
        // The faces around a and b, T included once.
        std::vector<Index> ring = faces_of[a];
        for (Index g : faces_of[b])
          if (g != f) ring.push_back(g);
        double before = 10;
        for (Index g : ring) {
          const Triangle& u = m.triangles[g];
          const Vec3 q0 = m.positions[u[0]], q1 = m.positions[u[1]], q2 = m.positions[u[2]];
          before = std::min({before, angle_at(q0, q1, q2), angle_at(q1, q2, q0), angle_at(q2, q0, q1)});
        }
        double best = before, best_s = 0;
        Vec3 best_x;
        for (double offset : {0.5 * span, 0.0, span}) {
          const double s = curves.wrap(l, arc[a] + offset);
          const Vec3 x = curves.at(l, s);
          double worst = 10;
          for (Index g : ring) {
            if (g == f) continue;
            const Triangle& u = m.triangles[g];
            Vec3 q[3], o[3];
            for (int k = 0; k < 3; ++k) {
              o[k] = m.positions[u[k]];
              q[k] = (u[k] == a || u[k] == b) ? x : o[k];
            }
            const Vec3 n0 = cross(o[1] - o[0], o[2] - o[0]), n1 = cross(q[1] - q[0], q[2] - q[0]);
            if (dot(n0, n1) <= fold_cos * norm(n0) * norm(n1)) {
              worst = -1;
              break;
            }
            worst = std::min({worst, angle_at(q[0], q[1], q[2]), angle_at(q[1], q[2], q[0]), angle_at(q[2], q[0], q[1])});
          }
          if (worst > best + 1e-9) best = worst, best_s = s, best_x = x;
        }
        if (best <= before + 1e-9) continue;
        const double chord_before = std::max({curves.chord_deviation(l, arc[pa_], back),
                                              curves.chord_deviation(l, arc[a], span),
                                              curves.chord_deviation(l, arc[b], ahead)});
        const double chord_after = std::max(curves.chord_deviation(l, arc[pa_], curves.wrap(l, best_s - arc[pa_])),
                                            curves.chord_deviation(l, best_s, curves.wrap(l, arc[nb_] - best_s)));
        if (chord_after > std::max(chord_before, max_deviation)) continue;
        // Collapse b into a, at best_x.
        m.positions[a] = best_x;
        for (Index g : faces_of[b])
          for (Index& w : m.triangles[g])
            if (w == b) w = a;
        removed[f] = true;
        for (Index v : na) locked[v] = true;
        for (Index v : nbv) locked[v] = true;
        locked[a] = locked[b] = true;
        ++collapses;
      }
    if (collapses == 0) break;
    std::vector<Triangle> kept;
    kept.reserve(m.num_faces());
    for (Index f = 0; f < m.num_faces(); ++f)
      if (!removed[f]) kept.push_back(m.triangles[f]);
    m.triangles = std::move(kept);
    total += collapses;
  }
  return total;
}

}  // namespace gsp::cvt::detail
