#include "sleeve.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace gsp::pathfinding::detail {

namespace {

using P2 = std::array<double, 2>;
constexpr double kPi = 3.14159265358979323846;

double cross2(P2 a, P2 b) { return a[0] * b[1] - a[1] * b[0]; }
P2 sub(P2 a, P2 b) { return {a[0] - b[0], a[1] - b[1]}; }
double angle2(P2 a, P2 b) { return std::atan2(std::abs(cross2(a, b)), a[0] * b[0] + a[1] * b[1]); }

// An end of the path as the mesh vertices it is a weighted sum of (one for a vertex, two on
// an edge, three inside a face).
struct End {
  Index vertex[3];
  double weight[3];
  int n = 0;
};

// A walk through faces: faces[k] is entered from faces[k - 1] over the edge whose halfedge in
// faces[k - 1] is exit[k - 1] and in faces[k] is entry[k].
struct Sleeve {
  std::vector<Index> faces, entry, exit;

  // Cuts out every detour that comes back to a face it already passed (the walk can circle a
  // vertex or step back and forth); a shortest path crosses a face at most once (a
  // simplification: on strongly curved meshes a geodesic may cross a long face twice).
  void remove_loops() {
    std::vector<Index> f2, e2, x2;
    for (std::size_t k = 0; k < faces.size(); ++k) {
      std::size_t at = f2.size();
      for (std::size_t m = 0; m < f2.size(); ++m)
        if (f2[m] == faces[k]) at = m;
      if (at < f2.size()) {   // back at f2[at]: drop what came after it, leave by this exit
        f2.resize(at + 1), e2.resize(at + 1), x2.resize(at + 1);
        x2[at] = exit[k];
        continue;
      }
      f2.push_back(faces[k]), e2.push_back(entry[k]), x2.push_back(exit[k]);
    }
    faces.swap(f2), entry.swap(e2), exit.swap(x2);
  }
};

class Shortener {
 public:
  Shortener(const TriangleMesh& mesh, const Connectivity& conn) : mesh_(mesh), conn_(conn) {}

  bool build(const PathPoint& start, const PathPoint& end, const std::vector<Index>& segment_faces);
  // One round: funnel, then reroute every bend that can be undone; false when none could.
  bool reroute_round();
  void emit(std::vector<PathPoint>& out);
  std::size_t sleeve_size() const { return s_.faces.size(); }

 private:
  struct Portal {
    P2 left, right;
    Index left_vertex, right_vertex;   // kInvalidIndex for the two end "portals"
  };
  struct Bend {
    std::size_t portal;
    bool left;
  };

  bool valid_face(Index f) const {
    const Triangle& t = mesh_.triangles[f];
    return t[0] != t[1] && t[1] != t[2] && t[0] != t[2];
  }
  bool contains(Index f, const End& e) const {
    const Triangle& t = mesh_.triangles[f];
    for (int i = 0; i < e.n; ++i)
      if (t[0] != e.vertex[i] && t[1] != e.vertex[i] && t[2] != e.vertex[i]) return false;
    return true;
  }
  Index corner_at(Index f, Index v) const {
    for (Index c = 0; c < 3; ++c)
      if (mesh_.triangles[f][c] == v) return c;
    return kInvalidIndex;
  }
  double corner_angle(Index f, Index c) const {
    const Triangle& t = mesh_.triangles[f];
    const Vec3 p = mesh_.positions[t[c]];
    const Vec3 a = mesh_.positions[t[(c + 1) % 3]] - p, b = mesh_.positions[t[(c + 2) % 3]] - p;
    return std::atan2(norm(gsp::cross(a, b)), dot(a, b));
  }
  // The halfedge of face b on the edge that halfedge h of face a lies on, if any.
  Index across(Index h, Index b) const {
    for (Index g = conn_.radial_next[h]; g != h; g = conn_.radial_next[g])
      if (face_of(g) == b) return g;
    return kInvalidIndex;
  }
  bool link(Index a, Index b, Index& ha, Index& hb) const {
    for (Index i = 0; i < 3; ++i)
      if ((hb = across(3 * a + i, b)) != kInvalidIndex) return ha = 3 * a + i, true;
    return false;
  }
  // The faces round v from the face of `first_exit` (one of its halfedges at v, the edge to
  // leave by) to `to` (not including the first face, including `to`); manifold edges only.
  // Appends to `out` (face, entry halfedge, exit halfedge of the previous face) and gives the
  // summed corner angles at v of the faces strictly in between.
  bool fan(Index v, Index to, Index first_exit, Sleeve& out, double* angle) const;

