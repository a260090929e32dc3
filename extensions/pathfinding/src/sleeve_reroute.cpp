// Rerouting the sleeve round the other side of a bend where that side's angle is below pi: the
// path there is not locally shortest (sleeve_shortener.hpp).
#include "sleeve_shortener.hpp"

#include <utility>

namespace gsp::pathfinding::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

bool Shortener::reroute_round() {
  unfold();
  funnel();
  bool changed = false;
  // Bends from the last to the first, so the sleeve indices of earlier ones stay valid.
  std::size_t limit = s_.faces.size();   // faces from here on were replaced this round
  for (std::size_t b = bends_.size(); b-- > 0;)
    if (reroute_bend(b, limit)) changed = true;
  if (!changed) return false;
  s_.remove_loops();
  trim_to_ends();
  return true;
}

// A bend at a vertex whose angle on the other side of the path is below pi can be undone: the
// sleeve goes round that side instead. False where it is a true corner or cannot be rerouted.
bool Shortener::reroute_bend(std::size_t b, std::size_t& limit) {
  const Bend& bend = bends_[b];
  const Portal& p = portals_[bend.portal];
  const Index v = bend.left ? p.left_vertex : p.right_vertex;
  if (v == kInvalidIndex) return false;
  std::size_t lo, hi;
  portals_round(v, bend.portal, lo, hi);
  const std::size_t i = lo - 1, j = hi;   // sleeve faces round v: i .. j
  if (j >= limit || i == j) return false;
  Sleeve side;
  double between = 0;
  if (!other_fan(v, i, j, side, between)) return false;
  // Not below pi: a true corner of the geodesic (or a boundary).
  if (!(other_side_angle(b, v, lo, hi, between) < kPi - 1e-9)) return false;
  splice(i, j, side);
  limit = i + 1;
  return true;
}

// The bend's vertex is shared by a run of inner portals, lo .. hi: the sleeve faces between
// them fan round it.
void Shortener::portals_round(Index v, std::size_t portal, std::size_t& lo, std::size_t& hi) const {
  auto has_v = [&](std::size_t i) {
    return i > 0 && i + 1 < portals_.size() && (portals_[i].left_vertex == v || portals_[i].right_vertex == v);
  };
  lo = portal, hi = portal;
  while (has_v(lo - 1)) --lo;
  while (has_v(hi + 1)) ++hi;
}

// The other side: from face i over its edge at v that is not portal lo, round to face j; false
// where there is no such fan or it comes back the sleeve's own way.
bool Shortener::other_fan(Index v, std::size_t i, std::size_t j, Sleeve& side, double& between) const {
  const Index fi = s_.faces[i];
  const Index ci = corner_at(fi, v);
  const Index hv = 3 * fi + ci, hp = prev_halfedge(3 * fi + ci);   // fi's two edges at v
  const Index first = s_.exit[i] == hv ? hp : hv;
  return fan(v, s_.faces[j], first, side, &between) && side.entry.back() != s_.entry[j];
}

// The angle the path sweeps at v on the other side: the rest of face i's corner after the
// incoming direction, the faces in between, the part of face j's corner before the outgoing.
double Shortener::other_side_angle(std::size_t b, Index v, std::size_t lo, std::size_t hi, double between) const {
  const P2 V = bend_point(bends_[b]);
  const P2 prev = b == 0 ? portals_[0].left : bend_point(bends_[b - 1]);
  const P2 next = b + 1 == bends_.size() ? portals_.back().left : bend_point(bends_[b + 1]);
  auto other_end = [&](std::size_t portal) {
    return portals_[portal].left_vertex == v ? portals_[portal].right : portals_[portal].left;
  };
  const Index fi = s_.faces[lo - 1], fj = s_.faces[hi];
  return between + corner_angle(fi, corner_at(fi, v)) + corner_angle(fj, corner_at(fj, v)) -
         angle2(sub(prev, V), sub(other_end(lo), V)) - angle2(sub(other_end(hi), V), sub(next, V));
}

// Faces i+1 .. j give way to the other side's fan (which ends with face j).
void Shortener::splice(std::size_t i, std::size_t j, const Sleeve& side) {
  Sleeve s;
  s.faces.assign(s_.faces.begin(), s_.faces.begin() + i + 1);
  s.entry.assign(s_.entry.begin(), s_.entry.begin() + i + 1);
  s.exit.assign(s_.exit.begin(), s_.exit.begin() + i);
  s.append(side);
  s.exit.push_back(s_.exit[j]);
  s.faces.insert(s.faces.end(), s_.faces.begin() + j + 1, s_.faces.end());
  s.entry.insert(s.entry.end(), s_.entry.begin() + j + 1, s_.entry.end());
  s.exit.insert(s.exit.end(), s_.exit.begin() + j + 1, s_.exit.end());
  s_ = std::move(s);
}

// Rerouting can pass the start or the end again: the sleeve is trimmed back to them.
void Shortener::trim_to_ends() {
  std::size_t first = 0, last = s_.faces.size() - 1;
  for (std::size_t k = 0; k < s_.faces.size(); ++k)
    if (contains(s_.faces[k], start_)) first = k;
  for (std::size_t k = s_.faces.size(); k-- > first;)
    if (contains(s_.faces[k], end_)) last = k;
  if (first > 0 || last + 1 < s_.faces.size()) s_.keep(first, last);
}

}  // namespace gsp::pathfinding::detail
