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
       std::size_t max_steps, bool shorten)
      : mesh_(mesh), conn_(conn), field_(field), eps_(1e-7 * mean_edge), max_steps_(max_steps), shorten_(shorten) {}

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
    if (!(denom > 1e-12 * d00 * d11) || repeats_vertex(t)) return false;
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
  enum class VertexStep { moved, source, keep, stuck };
  VertexStep at_vertex(Index v, Walker& w);
  bool cross(const Walker& from, Index h, const Bary& bq, Walker& to) const;

  const TriangleMesh& mesh_;
  const Connectivity& conn_;
  const GeodesicResult& field_;
  double eps_;
  std::size_t max_steps_;
  bool shorten_;
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
  if (shorten_ && detail::shorten_in_sleeve(mesh_, conn_, first, last, segment_faces, taut)) {
    std::vector<PathPoint> walk(out_.points.rbegin(), out_.points.rend());
    out_.points.swap(taut);
    // The route down the field's vertex distances, pulled taut too: keep the shorter.
    std::vector<PathPoint> other;
    const std::vector<Index> faces = detail::descent_faces(mesh_, conn_, field_.vertex_distance, first, last);
    if (!faces.empty() && detail::shorten_in_sleeve(mesh_, conn_, first, last, faces, other) &&
        polyline_length(other) < polyline_length(out_.points))
      out_.points.swap(other);
    // The walk itself where both came out longer: a sleeve through needle faces (aspect ratio
    // in the thousands) can unfold on the wrong side of an edge; measured once in 96 pairs on
    // falcon (taut 0.55% over exact, the walk 0.27%).
    if (polyline_length(walk) < polyline_length(out_.points)) out_.points.swap(walk);
  } else {
    // Not shortened, or no sleeve (the walk passes a vertex whose fan has a non-manifold edge
    // or a boundary between the two faces): the walk as it is, in source-to-end order (consecutive points
    // still share a face; each point's barycentrics are in its own face).
    std::reverse(out_.points.begin(), out_.points.end());
  }
  out_.length = polyline_length(out_.points);
  return out_;
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
    return Walk(mesh_, conn_, field, mean_edge_, max_steps, options_.shorten).run(end);
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
    if (!options_.shorten || !detail::descent_path(mesh_, conn_, field, last, path)) throw;
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
