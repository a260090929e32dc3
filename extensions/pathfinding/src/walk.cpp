// The walk's course: from the end point, one straight stretch after another, to the source;
// then pulled taut (walk.hpp).
#include "walk.hpp"

#include "descent_faces.hpp"
#include "sleeve.hpp"

#include <algorithm>
#include <string>

namespace gsp::pathfinding::detail {

namespace {

// Where a straight stretch from barycentric `from` towards `to` stops at t: clamped onto the
// face and renormalised, so the point is exactly on the face's border.
Bary point_along(const Bary& from, double t, const Bary& to) {
  Bary bq;
  for (int i = 0; i < 3; ++i) bq[i] = std::max(0.0, from[i] + t * (to[i] - from[i]));
  const double sum = bq[0] + bq[1] + bq[2];
  for (double& x : bq) x /= sum;
  return bq;
}

}  // namespace

GeodesicPath Walk::run(const Endpoint& end) {
  Walker w = start(end);
  out_.field_distance = end_distance(end);
  emit(w);
  for (std::size_t steps = 0; !at_source_; ++steps) {
    if (steps >= max_steps_)
      throw Error("path tracing gave up after " + std::to_string(max_steps_) +
                  " steps without reaching the source (inconsistent field?)");
    step(w);
  }
  pull_taut();
  out_.length = polyline_length(out_.points);
  return out_;
}

// The walk must begin in a face with a plane: a vertex picks its face; a point in a degenerate
// face starts from its nearest corner (the face has no plane to walk in).
Walker Walk::start(const Endpoint& end) {
  Walker w;
  if (end.is_vertex()) {
    w.position = mesh_.positions[end.element];
    if (step_vertex(end.element, w) == VertexStep::source) {
      // Zero-length path: the end point is the source.
      const Index c = conn_.vertex_corners[conn_.vertex_corner_begin[end.element]];
      w.face = face_of(c);
      w.bary = corner_bary(corner_of(c));
    }
    return w;
  }
  w.face = end.element;
  w.bary = end.barycentric;
  w.position = end.position(mesh_);
  if (!reached(w.face)) throw NoPath("face " + std::to_string(w.face) + " is not reached by the field");
  adopt_own(w);
  Bary unused;
  if (!bary_of(end.element, w.position, unused)) {
    const Index corner = Index(std::max_element(w.bary.begin(), w.bary.end()) - w.bary.begin());
    emit(w);
    w.face = kInvalidIndex;
    if (step_vertex(mesh_.triangles[end.element][corner], w) == VertexStep::source) {
      // That corner is the source (an unwelded copy of it, as at a capsule's pole): the walk
      // ends at the corner, a point of the end's own face (a walker without a face crashed the
      // shortening and would have written face 4294967295).
      w.face = end.element;
      w.bary = corner_bary(corner);
    }
  }
  return w;
}

// The field's own distance at the end, reported beside the path's length to measure it by.
double Walk::end_distance(const Endpoint& end) const {
  if (!end.is_vertex()) return field_.distance_at(mesh_, end.element, end.barycentric);
  const std::vector<double>& d = field_.vertex_distance();
  return d.size() > end.element ? d[end.element] : kInf;
}

// Every arrival at a vertex ends the walk there when v is the source, and fails the trace when
// the field never reached v.
Walk::VertexStep Walk::step_vertex(Index v, Walker& w) {
  const VertexStep r = at_vertex(v, w);
  if (r == VertexStep::stuck) throw NoPath("vertex " + std::to_string(v) + " is not reached by the field");
  if (r == VertexStep::source) {
    at_source_ = true;
    w.position = mesh_.positions[v];
    // The point's face and weights name v too: the walker may come from a face without area
    // that ends at v's line but not at v (a CAD part's T-junction), whose weights were of
    // another corner (the log cabin STL: the path's last point 33.6 units from its face point).
    const Triangle* t = w.face < mesh_.num_faces() ? &mesh_.triangles[w.face] : nullptr;
    const Index* corner = t ? std::find(t->begin(), t->end(), v) : nullptr;
    if (t && corner != t->end()) {
      w.bary = corner_bary(Index(corner - t->begin()));
    } else {
      const Index c = conn_.vertex_corners[conn_.vertex_corner_begin[v]];
      w.face = face_of(c);
      w.bary = corner_bary(corner_of(c));
    }
  }
  return r;
}

// The face's own source, when it is no longer and leads on: it knows where the geodesic
// really turns; a carried one only knows the unfolding it came through.
void Walk::prefer_own(Walker& w) const {
  const double carried = w.value();
  if (own_value(w.face, w.position) <= carried * (1 + 1e-6) + 10 * eps_ && own_enters(w)) adopt_own(w);
}

// The walk advances one straight stretch at a time: from w towards its target, to where it
// leaves the face (across an edge, or at a corner) or reaches the target.
void Walk::step(Walker& w) {
  if (!w.own) prefer_own(w);
  double t_exit;
  int exit_corner;
  Bary bs;
  if (!exit_of(w, t_exit, exit_corner, bs)) throw Error("path tracing entered degenerate face " + std::to_string(w.face));
  const Bary bq = point_along(w.bary, t_exit, bs);
  const int top = int(std::max_element(bq.begin(), bq.end()) - bq.begin());
  Walker next = w;
  next.bary = bq;
  next.position = SurfacePoint::in_face(w.face, bq).position(mesh_);
  if (exit_corner < 0) {
    reach_target(w, next, top);
    return;
  }
  emit(next);
  if (bq[top] >= 1 - kVertexTol && t_exit > 1e-9) {   // arrived at a corner
    w = next;
    // On `keep` the walk carries on through the vertex with the carried source: the next step
    // leaves the face at t = 0 through an edge at the vertex and rotates round it.
    step_vertex(mesh_.triangles[w.face][top], w);
    return;
  }
  leave_face(w, next, exit_corner);
}

// A target reached inside (or on the border of) the face is the source, a corner where the
// geodesic turns, or a carried target from an unfolding the field did not use.
void Walk::reach_target(Walker& w, Walker next, int top) {
  next.position = w.target;
  next.entry = kInvalidIndex;
  emit(next);
  // A source with sigma > 0 next to a corner is that corner (a turn of the geodesic): the
  // float-stored source misses the vertex by about 1e-5 of an edge on fine meshes.
  const bool at_corner = next.bary[top] >= 1 - kCornerSnap;
  if (w.own && w.sigma > eps_ && !at_corner) {
    // A turn at a vertex that lies on this face's edge without being its corner: a face without
    // area joins it there (a CAD part's T-junction). The walk goes on from that
    // vertex; before, it ended there as if at the source (a CAD wall: 3.6 of 12.3 units).
    const Index u = vertex_across(w.face, w.target);
    if (u != kInvalidIndex) {
      w = next;
      w.sigma = kInf;
      step_vertex(u, w);
      return;
    }
  }
  if (w.own && (w.sigma <= eps_ || !at_corner)) {
    out_.source = w.label;   // the real source (a vertex, or a face point)
    at_source_ = true;
    return;
  }
  if (w.own && at_corner) {   // a corner of the geodesic
    next.bary = corner_bary(top);
    next.position = mesh_.positions[mesh_.triangles[w.face][top]];
    w = next;
    w.sigma = kInf;   // nothing carried beyond a corner
    step_vertex(mesh_.triangles[w.face][top], w);
    return;
  }
  // A carried target that is no vertex: the unfolding it came through was not the one the
  // field used; go on with the face's own source.
  w = next;
  adopt_own(w);
}

// The vertex at x (within kCornerSnap of the face's longest edge) among the vertices of the
// faces at f's corners (a T-junction's vertex is the far corner of a face without area across
// one of f's edges, or of one beyond it in a chain of such faces along the edge);
// kInvalidIndex if none.
Index Walk::vertex_across(Index f, Vec3 x) const {
  const Triangle& t = mesh_.triangles[f];
  const double tol = kCornerSnap * std::max({distance(mesh_.positions[t[0]], mesh_.positions[t[1]]),
                                             distance(mesh_.positions[t[1]], mesh_.positions[t[2]]),
                                             distance(mesh_.positions[t[2]], mesh_.positions[t[0]])});
  for (const Index c : t)
    for (Index k = conn_.vertex_corner_begin[c]; k < conn_.vertex_corner_begin[c + 1]; ++k)
      for (const Index u : mesh_.triangles[face_of(conn_.vertex_corners[k])])
        if (u != t[0] && u != t[1] && u != t[2] && distance(mesh_.positions[u], x) <= tol) return u;
  return kInvalidIndex;
}

// The walk leaves w's face over the edge opposite exit_corner, at `next`: into the neighbour,
// or, off the boundary, into the nearer corner of that edge.
void Walk::leave_face(Walker& w, const Walker& next, int exit_corner) {
  const Index h = 3 * w.face + Index((exit_corner + 1) % 3);   // the edge opposite the corner
  const Bary bq = next.bary;
  Walker crossed;
  if (cross(next, h, bq, crossed)) {
    w = crossed;
    return;
  }
  // Off the boundary: only rounding can do that, next to a corner; go on from there.
  const Index ca = corner_of(h), cb = corner_of(next_halfedge(h));
  if (std::min(bq[ca], bq[cb]) > 1e-3)
    throw Error("path tracing ran off the mesh boundary at face " + std::to_string(w.face));
  w = next;
  w.sigma = kInf;
  step_vertex(mesh_.triangles[w.face][bq[ca] > bq[cb] ? ca : cb], w);
}

// Pull the walk taut: the funnel in the sleeve of faces it crossed, bends the geodesic does
// not need undone (sleeve.hpp); the older in-place relaxation where no sleeve can be formed.
void Walk::pull_taut() {
  std::vector<PathPoint> taut;
  std::vector<Index> segment_faces;   // walk order: each point's face holds the segment to it
  for (std::size_t k = out_.points.size(); k-- > 1;) segment_faces.push_back(out_.points[k].point.element);
  const PathPoint first = out_.points.back(), last = out_.points.front();
  if (shorten_ && shorten_in_sleeve(mesh_, conn_, first, last, segment_faces, taut)) {
    keep_shortest(taut, first, last);
    return;
  }
  // Not shortened, or no sleeve (the walk passes a vertex whose fan has a non-manifold edge
  // or a boundary between the two faces): the walk as it is, in source-to-end order (consecutive points
  // still share a face; each point's barycentrics are in its own face).
  out_.points = reversed_path(mesh_, out_.points);
}

// A taut path cannot change sides of a feature: of the taut walk, the taut descent route and
// the walk itself (source-to-end order), the shortest is the path.
void Walk::keep_shortest(std::vector<PathPoint>& taut, const PathPoint& first, const PathPoint& last) {
  std::vector<PathPoint> walk = reversed_path(mesh_, out_.points);
  out_.points.swap(taut);
  // The route down the field's vertex distances, pulled taut too: keep the shorter.
  std::vector<PathPoint> other;
  const std::vector<Index> faces = descent_faces(mesh_, conn_, field_.vertex_distance(), first, last);
  if (!faces.empty() && shorten_in_sleeve(mesh_, conn_, first, last, faces, other) &&
      polyline_length(other) < polyline_length(out_.points))
    out_.points.swap(other);
  // The walk itself where both came out longer: a sleeve through needle faces (aspect ratio
  // in the thousands) can unfold on the wrong side of an edge (docs/pathfinding.md, "How a
  // path is made", step 4).
  if (polyline_length(walk) < polyline_length(out_.points)) out_.points.swap(walk);
}

}  // namespace gsp::pathfinding::detail
