#include <gsp/pathfinding/path_tracer.hpp>

#include "descent_faces.hpp"
#include "sleeve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace gsp::pathfinding {

namespace {

using Bary = std::array<double, 3>;
constexpr double kInf = std::numeric_limits<double>::infinity();
// Barycentric slack: a coordinate this far below 0 still counts as on the edge (the sources
// are stored in single precision by default; relative position errors are about 1e-7).
constexpr double kBaryTol = 1e-6;
// A point this close to a corner (in barycentric terms) is that vertex.
constexpr double kVertexTol = 1e-6;
// A virtual source with sigma > 0 this close to a corner is that corner.
constexpr double kCornerSnap = 1e-3;

// The walk's state: a point of a face, the halfedge it entered the face through (so that a
// path running along that edge is not bounced back across it), and the source it is heading
// for: a point S in the face's plane and sigma, the face's own virtual source or one carried
// over from the faces behind, unfolded across the edges crossed.
struct Walker {
  Index face = kInvalidIndex;
  Bary bary{1, 0, 0};
  Vec3 position;
  Index entry = kInvalidIndex;
  Vec3 target;
  double sigma = kInf;
  Index label = kInvalidIndex;
  bool own = false;   // target is the face's own virtual source
  double value() const { return sigma + distance(position, target); }
};

class Walk {
 public:
  Walk(const TriangleMesh& mesh, const Connectivity& conn, const GeodesicResult& field, double mean_edge,
       std::size_t max_steps)
      : mesh_(mesh), conn_(conn), field_(field), eps_(1e-7 * mean_edge), max_steps_(max_steps) {}

  GeodesicPath run(const Endpoint& end);

 private:
  bool reached(Index f) const { return f < field_.face_sources.size() && field_.face_sources[f].reached(); }

