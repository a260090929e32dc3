// The walk's moves: the straight stretch inside a face, the turn at a vertex, the step across
// an edge into the neighbour (walk.hpp).
#include "walk.hpp"

#include <algorithm>
#include <cmath>

namespace gsp::pathfinding::detail {

bool Walk::exit_of(const Walker& w, double& t_exit, int& exit_corner, Bary& bs) const {
  if (!bary_of(w.face, w.target, bs)) return false;
  t_exit = 1;
  exit_corner = -1;
  for (int i = 0; i < 3; ++i) {
    const double bi = std::max(0.0, w.bary[i]);
    if (!(bs[i] < -kBaryTol)) continue;   // the target on the inner side of edge i (or on it)
    // Running along the edge we came in by (the target on its line up to rounding): do not
    // bounce back across it.
    const double size = std::max({1.0, std::abs(bs[0]), std::abs(bs[1]), std::abs(bs[2])});
    if (w.entry != kInvalidIndex && bi <= kVertexTol && Index(i) == corner_of(prev_halfedge(w.entry)) &&
        bs[i] > -1e-4 * size)
      continue;
    const double t = bi / (bi - bs[i]);
    if (t < t_exit) t_exit = t, exit_corner = i;
  }
  return true;
}

// At vertex v: either v is the source, or the path goes on into the incident face whose own
// source explains v's distance best (the smallest sigma + |v - S|), preferring faces the
// straight line v -> S actually enters. `keep` when the source w carries is shorter than all.
Walk::VertexStep Walk::at_vertex(Index v, Walker& w) {
  const Vec3 pv = mesh_.positions[v];
  // A source unfolded onto v's position is v only where v's own value is 0: on a CAD wall an
  // unfolding of the source landed on a vertex 8 units from it and the walk ended there as if
  // at the source (docs/pathfinding.md, "Needles, fins and T-junctions").
  const std::vector<double>& values = field_.vertex_distance();
  const double dv = v < values.size() ? values[v] : kInf;
  double best = kInf, best_any = kInf;
  Index at_v = kInvalidIndex;
  struct Start {
    Index face = kInvalidIndex;
    Bary bary{};
  } best_start, best_any_start;
  // A face g holding v (at a corner, or on an edge) at weights b, whose corners j, l bound the
  // wedge the straight line from v to g's source must enter.
  auto consider = [&](Index g, const Bary& b, int j, int l) {
    const VirtualSource s = field_.source_at(g, pv);
    const double d = own_value(g, pv);
    Bary bs;
    bary_of(g, s.position, bs);
    const bool enters = bs[j] >= -kBaryTol && bs[l] >= -kBaryTol;
    if (d < best_any) best_any = d, best_any_start = {g, b};
    if (enters && d < best) best = d, best_start = {g, b};
  };
  for (Index k = conn_.vertex_corner_begin[v]; k < conn_.vertex_corner_begin[v + 1]; ++k) {
    const Index c = conn_.vertex_corners[k];
    const Index f = face_of(c);
    const Index i = corner_of(c);
    if (!usable(f)) {
      // A face without area with v on its long edge (a CAD part's T-junction: v lies on the
      // edge of the faces beyond): v is a point of those faces' edge, and the walk starts in
      // them. The field's value at v comes from them; with v's faces all flat or without
      // the reached one, the walk had no face to start in.
      if (!reached(f) || repeats_vertex(mesh_.triangles[f])) continue;
      const Index h = 3 * f + Index((i + 1) % 3);   // the edge opposite v
      for (Index g = conn_.radial_next[h]; g != h; g = conn_.radial_next[g]) {
        const Index fg = face_of(g);
        Bary b;
        if (fg == f || !usable(fg) || !bary_of(fg, pv, b)) continue;
        const int opposite = int(corner_of(prev_halfedge(g)));
        if (std::min({b[0], b[1], b[2]}) < -kBaryTol || b[opposite] > kBaryTol) continue;   // v not on that edge
        const VirtualSource s = field_.source_at(fg, pv);
        if (distance(s.position, pv) <= 10 * eps_) continue;
        b[opposite] = 0;
        consider(fg, b, opposite, opposite);
      }
      continue;
    }
    const VirtualSource s = field_.source_at(f, pv);
    if (distance(s.position, pv) <= 10 * eps_) {
      // The face's source sits on v: v is the real source (sigma 0), or the path turned here
      // and this face does not lead further.
      if (s.sigma <= eps_) {
        if (!(dv > 10 * eps_ && dv < kInf)) {
          out_.source = s.source;
          return VertexStep::source;
        }
        continue;
      }
      at_v = f;
      continue;
    }
    consider(f, corner_bary(i), int((i + 1) % 3), int((i + 2) % 3));
  }
  // A carried source clearly shorter than any face's own: go on with it.
  const double carried = w.face != kInvalidIndex && w.sigma < kInf ? w.value() : kInf;
  const double tol = 1e-6 * carried + 10 * eps_;
  if (best_start.face != kInvalidIndex && best > carried + tol) best_start = {};
  if (best_start.face == kInvalidIndex && best_any <= carried + tol) best_start = best_any_start, best = best_any;
  if (best_start.face == kInvalidIndex) {
    if (carried < kInf) return VertexStep::keep;
    // Every reached face has its source on v: a vertex source with an initial offset.
    if (at_v != kInvalidIndex) {
      out_.source = field_.source_at(at_v, pv).source;
      return VertexStep::source;
    }
    return VertexStep::stuck;
  }
  w.face = best_start.face;
  w.bary = best_start.bary;
  w.position = pv;
  w.entry = kInvalidIndex;
  adopt_own(w);
  return VertexStep::moved;
}

// from's target unfolded about the edge of halfedge h into the plane of the neighbour across
// it (halfedge g): edge frame x along a -> b, y towards each face's third corner; the target
// lies on the far side of the edge seen from `from`, i.e. on the neighbour's side. False for
// an edge of zero length (no frame).
bool Walk::unfold_target(const Walker& from, Index h, Index g, Vec3& target) const {
  const Index a = from_vertex(mesh_, h), b = to_vertex(mesh_, h);
  const Vec3 pa = mesh_.positions[a], pb = mesh_.positions[b];
  const double len = distance(pa, pb);
  if (!(len > 0)) return false;
  const Vec3 c_from = mesh_.positions[mesh_.triangles[from.face][corner_of(prev_halfedge(h))]];
  const Vec3 c_to = mesh_.positions[mesh_.triangles[face_of(g)][corner_of(prev_halfedge(g))]];
  const Vec3 ex = (1.0 / len) * (pb - pa);
  auto normal_dir = [&](Vec3 c) {
    const Vec3 y = (c - pa) - dot(c - pa, ex) * ex;
    const double n = norm(y);
    return n > 0 ? (1.0 / n) * y : Vec3{};
  };
  const Vec3 yf = normal_dir(c_from), yt = normal_dir(c_to);
  const double x = dot(from.target - pa, ex), y = dot(from.target - pa, yf);
  target = pa + x * ex - y * yt;
  return true;
}

// How far the face of halfedge g (across h's edge, or past faces without area along it) is
// from going on straight: from's target unfolded into its plane against its own source at q
// (position and sigma); 0 where there is nothing to compare.
double Walk::continuation_mismatch(const Walker& from, Index h, Index g, Vec3 q) const {
  Vec3 unfolded;
  if (!(from.sigma < kInf) || !unfold_target(from, h, g, unfolded)) return 0.0;
  const VirtualSource own = field_.source_at(face_of(g), q);
  return distance(unfolded, own.position) + std::abs(from.sigma - own.sigma);
}

// Crosses halfedge h of `from` at its point bq into the neighbour that continues the path best
// (at a non-manifold edge: the smallest own distance at the crossing; of neighbours that tie,
// the one whose own source is where from's target unfolds to, i.e. where the straight line
// goes on), carrying from's target over, unfolded about the edge into the neighbour's plane.
bool Walk::cross(const Walker& from, Index h, const Bary& bq, Walker& to) const {
  const Index a = from_vertex(mesh_, h);
  const double wa = bq[corner_of(h)], wb = bq[corner_of(next_halfedge(h))];
  const double s = wa + wb > 0 ? wb / (wa + wb) : 0.5;   // q = (1 - s) a + s b
  const Vec3 q = from.position;
  // Back over the edge it came by, where more than two faces meet: not into the face it came
  // from. On a house STL's fin two faces of such an edge each held a source across it, and the
  // walk went back and forth between them until its step limit; the path then fell back to
  // the edges (paths from one vertex: 5.1% over the field on average, up to 19.6%).
  const bool shared = from.came_over != kInvalidIndex && conn_.halfedge_edge[h] == from.came_over &&
                      conn_.radial_next[conn_.radial_next[h]] != h;
  const Index came_from = shared ? from.came_from : kInvalidIndex;
  // Neighbours within rounding of each other: on a wall meeting a ledge at a non-manifold edge
  // the crossing point has one distance in every face of the edge, and the first face of the
  // ring (the ledge's, its source unfolded from the far side) turned a wall path into a 6%
  // longer one (docs/pathfinding.md, "Needles, fins and T-junctions").
  const Index pick = best_neighbour(from, h, q, [&](auto&& visit) {
    for (Index g = conn_.radial_next[h]; g != h; g = conn_.radial_next[g]) {
      const Index f = face_of(g);
      if (f != from.face && f != came_from && usable(f)) visit(g);
    }
  });
  if (pick == kInvalidIndex) return cross_past_flat(from, h, to);
  const bool same = from_vertex(mesh_, pick) == a;   // the neighbour may walk the edge either way
  Bary b{0, 0, 0};
  b[corner_of(pick)] = same ? 1 - s : s;
  b[corner_of(next_halfedge(pick))] = same ? s : 1 - s;
  enter(from, h, pick, b, to);
  return true;
}

void Walk::enter(const Walker& from, Index h, Index g, const Bary& b, Walker& to) const {
  to = from;
  to.face = face_of(g);
  to.bary = b;
  to.entry = g;
  to.came_from = from.face, to.came_over = conn_.halfedge_edge[g];
  if (!unfold_target(from, h, g, to.target)) {
    adopt_own(to);
    return;
  }
  to.own = false;
}

}  // namespace gsp::pathfinding::detail