  void unfold();
  void funnel();
  P2 end_point(std::size_t k, const End& e) const;

  const TriangleMesh& mesh_;
  const Connectivity& conn_;
  Sleeve s_;
  End start_, end_;
  std::vector<std::array<P2, 3>> corner2_;   // per sleeve face: its corners in the unfolding
  std::vector<Portal> portals_;              // start, the edges between sleeve faces, end
  std::vector<Bend> bends_;
};

End end_of(const TriangleMesh& mesh, const PathPoint& p) {
  End e;
  std::array<double, 3> b = p.barycentric;
  for (double& x : b) x = std::max(0.0, x);
  const double sum = b[0] + b[1] + b[2];
  for (int i = 0; i < 3; ++i)
    if (b[i] > 1e-9 * sum) e.vertex[e.n] = mesh.triangles[p.face][i], e.weight[e.n++] = b[i] / sum;
  return e;
}

bool Shortener::fan(Index v, Index to, Index first_exit, Sleeve& out, double* angle) const {
  Index h = first_exit;
  double sum = 0;
  for (std::size_t guard = 0; guard < 256; ++guard) {
    const Index g = conn_.radial_next[h];
    if (g == h || conn_.radial_next[g] != h) return false;   // boundary or non-manifold edge
    const Index next = face_of(g);
    if (!valid_face(next)) return false;
    out.faces.push_back(next), out.entry.push_back(g), out.exit.push_back(h);
    if (next == to) {
      if (angle) *angle = sum;
      return true;
    }
    sum += corner_angle(next, corner_at(next, v));
    // Leave `next` over its other edge through v.
    h = from_vertex(mesh_, g) == v ? prev_halfedge(g) : next_halfedge(g);
  }
  return false;
}

bool Shortener::build(const PathPoint& start, const PathPoint& end, const std::vector<Index>& segment_faces) {
  if (segment_faces.empty()) return false;
  start_ = end_of(mesh_, start);
  end_ = end_of(mesh_, end);
  Sleeve s;
  for (const Index f : segment_faces) {
    if (f >= mesh_.num_faces() || !valid_face(f)) return false;
    if (!s.faces.empty() && s.faces.back() == f) continue;
    if (s.faces.empty()) {
      s.faces.push_back(f), s.entry.push_back(kInvalidIndex);
      continue;
    }
    const Index a = s.faces.back();
    Index ha, hb;
    if (link(a, f, ha, hb)) {
      s.exit.push_back(ha), s.faces.push_back(f), s.entry.push_back(hb);
      continue;
    }
    // The path runs through a vertex the two faces share: go round it on the side with the
    // smaller angle (the shortening moves it to the other side if that is shorter).
    Index v = kInvalidIndex;
    for (Index x : mesh_.triangles[a])
      if (corner_at(f, x) != kInvalidIndex) v = x;
    if (v == kInvalidIndex) return false;
    Sleeve best, side;
    double best_angle = 0, angle = 0;
    const Index ca = corner_at(a, v);
    for (Index h0 : {3 * a + ca, prev_halfedge(3 * a + ca)}) {
      side = Sleeve{};
      if (fan(v, f, h0, side, &angle) && (best.faces.empty() || angle < best_angle))
        best = side, best_angle = angle;
    }
    if (best.faces.empty()) return false;
    for (std::size_t i = 0; i < best.faces.size(); ++i)
      s.exit.push_back(best.exit[i]), s.faces.push_back(best.faces[i]), s.entry.push_back(best.entry[i]);
  }
  s.exit.push_back(kInvalidIndex);
  s.remove_loops();
  s_ = std::move(s);
  // The sleeve starts at the last face holding the start and ends at the first one after it
  // holding the end.
  std::size_t first = s_.faces.size(), last = s_.faces.size();
  for (std::size_t k = 0; k < s_.faces.size(); ++k)
    if (contains(s_.faces[k], start_)) first = k;
  if (first == s_.faces.size()) return false;
  for (std::size_t k = first; k < s_.faces.size() && last == s_.faces.size(); ++k)
    if (contains(s_.faces[k], end_)) last = k;
  if (last == s_.faces.size()) return false;
  s_.faces = {s_.faces.begin() + first, s_.faces.begin() + last + 1};
  s_.entry = {s_.entry.begin() + first, s_.entry.begin() + last + 1};
  s_.exit = {s_.exit.begin() + first, s_.exit.begin() + last + 1};
  s_.entry.front() = kInvalidIndex, s_.exit.back() = kInvalidIndex;
  return true;
}

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

bool Shortener::reroute_round() {
  unfold();
  funnel();
  bool changed = false;
  // Bends from the last to the first, so the sleeve indices of earlier ones stay valid.
  std::size_t limit = s_.faces.size();   // faces from here on were replaced this round
  for (std::size_t b = bends_.size(); b-- > 0;) {
    const Bend& bend = bends_[b];
    const Portal& p = portals_[bend.portal];
    const Index v = bend.left ? p.left_vertex : p.right_vertex;
    if (v == kInvalidIndex) continue;
    auto has_v = [&](std::size_t i) {
      return i > 0 && i + 1 < portals_.size() && (portals_[i].left_vertex == v || portals_[i].right_vertex == v);
    };
    std::size_t lo = bend.portal, hi = bend.portal;
    while (has_v(lo - 1)) --lo;
    while (has_v(hi + 1)) ++hi;
    const std::size_t i = lo - 1, j = hi;   // sleeve faces round v: i .. j
    if (j >= limit || i == j) continue;
    const P2 V = bend.left ? p.left : p.right;
    const P2 prev = b == 0 ? portals_[0].left
                           : (bends_[b - 1].left ? portals_[bends_[b - 1].portal].left : portals_[bends_[b - 1].portal].right);
    const P2 next = b + 1 == bends_.size()
                        ? portals_.back().left
                        : (bends_[b + 1].left ? portals_[bends_[b + 1].portal].left : portals_[bends_[b + 1].portal].right);
    auto other_end = [&](std::size_t portal) {
      return portals_[portal].left_vertex == v ? portals_[portal].right : portals_[portal].left;
    };
    // The other side: from face i over its edge at v that is not portal lo, round to face j.
    Sleeve side;
    double between = 0;
    const Index fi = s_.faces[i];
    const Index ci = corner_at(fi, v);
    const Index hv = 3 * fi + ci, hp = prev_halfedge(3 * fi + ci);   // fi's two edges at v
    const Index first = s_.exit[i] == hv ? hp : hv;
    if (!fan(v, s_.faces[j], first, side, &between)) continue;
    if (side.entry.back() == s_.entry[j]) continue;   // came back the sleeve's own way
    // The angle the path sweeps at v on that side: the rest of face i's corner after the
    // incoming direction, the faces in between, the part of face j's corner before the outgoing.
    const double other_side = between + corner_angle(fi, ci) + corner_angle(s_.faces[j], corner_at(s_.faces[j], v)) -
                              angle2(sub(prev, V), sub(other_end(lo), V)) -
                              angle2(sub(other_end(hi), V), sub(next, V));
    if (!(other_side < kPi - 1e-9)) continue;   // a true corner of the geodesic (or a boundary)
    // Replace faces i+1 .. j by the other side's fan (which ends with face j).
    Sleeve s;
    s.faces.assign(s_.faces.begin(), s_.faces.begin() + i + 1);
    s.entry.assign(s_.entry.begin(), s_.entry.begin() + i + 1);
    s.exit.assign(s_.exit.begin(), s_.exit.begin() + i);
    for (std::size_t k = 0; k < side.faces.size(); ++k)
      s.exit.push_back(side.exit[k]), s.faces.push_back(side.faces[k]), s.entry.push_back(side.entry[k]);
    s.exit.push_back(s_.exit[j]);
    s.faces.insert(s.faces.end(), s_.faces.begin() + j + 1, s_.faces.end());
    s.entry.insert(s.entry.end(), s_.entry.begin() + j + 1, s_.entry.end());
    s.exit.insert(s.exit.end(), s_.exit.begin() + j + 1, s_.exit.end());
    s_ = std::move(s);
    limit = i + 1;
    changed = true;
  }
  if (!changed) return false;
  s_.remove_loops();
  // Rerouting can pass the start or the end again: trim.
  std::size_t first = 0, last = s_.faces.size() - 1;
  for (std::size_t k = 0; k < s_.faces.size(); ++k)
    if (contains(s_.faces[k], start_)) first = k;
  for (std::size_t k = s_.faces.size(); k-- > first;)
    if (contains(s_.faces[k], end_)) last = k;
  if (first > 0 || last + 1 < s_.faces.size()) {
    s_.faces = {s_.faces.begin() + first, s_.faces.begin() + last + 1};
    s_.entry = {s_.entry.begin() + first, s_.entry.begin() + last + 1};
    s_.exit = {s_.exit.begin() + first, s_.exit.begin() + last + 1};
    s_.entry.front() = kInvalidIndex, s_.exit.back() = kInvalidIndex;
  }
  return true;
}

void Shortener::emit(std::vector<PathPoint>& out) {
  unfold();
  funnel();
  out.clear();
  auto bary_point = [&](Index f, const End& e) {
    PathPoint q;
    q.face = f;
    q.barycentric = {0, 0, 0};
    for (int i = 0; i < e.n; ++i) q.barycentric[corner_at(f, e.vertex[i])] += e.weight[i];
    const Triangle& t = mesh_.triangles[f];
    q.position = q.barycentric[0] * mesh_.positions[t[0]] + q.barycentric[1] * mesh_.positions[t[1]] +
                 q.barycentric[2] * mesh_.positions[t[2]];
    return q;
  };
  auto push = [&](const PathPoint& q) {
    if (!out.empty() && distance(out.back().position, q.position) <= 1e-12 * (1 + norm(q.position))) return;
    out.push_back(q);
  };
  push(bary_point(s_.faces[0], start_));
  // Straight sections between the start, the bends and the end.
  std::vector<std::pair<std::size_t, P2>> apexes{{0, portals_[0].left}};
  for (const Bend& b : bends_) apexes.push_back({b.portal, b.left ? portals_[b.portal].left : portals_[b.portal].right});
  apexes.push_back({portals_.size() - 1, portals_.back().left});
  for (std::size_t a = 0; a + 1 < apexes.size(); ++a) {
    const auto [ia, P] = apexes[a];
    const auto [ib, Q] = apexes[a + 1];
    const P2 d = sub(Q, P);
    for (std::size_t k = ia + 1; k <= ib && k + 1 < portals_.size(); ++k) {
      const Portal& pt = portals_[k];
      const P2 e = sub(pt.right, pt.left);
      double t;   // along left -> right
      if (k == ib) {
        t = bends_[a].left ? 0 : 1;
      } else {
        const double den = cross2(e, d);
        t = std::abs(den) > 0 ? cross2(sub(P, pt.left), d) / den : 0.5;
        t = std::min(1.0, std::max(0.0, t));
      }
      const Index f = s_.faces[k - 1];
      End on_edge;
      on_edge.vertex[0] = pt.left_vertex, on_edge.weight[0] = 1 - t;
      on_edge.vertex[1] = pt.right_vertex, on_edge.weight[1] = t;
      on_edge.n = 2;
      push(bary_point(f, on_edge));
    }
  }
  PathPoint last = bary_point(s_.faces.back(), end_);
  if (!out.empty() && out.size() > 1 && distance(out.back().position, last.position) <= 1e-12 * (1 + norm(last.position)))
    out.pop_back();
  out.push_back(last);
}

}  // namespace

bool shorten_in_sleeve(const TriangleMesh& mesh, const Connectivity& conn, const PathPoint& start, const PathPoint& end,
                       const std::vector<Index>& segment_faces, std::vector<PathPoint>& out,
                       const SleeveOptions& options) {
  Shortener s(mesh, conn);
  if (!s.build(start, end, segment_faces)) return false;
  const std::size_t cap = options.max_reroutes ? options.max_reroutes : 4 * s.sleeve_size() + 256;
  for (std::size_t round = 0; round < cap && s.reroute_round(); ++round) {
  }
  s.emit(out);
  return true;
}

}  // namespace gsp::pathfinding::detail
