// The walk's crossing past faces without area (walk.hpp): CAD T-junctions.
#include "walk.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace gsp::pathfinding::detail {

// Where every other face of h's edge has no area (a CAD part's T-junction: a vertex on the
// edge, joined to it by a face whose corners lie on one line), the walk goes on past such
// faces: from the crossing point q over their other edges that q lies on, into the first face
// with area (the least own distance at q), up to kMaxFlatChain faces deep. The faces beyond
// meet the edge's line, so the target unfolds about it as over the edge itself. Before, the
// walk stopped at such edges and the path came from the fallbacks (a square with a T-junction
// on its diagonal: 3.24 for 2.83).
bool Walk::cross_past_flat(const Walker& from, Index h, Walker& to) const {
  constexpr int kMaxFlatChain = 8;
  const Vec3 q = from.position;
  auto flat = [&](Index f) {
    Bary unused;
    return f != from.face && !bary_of(f, mesh_.positions[mesh_.triangles[f][0]], unused);
  };
  auto holds_q = [&](Index g) {   // q on the edge of halfedge g
    const Vec3 pa = mesh_.positions[from_vertex(mesh_, g)], pb = mesh_.positions[to_vertex(mesh_, g)];
    const Vec3 d = pb - pa;
    const double dd = dot(d, d);
    const double t = dd > 0 ? std::clamp(dot(q - pa, d) / dd, 0.0, 1.0) : 0.0;
    return distance(q, pa + t * d) <= 1e-6 * std::sqrt(dd) + 10 * eps_;
  };
  std::array<Index, 2 * kMaxFlatChain> stack{};
  std::array<Index, 2 * kMaxFlatChain> seen{};
  std::size_t top = 0, n_seen = 0;
  auto visit = [&](Index g) {
    const Index f = face_of(g);
    if (!flat(f) || n_seen == seen.size() || std::find(seen.begin(), seen.begin() + n_seen, f) != seen.begin() + n_seen)
      return;
    seen[n_seen++] = f;
    if (top < stack.size()) stack[top++] = g;
  };
  for (Index g = conn_.radial_next[h]; g != h; g = conn_.radial_next[g]) visit(g);
  std::array<Index, 2 * kMaxFlatChain> found{};
  std::size_t n_found = 0;
  while (top > 0) {
    const Index g = stack[--top];
    for (const Index e : {next_halfedge(g), prev_halfedge(g)}) {
      if (!holds_q(e)) continue;
      for (Index r = conn_.radial_next[e]; r != e; r = conn_.radial_next[r]) {
        const Index f = face_of(r);
        if (f == from.face) continue;
        if (!usable(f)) visit(r);
        else if (n_found < found.size()) found[n_found++] = r;
      }
    }
  }
  // As in cross() (past a T-junction's vertex the faces on both sides of it give q one
  // distance).
  const Index pick = best_neighbour(from, h, q, [&](auto&& visit_face) {
    for (std::size_t k = 0; k < n_found; ++k) visit_face(found[k]);
  });
  if (pick == kInvalidIndex) return false;
  const Vec3 pa = mesh_.positions[from_vertex(mesh_, pick)], pb = mesh_.positions[to_vertex(mesh_, pick)];
  const Vec3 d = pb - pa;
  const double dd = dot(d, d);
  const double s = dd > 0 ? std::clamp(dot(q - pa, d) / dd, 0.0, 1.0) : 0.0;
  Bary b{0, 0, 0};
  b[corner_of(pick)] = 1 - s;
  b[corner_of(next_halfedge(pick))] = s;
  enter(from, h, pick, b, to);
  return true;
}

}  // namespace gsp::pathfinding::detail
