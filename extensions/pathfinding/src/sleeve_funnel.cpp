// The sleeve unfolded into the plane and the path pulled straight in it (the funnel), then
// written back onto the mesh (sleeve_shortener.hpp).
#include "sleeve_shortener.hpp"

#include <algorithm>
#include <utility>

namespace gsp::pathfinding::detail {

namespace {

// Where a straight section from P in direction d crosses a portal from a to b: 0 at a, 1 at
// b; clamped, so rounding cannot put the path off the edge.
double crossing(P2 a, P2 b, P2 P, P2 d) {
  const P2 e = sub(b, a);
  const double den = cross2(e, d);
  const double t = std::abs(den) > 0 ? cross2(sub(P, a), d) / den : 0.5;
  return std::min(1.0, std::max(0.0, t));
}

}  // namespace

void Shortener::unfold() {
  const std::size_t n = s_.faces.size();
  corner2_.resize(n);
  auto pos = [&](Index f, Index c) { return mesh_.positions[mesh_.triangles[f][c]]; };
  {
    const Index f = s_.faces[0];
    const double l01 = distance(pos(f, 0), pos(f, 1));
    const Vec3 e = pos(f, 2) - pos(f, 0);
    const double x = l01 > 0 ? dot(e, (1.0 / l01) * (pos(f, 1) - pos(f, 0))) : 0;
    corner2_[0] = {P2{0, 0}, P2{l01, 0}, P2{x, std::sqrt(std::max(0.0, dot(e, e) - x * x))}};
  }
  portals_.assign(1, Portal{});
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const Index f = s_.faces[k], g = s_.faces[k + 1];
    const Index h = s_.exit[k], gh = s_.entry[k + 1];
    const Index ca = corner_of(h), cb = corner_of(next_halfedge(h)), cc = corner_of(prev_halfedge(h));
    const P2 A = corner2_[k][ca], B = corner2_[k][cb], C = corner2_[k][cc];
    const Index va = mesh_.triangles[f][ca], vb = mesh_.triangles[f][cb];
    // The next face: its corners on the edge copy A and B, its third corner goes to the other
    // side of the edge than C.
    const Index gc = corner_of(prev_halfedge(gh));
    const Index ga = corner_at(g, va), gb = corner_at(g, vb);
    const double len = std::hypot(B[0] - A[0], B[1] - A[1]);
    const P2 u = len > 0 ? P2{(B[0] - A[0]) / len, (B[1] - A[1]) / len} : P2{1, 0};
    P2 nrm{-u[1], u[0]};
    if (cross2(u, sub(C, A)) > 0) nrm = P2{u[1], -u[0]};
    const Vec3 e = pos(g, gc) - pos(g, ga);
    const double along = len > 0 ? dot(e, (1.0 / distance(pos(g, ga), pos(g, gb))) * (pos(g, gb) - pos(g, ga))) : 0;
    const double height = std::sqrt(std::max(0.0, dot(e, e) - along * along));
    corner2_[k + 1][ga] = A, corner2_[k + 1][gb] = B;
    corner2_[k + 1][gc] = P2{A[0] + along * u[0] + height * nrm[0], A[1] + along * u[1] + height * nrm[1]};
    // Facing forward (away from C), the left end of the edge.
    const P2 left_dir{-nrm[1], nrm[0]};
    const bool a_left = (A[0] - B[0]) * left_dir[0] + (A[1] - B[1]) * left_dir[1] > 0;
    portals_.push_back(a_left ? Portal{A, B, va, vb} : Portal{B, A, vb, va});
  }
  const P2 ps = end_point(0, start_), pe = end_point(n - 1, end_);
  portals_.front() = {ps, ps, kInvalidIndex, kInvalidIndex};
  portals_.push_back({pe, pe, kInvalidIndex, kInvalidIndex});
}

P2 Shortener::end_point(std::size_t k, const End& e) const {
  P2 p{0, 0};
  for (int i = 0; i < e.n; ++i) {
    const P2 c = corner2_[k][corner_at(s_.faces[k], e.vertex[i])];
    p[0] += e.weight[i] * c[0], p[1] += e.weight[i] * c[1];
  }
  return p;
}

