#include "intrinsic_delaunay.hpp"

#include <gsp/connectivity.hpp>

#include <algorithm>
#include <cmath>

namespace gsp::detail {
namespace {

// Angle opposite side c in a triangle with sides a, b, c (clamped: slivers round past +-1).
double opposite_angle(double a, double b, double c) {
  if (!(a > 0 && b > 0)) return 0;
  const double cosine = (a * a + b * b - c * c) / (2 * a * b);
  return std::acos(std::clamp(cosine, -1.0, 1.0));
}

// The twin of h when its edge is flippable, else kInvalidIndex.
Index flippable_twin(const IntrinsicTriangulation& t, Index h) {
  const Index g = t.ring[h];
  if (g == h || t.ring[g] != h) return kInvalidIndex;   // boundary or non-manifold
  const Index f1 = face_of(h), f2 = face_of(g);
  if (f1 == f2 || t.skipped[f1] || t.skipped[f2]) return kInvalidIndex;
  const Triangle& a = t.triangles[f1];
  const Triangle& b = t.triangles[f2];
  // Consistent orientation: g runs the edge backwards.
  if (a[corner_of(h)] != b[corner_of(next_halfedge(g))]) return kInvalidIndex;
  if (a[corner_of(prev_halfedge(h))] == b[corner_of(prev_halfedge(g))]) return kInvalidIndex;
  return g;
}

bool is_delaunay(const IntrinsicTriangulation& t, Index h, Index g) {
  const double lab = t.length[h];
  const double ac = opposite_angle(t.length[next_halfedge(h)], t.length[prev_halfedge(h)], lab);
  const double ad = opposite_angle(t.length[next_halfedge(g)], t.length[prev_halfedge(g)], t.length[g]);
  return ac + ad <= 3.14159265358979323846 * (1 + 1e-9);
}

}  // namespace

std::size_t make_intrinsic_delaunay(IntrinsicTriangulation& t, std::size_t max_flips) {
  const Index nh = Index(t.length.size());
  std::vector<Index> stack;
  std::vector<char> queued(nh, 0);
  for (Index h = 0; h < nh; ++h)
    if (flippable_twin(t, h) != kInvalidIndex && h < t.ring[h]) stack.push_back(h), queued[h] = 1;
  std::size_t flips = 0;
  while (!stack.empty() && flips < max_flips) {
    const Index h = stack.back();
    stack.pop_back();
    queued[h] = 0;
    const Index g = flippable_twin(t, h);
    if (g == kInvalidIndex || is_delaunay(t, h, g)) continue;
    const Index f1 = face_of(h), f2 = face_of(g);
    const Index hn = next_halfedge(h), hp = prev_halfedge(h), gn = next_halfedge(g), gp = prev_halfedge(g);
    const Index a = t.triangles[f1][corner_of(h)], b = t.triangles[f1][corner_of(hn)];
    const Index c = t.triangles[f1][corner_of(hp)], d = t.triangles[f2][corner_of(gp)];
    const double lab = t.length[h], lbc = t.length[hn], lca = t.length[hp];
    const double lad = t.length[gn], ldb = t.length[gp];
    // Unfold: a = (0, 0), b = (lab, 0), c above, d below; the new diagonal is |cd|.
    const double cx = (lab * lab + lca * lca - lbc * lbc) / (2 * lab);
    const double cy = std::sqrt(std::max(0.0, lca * lca - cx * cx));
    const double dx = (lab * lab + lad * lad - ldb * ldb) / (2 * lab);
    const double dy = -std::sqrt(std::max(0.0, lad * lad - dx * dx));
    const double lcd = std::hypot(cx - dx, cy - dy);
    if (!(lcd > 0) || !std::isfinite(lcd)) continue;
    // Outer halfedges and where they go: f1' = (c, a, d), f2' = (d, b, c).
    const Index outer_old[4] = {hp, gn, gp, hn};   // c->a, a->d, d->b, b->c
    const Index base1 = 3 * f1, base2 = 3 * f2;
    const Index outer_new[4] = {base1 + 0, base1 + 1, base2 + 0, base2 + 1};
    const double outer_len[4] = {lca, lad, ldb, lbc};
    Index outer_ring[4];
    for (int k = 0; k < 4; ++k) outer_ring[k] = t.ring[outer_old[k]];
    auto remap = [&](Index x) {
      for (int k = 0; k < 4; ++k)
        if (x == outer_old[k]) return outer_new[k];
      return x;
    };
    t.triangles[f1] = {c, a, d};
    t.triangles[f2] = {d, b, c};
    for (int k = 0; k < 4; ++k) {
      t.length[outer_new[k]] = outer_len[k];
      // Its ring partner (if any) must now point at the new index; a ring of one points at itself.
      const Index partner = outer_ring[k] == outer_old[k] ? outer_new[k] : remap(outer_ring[k]);
      t.ring[outer_new[k]] = partner;
    }
    // Every other halfedge whose ring link pointed at a moved halfedge.
    for (int k = 0; k < 4; ++k) {
      if (outer_ring[k] == outer_old[k]) continue;
      // Walk the partner's ring to the link that points to the old index.
      Index x = outer_ring[k];
      for (Index guard = 0; guard < nh; ++guard) {
        const Index nx = t.ring[x];
        if (nx == outer_old[k]) {
          t.ring[x] = outer_new[k];
          break;
        }
        if (nx == outer_new[k]) break;   // already relinked (the partner moved too)
        x = nx;
      }
    }
    t.length[base1 + 2] = t.length[base2 + 2] = lcd;   // d->c and c->d
    t.ring[base1 + 2] = base2 + 2;
    t.ring[base2 + 2] = base1 + 2;
    ++flips;
    for (Index x : {base1 + 0, base1 + 1, base2 + 0, base2 + 1})
      if (!queued[x] && flippable_twin(t, x) != kInvalidIndex) stack.push_back(x), queued[x] = 1;
  }
  return flips;
}

}  // namespace gsp::detail