  // Barycentric coordinates of x (projected into f's plane); false for a degenerate face.
  bool bary_of(Index f, Vec3 x, Bary& b) const {
    const Triangle& t = mesh_.triangles[f];
    const Vec3 a = mesh_.positions[t[0]];
    const Vec3 e0 = mesh_.positions[t[1]] - a, e1 = mesh_.positions[t[2]] - a, e2 = x - a;
    const double d00 = dot(e0, e0), d01 = dot(e0, e1), d11 = dot(e1, e1), d20 = dot(e2, e0), d21 = dot(e2, e1);
    const double denom = d00 * d11 - d01 * d01;
    if (!(denom > 1e-12 * d00 * d11) || t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return false;
    b[1] = (d11 * d20 - d01 * d21) / denom;
    b[2] = (d00 * d21 - d01 * d20) / denom;
    b[0] = 1 - b[1] - b[2];
    return true;
  }
  bool usable(Index f) const {
    Bary b;
    return reached(f) && bary_of(f, mesh_.positions[mesh_.triangles[f][0]], b);
  }
  double own_value(Index f, Vec3 x) const {
    const VirtualSource& s = field_.face_sources[f];
    return s.sigma + distance(x, s.position);
  }
  Vec3 point(Index f, const Bary& b) const {
    const Triangle& t = mesh_.triangles[f];
    return b[0] * mesh_.positions[t[0]] + b[1] * mesh_.positions[t[1]] + b[2] * mesh_.positions[t[2]];
  }
  void adopt_own(Walker& w) const {
    const VirtualSource& s = field_.face_sources[w.face];
    w.target = s.position, w.sigma = s.sigma, w.label = s.source, w.own = true;
  }
  // Appends w's point; its face is the one the segment from the previous point lies in.
  void emit(const Walker& w) {
    if (!out_.points.empty() && distance(out_.points.back().position, w.position) <= eps_) return;
    out_.points.push_back({w.face, w.bary, w.position});
  }
  void shorten();
  void drop_face_bends();
  void pull_taut();
  bool unpin_vertices();

  // The straight walk from w towards its target: the parameter t in [0, 1] where it leaves the
  // face and through which corner's opposite edge (-1: the target is inside the face).
  bool exit_of(const Walker& w, double& t_exit, int& exit_corner, Bary& bs) const;
  // The own source of w's face leads into the face from w (not straight back out).
  bool own_enters(const Walker& w) const {
    Walker o = w;
    adopt_own(o);
    double t;
    int corner;
    Bary bs;
    return exit_of(o, t, corner, bs) && (corner < 0 || t > 1e-9);
  }
  // The face's own source (reached inside the face) is a real source: the face's corners are
  // about as near the sources as the field says the source point is.
  bool genuine_source(const Walker& w) const {
    const Triangle& t = mesh_.triangles[w.face];
    double edge = 0, nearest = kInf;
    for (int i = 0; i < 3; ++i) {
      edge = std::max(edge, distance(mesh_.positions[t[i]], mesh_.positions[t[(i + 1) % 3]]));
      if (t[i] < field_.vertex_distance.size()) nearest = std::min(nearest, field_.vertex_distance[t[i]]);
    }
    return nearest <= w.sigma + 1.5 * edge + 10 * eps_;
  }
  enum class VertexStep { moved, source, keep, stuck };
  VertexStep at_vertex(Index v, Walker& w);
  bool cross(const Walker& from, Index h, const Bary& bq, Walker& to) const;

  const TriangleMesh& mesh_;
  const Connectivity& conn_;
  const GeodesicResult& field_;
  double eps_;
  std::size_t max_steps_;
  GeodesicPath out_;
};

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
  double best = kInf, best_any = kInf;
  Index best_corner = kInvalidIndex, best_any_corner = kInvalidIndex, at_v = kInvalidIndex;
  for (Index k = conn_.vertex_corner_begin[v]; k < conn_.vertex_corner_begin[v + 1]; ++k) {
    const Index c = conn_.vertex_corners[k];
    const Index f = face_of(c);
    if (!usable(f)) continue;
    const VirtualSource& s = field_.face_sources[f];
    if (distance(s.position, pv) <= 10 * eps_) {
      // The face's source sits on v: v is the real source (sigma 0), or the path turned here
      // and this face does not lead further.
      if (s.sigma <= eps_) {
        out_.source = s.source;
        return VertexStep::source;
      }
      at_v = f;
      continue;
    }
    const double d = own_value(f, pv);
    Bary bs;
    bary_of(f, s.position, bs);
    const Index i = corner_of(c), j = (i + 1) % 3, l = (i + 2) % 3;
    const bool enters = bs[j] >= -kBaryTol && bs[l] >= -kBaryTol;
    if (d < best_any) best_any = d, best_any_corner = c;
    if (enters && d < best) best = d, best_corner = c;
  }
  // A carried source clearly shorter than any face's own: go on with it.
  const double carried = w.face != kInvalidIndex && w.sigma < kInf ? w.value() : kInf;
  const double tol = 1e-6 * carried + 10 * eps_;
  if (best_corner != kInvalidIndex && best > carried + tol) best_corner = kInvalidIndex;
  if (best_corner == kInvalidIndex && best_any <= carried + tol) best_corner = best_any_corner, best = best_any;
  if (best_corner == kInvalidIndex) {
    if (carried < kInf) return VertexStep::keep;
    // Every reached face has its source on v: a vertex source with an initial offset.
    if (at_v != kInvalidIndex) {
      out_.source = field_.face_sources[at_v].source;
      return VertexStep::source;
    }
    return VertexStep::stuck;
  }
  w.face = face_of(best_corner);
  w.bary = {0, 0, 0};
  w.bary[corner_of(best_corner)] = 1;
  w.position = pv;
  w.entry = kInvalidIndex;
  adopt_own(w);
  return VertexStep::moved;
}

// Crosses halfedge h of `from` at its point bq into the neighbour that continues the path best
// (at a non-manifold edge: the smallest own distance at the crossing), carrying from's target
// over, unfolded about the edge into the neighbour's plane.
bool Walk::cross(const Walker& from, Index h, const Bary& bq, Walker& to) const {
  const Index a = from_vertex(mesh_, h), b = to_vertex(mesh_, h);
  const double wa = bq[corner_of(h)], wb = bq[corner_of(next_halfedge(h))];
  const double s = wa + wb > 0 ? wb / (wa + wb) : 0.5;   // q = (1 - s) a + s b
  const Vec3 q = from.position;
  double best = kInf;
  Index pick = kInvalidIndex;
  for (Index g = conn_.radial_next[h]; g != h; g = conn_.radial_next[g]) {
    const Index f = face_of(g);
    if (f == from.face || !usable(f)) continue;
    const double d = own_value(f, q);
    if (pick == kInvalidIndex || d < best) best = d, pick = g;
  }
  if (pick == kInvalidIndex) return false;
  const Index f = face_of(pick);
  to = from;
  to.face = f;
  to.bary = {0, 0, 0};
  const bool same = from_vertex(mesh_, pick) == a;   // the neighbour may walk the edge either way
  to.bary[corner_of(pick)] = same ? 1 - s : s;
  to.bary[corner_of(next_halfedge(pick))] = same ? s : 1 - s;
  to.entry = pick;
  // Unfold: edge frame (x along a -> b, y towards each face's third corner); the target lies on
  // the far side of the edge seen from `from`, i.e. on the neighbour's side.
  const Vec3 pa = mesh_.positions[a], pb = mesh_.positions[b];
  const double len = distance(pa, pb);
  const Vec3 c_from = mesh_.positions[mesh_.triangles[from.face][corner_of(prev_halfedge(h))]];
  const Vec3 c_to = mesh_.positions[mesh_.triangles[f][corner_of(prev_halfedge(pick))]];
  if (!(len > 0)) {
    adopt_own(to);
    return true;
  }
  const Vec3 ex = (1.0 / len) * (pb - pa);
  auto normal_dir = [&](Vec3 c) {
    const Vec3 y = (c - pa) - dot(c - pa, ex) * ex;
    const double n = norm(y);
    return n > 0 ? (1.0 / n) * y : Vec3{};
  };
  const Vec3 yf = normal_dir(c_from), yt = normal_dir(c_to);
  const double x = dot(from.target - pa, ex), y = dot(from.target - pa, yf);
  to.target = pa + x * ex - y * yt;
  to.own = false;
  return true;
}

GeodesicPath Walk::run(const Endpoint& end) {
  Walker w;
  bool at_source = false;
  auto step_vertex = [&](Index v) {
    const VertexStep r = at_vertex(v, w);
    if (r == VertexStep::stuck) throw NoPath("vertex " + std::to_string(v) + " is not reached by the field");
    if (r == VertexStep::source) {
      at_source = true;
      w.position = mesh_.positions[v];
    }
    return r;
  };

  // The start: a vertex picks its face; a point in a degenerate face starts from its nearest
  // corner (the face has no plane to walk in).
  if (end.is_vertex()) {
    w.position = mesh_.positions[end.vertex];
    if (step_vertex(end.vertex) == VertexStep::source) {
      // Zero-length path: the end point is the source.
      const Index c = conn_.vertex_corners[conn_.vertex_corner_begin[end.vertex]];
      w.face = face_of(c);
      w.bary = {0, 0, 0};
      w.bary[corner_of(c)] = 1;
    }
  } else {
    w.face = end.face;
    w.bary = end.barycentric;
    w.position = point(end.face, end.barycentric);
    if (!reached(end.face)) throw NoPath("face " + std::to_string(end.face) + " is not reached by the field");
    adopt_own(w);
    Bary unused;
    if (!bary_of(end.face, w.position, unused)) {
      const Index corner = Index(std::max_element(w.bary.begin(), w.bary.end()) - w.bary.begin());
      emit(w);
      w.face = kInvalidIndex;
      step_vertex(mesh_.triangles[end.face][corner]);
    }
  }
  out_.field_distance = end.is_vertex() ? field_.vertex_distance.size() > end.vertex
                                              ? field_.vertex_distance[end.vertex]
                                              : kInf
                                        : field_.distance_at(mesh_, end.face, end.barycentric);
  emit(w);

  for (std::size_t steps = 0; !at_source; ++steps) {
    if (steps >= max_steps_)
      throw Error("path tracing gave up after " + std::to_string(max_steps_) +
                  " steps without reaching the source (inconsistent field?)");
    // The face's own source, when it is no longer and leads on: it knows where the geodesic
    // really turns; a carried one only knows the unfolding it came through.
    if (!w.own) {
      const double carried = w.value();
      if (own_value(w.face, w.position) <= carried * (1 + 1e-6) + 10 * eps_ && own_enters(w)) adopt_own(w);
    }
    double t_exit;
    int exit_corner;
    Bary bs;
    if (!exit_of(w, t_exit, exit_corner, bs)) throw Error("path tracing entered degenerate face " + std::to_string(w.face));
    Bary bq;
    for (int i = 0; i < 3; ++i) bq[i] = std::max(0.0, w.bary[i] + t_exit * (bs[i] - w.bary[i]));
    const double sum = bq[0] + bq[1] + bq[2];
    for (double& x : bq) x /= sum;
    const int top = int(std::max_element(bq.begin(), bq.end()) - bq.begin());
    Walker next = w;
    next.bary = bq;
    next.position = point(w.face, bq);
    if (exit_corner < 0 && w.own && (w.sigma <= eps_ || bq[top] < 1 - kCornerSnap) && !genuine_source(w)) {
      // The face's source lies inside the face only in an unfolding that overlaps itself (the
      // face was reached the long way round a curved part): no real source is here. Go on
      // from the face's corner nearest to the sources; the shortening straightens the detour.
      const Triangle& t = mesh_.triangles[w.face];
      int best = 0;
      for (int i = 1; i < 3; ++i)
        if (field_.vertex_distance[t[i]] < field_.vertex_distance[t[best]]) best = i;
      next.bary = {0, 0, 0};
      next.bary[best] = 1;
      next.position = mesh_.positions[t[best]];
      emit(next);
      w = next;
      w.sigma = kInf;
      step_vertex(t[best]);
      continue;
    }
    if (exit_corner < 0) {
      // Reached the target inside (or on the border of) the face.
      next.position = w.target;
      next.entry = kInvalidIndex;
      emit(next);
      // A source with sigma > 0 next to a corner is that corner (a turn of the geodesic): the
      // float-stored source misses the vertex by about 1e-5 of an edge on fine meshes.
      const bool at_corner = bq[top] >= 1 - kCornerSnap;
      if (w.own && (w.sigma <= eps_ || !at_corner)) {
        out_.source = w.label;   // the real source (a vertex, or a face point)
        break;
      }
      if (w.own && at_corner) {   // a corner of the geodesic
        next.position = point(w.face, next.bary = Bary{0, 0, 0});
        next.bary[top] = 1;
        next.position = mesh_.positions[mesh_.triangles[w.face][top]];
        w = next;
        w.sigma = kInf;   // nothing carried beyond a corner
        step_vertex(mesh_.triangles[w.face][top]);
        continue;
      }
      // A carried target that is no vertex: the unfolding it came through was not the one the
      // field used; go on with the face's own source.
      w = next;
      adopt_own(w);
      continue;
    }
    emit(next);
    if (bq[top] >= 1 - kVertexTol && t_exit > 1e-9) {   // arrived at a corner
      w = next;
      if (step_vertex(mesh_.triangles[w.face][top]) != VertexStep::keep) continue;
      // Carry on through the vertex with the carried source: below, the walk leaves the face
      // at t = 0 through an edge at the vertex and rotates round it.
      continue;
    }
    const Index h = 3 * w.face + Index((exit_corner + 1) % 3);   // the edge opposite the corner
    Walker crossed;
    if (!cross(next, h, bq, crossed)) {
      // Off the boundary: only rounding can do that, next to a corner; go on from there.
      const Index ca = corner_of(h), cb = corner_of(next_halfedge(h));
      if (std::min(bq[ca], bq[cb]) > 1e-3)
        throw Error("path tracing ran off the mesh boundary at face " + std::to_string(w.face));
      w = next;
      w.sigma = kInf;
      step_vertex(mesh_.triangles[w.face][bq[ca] > bq[cb] ? ca : cb]);
      continue;
    }
    w = crossed;
  }
  // Pull the walk taut: the funnel in the sleeve of faces it crossed, bends the geodesic does
  // not need undone (sleeve.hpp); the older in-place relaxation where no sleeve can be formed.
  std::vector<PathPoint> taut;
  std::vector<Index> segment_faces;   // walk order: each point's face holds the segment to it
  for (std::size_t k = out_.points.size(); k-- > 1;) segment_faces.push_back(out_.points[k].face);
  const PathPoint first = out_.points.back(), last = out_.points.front();
  if (detail::shorten_in_sleeve(mesh_, conn_, first, last, segment_faces, taut)) {
    out_.points.swap(taut);
    // The route down the field's vertex distances, pulled taut too: keep the shorter.
    std::vector<PathPoint> other;
    const std::vector<Index> faces = detail::descent_faces(mesh_, conn_, field_.vertex_distance, first, last);
    if (!faces.empty() && detail::shorten_in_sleeve(mesh_, conn_, first, last, faces, other) &&
        polyline_length(other) < polyline_length(out_.points))
      out_.points.swap(other);
  } else {
    pull_taut();
    std::reverse(out_.points.begin(), out_.points.end());
  }
  out_.length = polyline_length(out_.points);
  return out_;
}

// The walk follows approximate virtual sources, so it can zig-zag a little. Pull it taut
// within the faces it runs through: every point where the path crosses an edge between two
// faces slides along that edge to the spot where the two segments unfold into a straight line
// (clamped to the edge), sweeping until nothing moves; points at vertices stay.
void Walk::pull_taut() {
  drop_face_bends();
  shorten();
  for (int round = 0; round < 64 && unpin_vertices(); ++round) {
    drop_face_bends();
    shorten();
  }
}

// A point strictly inside a face where the path bends (the walk switched from a carried source
// to the face's own there) is never part of a geodesic: the segments before and after it lie in
// the same face, so the straight segment between their other ends does too. Points at vertices
// stay (they may be true corners; unpin_vertices decides).
void Walk::drop_face_bends() {
  std::vector<PathPoint>& pts = out_.points;
  if (pts.size() < 3) return;
  std::vector<PathPoint> kept;
  kept.reserve(pts.size());
  kept.push_back(pts.front());
  for (std::size_t k = 1; k + 1 < pts.size(); ++k) {
    const bool same_face = pts[k].face == pts[k + 1].face;
    bool at_vertex = false;
    for (Index v : mesh_.triangles[pts[k].face])
      at_vertex |= distance(mesh_.positions[v], pts[k].position) <= 10 * eps_;
    if (same_face && !at_vertex) continue;
    kept.push_back(pts[k]);
  }
  kept.push_back(pts.back());
  pts.swap(kept);
}

// A path point at a vertex v that the path wraps round by less than pi on one side is no true
// corner (a geodesic bends only where it must, at vertices with more than pi on both sides):
// replace it by points on the edges of that side's fan, for shorten() to pull straight.
bool Walk::unpin_vertices() {
  std::vector<PathPoint>& pts = out_.points;
  bool changed = false;
  std::vector<PathPoint> result;
  result.reserve(pts.size());
  auto angle = [](Vec3 a, Vec3 b) { return std::atan2(norm(gsp::cross(a, b)), dot(a, b)); };
  for (std::size_t k = 0; k < pts.size(); ++k) {
    result.push_back(pts[k]);
    if (k == 0 || k + 1 == pts.size()) continue;
    const Index fin = pts[k].face, fout = pts[k + 1].face;
    Index v = kInvalidIndex;
    for (Index c = 0; c < 3; ++c)
      if (distance(mesh_.positions[mesh_.triangles[fin][c]], pts[k].position) <= 10 * eps_) v = mesh_.triangles[fin][c];
    if (v == kInvalidIndex || fin == fout) continue;
    const Vec3 pv = mesh_.positions[v];
    const Vec3 to_prev = pts[k - 1].position - pv, to_next = pts[k + 1].position - pv;
    if (!(norm(to_prev) > eps_) || !(norm(to_next) > eps_)) continue;
    // Both ways round v from fin to fout, over manifold edges only.
    for (int dir = 0; dir < 2; ++dir) {
      std::vector<std::pair<Index, Index>> crossings;   // (other end u of the edge, face after it)
      Index f = fin;
      Index corner = 0;
      while (mesh_.triangles[f][corner] != v) ++corner;
      // The edge through v to leave f by: v -> next corner (dir 0) or prev corner -> v (dir 1).
      Index h = dir == 0 ? 3 * f + corner : prev_halfedge(3 * f + corner);
      double total = 0;
      Vec3 from = to_prev;
      bool ok = false;
      for (std::size_t guard = 0; guard < 64; ++guard) {
        const Index u = from_vertex(mesh_, h) == v ? to_vertex(mesh_, h) : from_vertex(mesh_, h);
        const Vec3 edge = mesh_.positions[u] - pv;
        total += angle(from, edge);
        const Index g = conn_.radial_next[h];
        if (g == h || conn_.radial_next[g] != h || !usable(face_of(g))) break;
        const Index fg = face_of(g);
        crossings.push_back({u, fg});
        from = edge;
        if (fg == fout) {
          total += angle(from, to_next);
          ok = true;
          break;
        }
        // Leave fg by its other edge through v.
        const Index gv = from_vertex(mesh_, g) == v ? g : next_halfedge(g);
        h = gv == g ? prev_halfedge(g) : next_halfedge(g);
        if (from_vertex(mesh_, h) != v && to_vertex(mesh_, h) != v) break;
      }
      if (!ok || !(total < M_PI - 1e-6)) continue;
      result.pop_back();
      for (auto [u, fg] : crossings) {
        PathPoint q;
        q.face = fg == crossings.front().second ? fin : fg;
        q.position = pv + 0.5 * (mesh_.positions[u] - pv);
        result.push_back(q);
      }
      // Each inserted point's face is the one its incoming segment lies in.
      for (std::size_t j = 0; j < crossings.size(); ++j)
        result[result.size() - crossings.size() + j].face = j == 0 ? fin : crossings[j - 1].second;
      changed = true;
      break;
    }
  }
  if (changed) {
    for (PathPoint& q : result) {
      Bary b;
      if (bary_of(q.face, q.position, b)) q.barycentric = b;
    }
    pts.swap(result);
  }
  return changed;
}

void Walk::shorten() {
  std::vector<PathPoint>& pts = out_.points;
  const std::size_t n = pts.size();
  if (n < 3) return;
  struct Slide {
    std::size_t k;
    Index in, out, a, b;
  };
  std::vector<Slide> slides;
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const Index fin = pts[k].face, fout = pts[k + 1].face;
    if (fin == fout) continue;
    const Triangle& ti = mesh_.triangles[fin];
    const Triangle& to = mesh_.triangles[fout];
    Index shared[3], m = 0;
    for (Index v : ti)
      if ((v == to[0] || v == to[1] || v == to[2]) && m < 3) shared[m++] = v;
    if (m != 2) continue;
    const Vec3 pa = mesh_.positions[shared[0]], pb = mesh_.positions[shared[1]];
    const double len = distance(pa, pb);
    if (!(len > 0)) continue;
    const double along = dot(pts[k].position - pa, (1.0 / len) * (pb - pa));
    if (along <= 10 * eps_ || along >= len - 10 * eps_) continue;   // at a vertex: pinned
    slides.push_back({k, fin, fout, shared[0], shared[1]});
  }
  auto third = [&](Index f, Index a, Index b) {
    for (Index v : mesh_.triangles[f])
      if (v != a && v != b) return mesh_.positions[v];
    return mesh_.positions[a];
  };
  // First, per run of consecutive sliding points between two fixed ones: unfold the faces they
  // cross into one plane and put each point where the straight line crosses its edge (the
  // exact answer when the line stays inside the strip; clamped otherwise, then polished below).
  using P2 = std::array<double, 2>;
  auto cross2 = [](P2 a, P2 b) { return a[0] * b[1] - a[1] * b[0]; };
  for (std::size_t r0 = 0; r0 < slides.size();) {
    std::size_t r1 = r0;
    while (r1 + 1 < slides.size() && slides[r1 + 1].k == slides[r1].k + 1 && slides[r1 + 1].in == slides[r1].out) ++r1;
    // 2D positions of the current face's corners, face by face along the strip.
    std::vector<std::pair<P2, P2>> edges2;   // per slide: its edge (a, b) in the plane
    const Slide& first = slides[r0];
    const Vec3 pa = mesh_.positions[first.a], pb = mesh_.positions[first.b];
    const double len0 = distance(pa, pb);
    const Vec3 ex = (1.0 / len0) * (pb - pa);
    auto local = [&](Vec3 x, Vec3 origin, Vec3 ux, Vec3 uy) { return P2{dot(x - origin, ux), dot(x - origin, uy)}; };
    const Vec3 cin = third(first.in, first.a, first.b);
    Vec3 yin = (cin - pa) - dot(cin - pa, ex) * ex;
    yin = (1.0 / std::max(norm(yin), 1e-300)) * yin;
    // The corners of the face being unfolded, 3D index -> 2D.
    Index fv[3] = {first.a, first.b, kInvalidIndex};
    P2 f2[3] = {P2{0, 0}, P2{len0, 0}, local(cin, pa, ex, yin)};
    for (Index v : mesh_.triangles[first.in])
      if (v != first.a && v != first.b) fv[2] = v;
    Bary b0;
    const std::size_t k0 = first.k - 1;
    bool ok = bary_of(first.in, pts[k0].position, b0);
    P2 start{0, 0};
    if (ok) {
      const Triangle& t = mesh_.triangles[first.in];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (t[i] == fv[j]) start[0] += b0[i] * f2[j][0], start[1] += b0[i] * f2[j][1];
    }
    P2 end{0, 0};
    for (std::size_t r = r0; ok && r <= r1; ++r) {
      const Slide& sl = slides[r];
      P2 a2{}, b2{}, cprev{};
      for (int j = 0; j < 3; ++j) {
        if (fv[j] == sl.a) a2 = f2[j];
        else if (fv[j] == sl.b) b2 = f2[j];
        else cprev = f2[j];
      }
      edges2.push_back({a2, b2});
      // Unfold the next face across (a, b), away from the previous face's third corner.
      const Vec3 A = mesh_.positions[sl.a], B = mesh_.positions[sl.b], C = third(sl.out, sl.a, sl.b);
      const double l = distance(A, B);
      const Vec3 u = (1.0 / l) * (B - A);
      const double along = dot(C - A, u), height = norm((C - A) - along * u);
      const P2 u2{(b2[0] - a2[0]) / l, (b2[1] - a2[1]) / l};
      P2 n2{-u2[1], u2[0]};
      if (cross2(u2, P2{cprev[0] - a2[0], cprev[1] - a2[1]}) > 0) n2 = P2{u2[1], -u2[0]};
      Index cv = kInvalidIndex;
      for (Index v : mesh_.triangles[sl.out])
        if (v != sl.a && v != sl.b) cv = v;
      fv[0] = sl.a, fv[1] = sl.b, fv[2] = cv;
      f2[0] = a2, f2[1] = b2, f2[2] = P2{a2[0] + along * u2[0] + height * n2[0], a2[1] + along * u2[1] + height * n2[1]};
    }
    Bary b1;
    const Slide& last = slides[r1];
    ok = ok && bary_of(last.out, pts[last.k + 1].position, b1);
    if (ok) {
      const Triangle& t = mesh_.triangles[last.out];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (t[i] == fv[j]) end[0] += b1[i] * f2[j][0], end[1] += b1[i] * f2[j][1];
      const P2 d{end[0] - start[0], end[1] - start[1]};
      for (std::size_t r = r0; r <= r1; ++r) {
        const auto& [a2, b2] = edges2[r - r0];
        const P2 e{b2[0] - a2[0], b2[1] - a2[1]};
        const double den = cross2(e, d);
        if (!(std::abs(den) > 0)) continue;
        const double s_edge = std::min(1.0, std::max(0.0, cross2(P2{start[0] - a2[0], start[1] - a2[1]}, d) / den));
        const Slide& sl = slides[r];
        pts[sl.k].position = mesh_.positions[sl.a] + s_edge * (mesh_.positions[sl.b] - mesh_.positions[sl.a]);
      }
    }
    r0 = r1 + 1;
  }
  for (int sweep = 0; sweep < 2000 && !slides.empty(); ++sweep) {
    double moved = 0;
    for (const Slide& sl : slides) {
      const Vec3 pa = mesh_.positions[sl.a], pb = mesh_.positions[sl.b];
      const double len = distance(pa, pb);
      const Vec3 ex = (1.0 / len) * (pb - pa);
      auto normal_dir = [&](Vec3 c) {
        const Vec3 y = (c - pa) - dot(c - pa, ex) * ex;
        const double l = norm(y);
        return l > 0 ? (1.0 / l) * y : Vec3{};
      };
      const Vec3 yi = normal_dir(third(sl.in, sl.a, sl.b)), yo = normal_dir(third(sl.out, sl.a, sl.b));
      const Vec3 prev = pts[sl.k - 1].position, next = pts[sl.k + 1].position;
      const double xp = dot(prev - pa, ex), yp = std::max(0.0, dot(prev - pa, yi));
      const double xn = dot(next - pa, ex), yn = std::max(0.0, dot(next - pa, yo));
      const double x = yp + yn > 0 ? xp + (xn - xp) * yp / (yp + yn) : 0.5 * (xp + xn);
      const double c = std::min(len, std::max(0.0, x));
      const Vec3 q = pa + c * ex;
      moved = std::max(moved, distance(q, pts[sl.k].position));
      pts[sl.k].position = q;
    }
    if (moved <= 1e-3 * eps_) break;
  }
  for (const Slide& sl : slides) {
    Bary b;
    if (bary_of(pts[sl.k].face, pts[sl.k].position, b)) {
      for (double& x : b) x = std::max(0.0, x);
      const double sum = b[0] + b[1] + b[2];
      for (double& x : b) x /= sum;
      pts[sl.k].barycentric = b;
      pts[sl.k].position = point(pts[sl.k].face, b);
    }
  }
}