// The funnel ("string pulling") over the portals: the shortest path inside the unfolded
// sleeve bends only at portal ends, where the funnel's two sides cross.
void Shortener::funnel() {
  bends_.clear();
  P2 apex = portals_[0].left, L = apex, R = apex;
  std::size_t li = 0, ri = 0;
  for (std::size_t i = 1; i < portals_.size(); ++i) {
    const P2 pl = portals_[i].left, pr = portals_[i].right;
    if (cross2(sub(R, apex), sub(pr, apex)) >= 0) {   // pr narrows the funnel from the right
      if (apex == R || cross2(sub(L, apex), sub(pr, apex)) < 0) {
        R = pr, ri = i;
      } else {   // crosses the left side: the path bends at L
        bends_.push_back({li, true});
        apex = L, R = L, ri = li, i = li;
        continue;
      }
    }
    if (cross2(sub(L, apex), sub(pl, apex)) <= 0) {   // pl narrows it from the left
      if (apex == L || cross2(sub(R, apex), sub(pl, apex)) > 0) {
        L = pl, li = i;
      } else {
        bends_.push_back({ri, false});
        apex = R, L = R, li = ri, i = ri;
        continue;
      }
    }
  }
}

void Shortener::emit(std::vector<PathPoint>& out) {
  unfold();
  funnel();
  out.clear();
  // A point at the previous one (up to the coordinates' rounding: a few dozen ulps, relative to
  // the positions, not to a unit length; camelhead scaled by 1e-7 lost a point 0.1% of an edge
  // from the last to 1e-12 absolute, and the segment then skipped the face between them).
  auto same_place = [](Vec3 a, Vec3 b) { return distance(a, b) <= 1e-14 * std::max(norm(a), norm(b)); };
  auto push = [&](const PathPoint& q) {
    if (!out.empty() && same_place(out.back().position, q.position)) return;
    out.push_back(q);
  };
  push(bary_point(s_.faces[0], start_));
  // Straight sections between the start, the bends and the end.
  std::vector<std::pair<std::size_t, P2>> apexes{{0, portals_[0].left}};
  for (const Bend& b : bends_) apexes.push_back({b.portal, bend_point(b)});
  apexes.push_back({portals_.size() - 1, portals_.back().left});
  for (std::size_t a = 0; a + 1 < apexes.size(); ++a) {
    const auto [ia, P] = apexes[a];
    const auto [ib, Q] = apexes[a + 1];
    const P2 d = sub(Q, P);
    for (std::size_t k = ia + 1; k <= ib && k + 1 < portals_.size(); ++k) {
      const Portal& pt = portals_[k];
      // Along left -> right; a section ends at its bend's side of the portal.
      const double t = k == ib ? (bends_[a].left ? 0.0 : 1.0) : crossing(pt.left, pt.right, P, d);
      End on_edge;
      on_edge.vertex[0] = pt.left_vertex, on_edge.weight[0] = 1 - t;
      on_edge.vertex[1] = pt.right_vertex, on_edge.weight[1] = t;
      on_edge.n = 2;
      push(bary_point(s_.faces[k - 1], on_edge));
    }
  }
  PathPoint last = bary_point(s_.faces.back(), end_);
  if (!out.empty() && out.size() > 1 && same_place(out.back().position, last.position)) out.pop_back();
  out.push_back(last);
}

// The path's points go back onto the mesh as points of sleeve faces, each in the face that
// holds the segment ending there.
PathPoint Shortener::bary_point(Index f, const End& e) const {
  PathPoint q;
  q.point = SurfacePoint::in_face(f, {0, 0, 0});
  for (int i = 0; i < e.n; ++i) q.point.barycentric[corner_at(f, e.vertex[i])] += e.weight[i];
  q.position = q.point.position(mesh_);
  return q;
}

}  // namespace gsp::pathfinding::detail