double mean_edge_length(const TriangleMesh& mesh) {
  double sum = 0;
  std::size_t n = 0;
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) sum += distance(mesh.positions[t[i]], mesh.positions[t[(i + 1) % 3]]), ++n;
  return n && sum > 0 ? sum / double(n) : 1.0;
}

}  // namespace

PathTracer::PathTracer(const TriangleMesh& mesh, const TraceOptions& options)
    : mesh_(mesh), conn_(build_connectivity(mesh)), options_(options), mean_edge_(mean_edge_length(mesh)) {}

GeodesicPath PathTracer::trace(const GeodesicResult& field, const Endpoint& end) const {
  if (field.face_sources.size() != mesh_.num_faces())
    throw InvalidInput("path tracing needs a field computed with want_face_sources on this mesh");
  endpoint_position(mesh_, end);   // validates
  const std::size_t max_steps = options_.max_steps ? options_.max_steps : 2 * mesh_.num_faces() + 64;
  try {
    return Walk(mesh_, conn_, field, mean_edge_, max_steps).run(end);
  } catch (const NoPath&) {
    throw;
  } catch (const Error&) {
    // The walk could not be completed (a cycle in an inconsistent field, a step off the
    // boundary): the route down the field's vertex distances, pulled taut, is the path.
    PathPoint last;
    last.position = endpoint_position(mesh_, end);
    if (end.is_vertex()) {
      const Index c = conn_.vertex_corners[conn_.vertex_corner_begin[end.vertex]];
      last.face = face_of(c);
      last.barycentric = {0, 0, 0};
      last.barycentric[corner_of(c)] = 1;
    } else {
      last.face = end.face, last.barycentric = end.barycentric;
    }
    GeodesicPath path;
    if (!detail::descent_path(mesh_, conn_, field, last, path)) throw;
    path.field_distance = end.is_vertex() ? field.vertex_distance[end.vertex] : field.distance_at(mesh_, end.face, end.barycentric);
    return path;
  }
}

std::vector<GeodesicPath> PathTracer::trace_all(const GeodesicResult& field, const std::vector<Endpoint>& ends) const {
  std::vector<GeodesicPath> paths;
  paths.reserve(ends.size());
  for (const Endpoint& e : ends) {
    try {
      paths.push_back(trace(field, e));
    } catch (const NoPath&) {
      paths.emplace_back();
    }
  }
  return paths;
}

}  // namespace gsp::pathfinding
