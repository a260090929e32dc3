#include <gsp/pathfinding/shortest_path.hpp>

#include <gsp/closest_point.hpp>

#include "source_field.hpp"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <exception>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace gsp::pathfinding {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kInf = std::numeric_limits<double>::infinity();
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The vertices a propagation must settle for paths to `to`: vertices as they are; a point
// inside a face is settled once its face's corners are.
std::vector<Index> target_vertices(const TriangleMesh& mesh, const std::vector<Endpoint>& to) {
  std::vector<Index> targets;
  for (const Endpoint& e : to) {
    check_endpoint(mesh, e);   // before indexing
    if (e.is_vertex()) {
      targets.push_back(e.element);
    } else {
      const Triangle& t = mesh.triangles[e.element];
      targets.insert(targets.end(), t.begin(), t.end());
    }
  }
  return targets;
}

// GSP's options for paths to `to`.
GeodesicOptions field_options(const TriangleMesh& mesh, const std::vector<Endpoint>& to, const PathQueryOptions& options) {
  GeodesicOptions go;
  go.want_face_sources = true;   // the walk back needs every face's virtual source
  go.precision = options.precision;
  if (options.method != PathMethod::full) {
    go.targets = target_vertices(mesh, to);
    go.goal_directed = options.method == PathMethod::astar && !go.targets.empty();
  }
  return go;
}

// The traced path starts where the walk found the source: the field's virtual source, stored
// in single precision by default (about 1e-7 of the model off). Puts it on the source itself.
void snap_start(const TriangleMesh& mesh, std::vector<PathPoint>& points, const Endpoint& source) {
  if (points.empty()) return;
  PathPoint& p = points.front();
  const Vec3 exact = source.position(mesh);
  const Triangle& t = mesh.triangles[p.point.element];
  const double scale = distance(mesh.positions[t[0]], mesh.positions[t[1]]) + distance(mesh.positions[t[1]], mesh.positions[t[2]]);
  if (!(distance(p.position, exact) <= 1e-4 * scale)) return;
  p.position = exact;
  p.point.barycentric = weights_in(mesh, p.point.element, exact);
}

// GSP's solver: the caller's, or built from the tracer's mesh the first time it is needed (a
// windows query needs one only for an end point the windows cannot reach).
class LazySolver {
 public:
  LazySolver(const GeodesicSolver* given, const PathTracer& tracer) : given_(given), tracer_(tracer) {}
  const GeodesicSolver& get() {
    if (given_) return *given_;
    if (!own_) own_ = std::make_unique<GeodesicSolver>(tracer_.mesh());
    return *own_;
  }
  const TriangleMesh& mesh() const { return tracer_.mesh(); }

 private:
  const GeodesicSolver* given_;
  const PathTracer& tracer_;
  std::unique_ptr<GeodesicSolver> own_;
};

// A propagation from one end point, GSP's or the windows', and the view the walk reads.
struct Field {
  GeodesicResult gsp;
  WindowField windows;
  std::unique_ptr<detail::SourceField> view;
  bool is_windows = false;
};

Field propagate(LazySolver& solver, const PathTracer& tracer, const Endpoint& from,
                const std::vector<Endpoint>& to, const PathQueryOptions& options, PropagationStats& stats) {
  const TriangleMesh& mesh = tracer.mesh();
  Field f;
  if (options.method != PathMethod::windows) {
    f.gsp = solver.get().compute({Source::at(from)}, field_options(mesh, to, options));
    stats = f.gsp.stats;
    f.view = std::make_unique<detail::GspSourceField>(f.gsp);
    return f;
  }
  WindowOptions wo;
  wo.windows = options.windows;
  // Neither the extra shadow windows nor the own-point test: they make fields more accurate but
  // put windows whose source is a vertex unfolded from far back in the faces, and the walk
  // then left the corridor (61 corpus meshes: worst path 0.037 -> 2.0%, one-ended up to 11%).
  wo.shadow_sources = false;
  wo.own_points = false;
  wo.targets = target_vertices(mesh, to);
  WindowStats ws;
  try {
    f.windows = tracer.windows().field({Source::at(from)}, wo, &ws);
  } catch (const std::invalid_argument& e) {
    throw InvalidInput(e.what());
  }
  stats = PropagationStats{};
  stats.faces_reached = ws.faces_reached;
  stats.face_updates = ws.window_updates;
  f.view = std::make_unique<detail::WindowSourceField>(f.windows);
  f.is_windows = true;
  return f;
}

GeodesicPath trace_in(const PathTracer& tracer, const Field& field, const Endpoint& end) {
  return field.is_windows ? tracer.trace(field.windows, end) : tracer.trace(field.gsp, end);
}

double field_at(const TriangleMesh& mesh, const Field& field, const Endpoint& e) {
  if (e.is_vertex()) return field.view->vertex_distance()[e.element];
  return field.view->distance_at(mesh, e.element, e.barycentric);
}

// A polyline on the surface from a to b: it starts and ends there and each segment lies in a
// face one of its two points names (both ends on that triangle, up to 1e-4 of its longest
// edge; path.hpp: consecutive points share a face).
bool on_face(const TriangleMesh& mesh, Index f, Vec3 q0, Vec3 q1, double tolerance) {
  if (f >= mesh.num_faces()) return false;
  const Triangle& t = mesh.triangles[f];
  const Vec3 p0 = mesh.positions[t[0]], p1 = mesh.positions[t[1]], p2 = mesh.positions[t[2]];
  const double slack = 1e-4 * std::max({distance(p0, p1), distance(p1, p2), distance(p2, p0)}) + tolerance;
  for (const Vec3 q : {q0, q1}) {
    const auto w = closest_point_on_triangle(q, p0, p1, p2);
    if (distance(q, w[0] * p0 + w[1] * p1 + w[2] * p2) > slack) return false;
  }
  return true;
}

bool on_surface(const TriangleMesh& mesh, const std::vector<PathPoint>& points, Vec3 a, Vec3 b, double tolerance) {
  if (points.empty()) return false;
  if (distance(points.front().position, a) > tolerance || distance(points.back().position, b) > tolerance) return false;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Vec3 q0 = points[i - 1].position, q1 = points[i].position;
    if (!on_face(mesh, points[i].point.element, q0, q1, tolerance) &&
        !on_face(mesh, points[i - 1].point.element, q0, q1, tolerance))
      return false;
  }
  return true;
}

void add_stats(PropagationStats& sum, const PropagationStats& s) {
  sum.update_steps += s.update_steps;
  sum.face_updates += s.face_updates;
  sum.enqueued += s.enqueued;
  sum.stale_skipped += s.stale_skipped;
  sum.postponed += s.postponed;
  sum.iterations += s.iterations;
  sum.faces_reached += s.faces_reached;
  sum.mean_edge_length = s.mean_edge_length;
}

// The paths that failed, are not on the surface, or are more than 1% longer than the field's
// distance at their end (which is never above the edge path: the vertex relaxation) are set
// against the path along the edges, which always exists where the end is reached: the shorter
// valid one is kept. A path that failed and has no edge path either rethrows its error.
void edge_safety_net(const TriangleMesh& mesh, const PathTracer& tracer, const Endpoint& from,
                     const std::vector<Endpoint>& to, const Field& field, std::vector<bool>& invalid,
                     std::vector<std::exception_ptr>& failed, PathQueryResult& r) {
  std::vector<std::size_t> suspect;
  for (std::size_t k = 0; k < to.size(); ++k) {
    const GeodesicPath& p = r.paths[k];
    const double d = field_at(mesh, field, to[k]);
    if (failed[k] || invalid[k] || (p.found() && std::isfinite(d) && !(p.length <= 1.01 * d))) suspect.push_back(k);
  }
  if (suspect.empty()) return;
  const auto t0 = Clock::now();
  std::vector<Endpoint> ends;
  for (std::size_t k : suspect) ends.push_back(to[k]);
  const PathQueryResult edges = edge_paths(mesh, tracer, from, ends);
  r.trace_seconds += seconds_since(t0);
  for (std::size_t i = 0; i < suspect.size(); ++i) {
    const std::size_t k = suspect[i];
    const GeodesicPath& e = edges.paths[i];
    GeodesicPath& p = r.paths[k];
    if (e.found() && (failed[k] || invalid[k] || e.length < p.length)) {
      const double field_distance = field_at(mesh, field, to[k]);
      p = e;
      p.field_distance = field_distance;
      failed[k] = nullptr;
      invalid[k] = false;
      ++r.edge_fallbacks;
    }
    if (failed[k]) std::rethrow_exception(failed[k]);
    if (invalid[k]) p = GeodesicPath{};   // no valid path: as unreachable (never a path off the surface)
  }
}

// The ends without a path so far: their places in `to`, and the end points.
std::pair<std::vector<std::size_t>, std::vector<Endpoint>> unreached(const std::vector<Endpoint>& to,
                                                                      const PathQueryResult& r) {
  std::pair<std::vector<std::size_t>, std::vector<Endpoint>> out;
  for (std::size_t k = 0; k < to.size(); ++k)
    if (!r.paths[k].found()) out.first.push_back(k), out.second.push_back(to[k]);
  return out;
}

// An end that no field reached may still be joined to `from` by edges whose faces have no
// area (a strip of collinear vertices; a mesh of nothing else): the path along the edges is
// on the surface too, so it is returned (counted as an edge fallback) rather than no path.
// gsp-geodesic gives such vertices their edge distances; before, gsp-path said "not
// connected" there.
void edge_paths_for_unreached(const TriangleMesh& mesh, const PathTracer& tracer, const Endpoint& from,
                              const std::vector<Endpoint>& to, PathQueryResult& r) {
  const auto [missing, ends] = unreached(to, r);
  if (missing.empty()) return;
  const auto t0 = Clock::now();
  const PathQueryResult edges = edge_paths(mesh, tracer, from, ends);
  r.trace_seconds += seconds_since(t0);
  for (std::size_t i = 0; i < missing.size(); ++i)
    if (edges.paths[i].found()) r.paths[missing[i]] = edges.paths[i], ++r.edge_fallbacks;
}

// One query as its steps share it: the inputs, the field from `from`, what the surface test
// needs, and per end the verdict so far. A walk that cannot be completed in this field (and
// whose descent fallback fails too) is kept as an error: the far end's field may still give
// the path.
struct Query {
  LazySolver& solver;
  const PathTracer& tracer;
  const TriangleMesh& mesh;
  const Endpoint& from;
  const std::vector<Endpoint>& to;
  const Field& field;
  double tolerance;
  Vec3 from_pos;
  std::vector<std::exception_ptr> failed;
  std::vector<bool> invalid;
};

// Every end's path walked back in the field from `from`: the first candidate, checked to lie
// on the surface.
void trace_forward(Query& q, PathQueryResult& r) {
  r.paths.resize(q.to.size());
  for (std::size_t k = 0; k < q.to.size(); ++k) {
    try {
      r.paths[k] = trace_in(q.tracer, q.field, q.to[k]);
      snap_start(q.mesh, r.paths[k].points, q.from);
      r.paths[k].length = polyline_length(r.paths[k].points);
      if (!on_surface(q.mesh, r.paths[k].points, q.from_pos, q.to[k].position(q.mesh), q.tolerance))
        q.invalid[k] = true;
    } catch (const NoPath&) {
      // unreachable: an empty path
    } catch (const Error&) {
      q.failed[k] = std::current_exception();
    }
  }
}

// The field grown from end k accumulates its errors from the other end, so near from's cut
// locus it may pick the shorter side: its path, walked back to `from`, replaces a failed,
// invalid or longer forward path.
void trace_back(Query& q, const PathQueryOptions& options, std::size_t k, PathQueryResult& r) {
  GeodesicPath& path = r.paths[k];
  if (!q.failed[k] && !q.invalid[k] && (!path.found() || !(path.length > 0))) return;
  auto t0 = Clock::now();
  PropagationStats back_stats;
  const Field back_field = propagate(q.solver, q.tracer, q.to[k], {q.from}, options, back_stats);
  r.compute_seconds += seconds_since(t0);
  add_stats(r.reverse_stats, back_stats);
  t0 = Clock::now();
  try {
    GeodesicPath back = trace_in(q.tracer, back_field, q.from);
    snap_start(q.mesh, back.points, q.to[k]);
    const bool back_valid =
        back.found() && on_surface(q.mesh, back.points, q.to[k].position(q.mesh), q.from_pos, q.tolerance);
    if (back_valid && (q.failed[k] || q.invalid[k] || polyline_length(back.points) < path.length)) {
      if (q.failed[k] || q.invalid[k]) path.field_distance = field_at(q.mesh, q.field, q.to[k]);
      path.points = reversed_path(q.mesh, back.points);
      path.length = polyline_length(path.points);
      path.source = 0;
      q.failed[k] = nullptr;
      q.invalid[k] = false;
      ++r.reversed;
    }
  } catch (const Error&) {
    // The walk back from `from` failed in this field: the forward path stands.
  }
  r.trace_seconds += seconds_since(t0);
}

// The windows method's paths set against GSP's A* paths to the same ends: every path kept is a
// polyline on the surface (each method's own checks and safety net), so the shorter of the two
// is the better answer wherever they differ. Why both: the windows that the walk follows (no
// shadow sources, see propagate()) can miss a shorter corridor that GSP's one source per face
// finds, as on a CAD log whose needles GSP unfolds right (the windows' path 1.7% longer than
// GSP's there); and the windows cross only edges with area on both sides, where GSP also
// crosses faces without area and joins vertices at one position (open seams, touching parts):
// an end the windows did not reach gets GSP's path (docs/pathfinding.md, "Needles, fins and
// T-junctions"). Cost: one A* query from `from`, plus GSP's preparation in a one-shot run.
// Tracing only where GSP's field is below the windows' path (by 0.1%) saved little (gsp-path's
// whole run, 10 ends, median over the corpus 1.11x -> 1.07x the run without the check) and lost
// every corpus improvement: GSP's taut path can be shorter than its own field.
PathQueryResult query(LazySolver& solver, const PathTracer& tracer, const Endpoint& from,
                      const std::vector<Endpoint>& to, const PathQueryOptions& options);

// GSP's distance field from `from` (what gsp-geodesic reports: intrinsic Delaunay faces, the
// vertex relaxation), bounded by the longest of the paths found, at each end: a vertex's
// value, or for a point in a face the shortest path through the face's corners. +inf where
// the solver refuses the mesh.
std::vector<double> full_field_at(LazySolver& solver, const Endpoint& from, const std::vector<Endpoint>& ends,
                                  const std::vector<GeodesicPath>& paths, const std::vector<std::size_t>& found,
                                  PathQueryResult& r) {
  std::vector<double> out(ends.size(), kInf);
  GeodesicOptions go;
  go.max_distance = 0;
  for (std::size_t k : found) go.max_distance = std::max(go.max_distance, paths[k].length);
  go.want_face_distances = false;
  const auto t0 = Clock::now();
  GeodesicResult field;
  try {
    field = solver.get().compute({Source::at(from)}, go);
  } catch (const Error&) {
    return out;
  }
  r.compute_seconds += seconds_since(t0);
  const TriangleMesh& mesh = solver.mesh();
  for (std::size_t i = 0; i < ends.size(); ++i)
    out[i] = ends[i].is_vertex() ? field.vertex_distance[ends[i].element]
                                 : corner_paths(mesh, ends[i].element, ends[i].position(mesh), field.vertex_distance);
  return out;
}

void shorter_astar_paths(LazySolver& solver, const PathTracer& tracer, const Endpoint& from,
                         const std::vector<Endpoint>& to, const PathQueryOptions& options, PathQueryResult& r) {
  PathQueryOptions astar = options;
  astar.method = PathMethod::astar;
  // The ends the windows did not reach: GSP's path, from both ends as asked.
  const auto [missing, missing_ends] = unreached(to, r);
  if (!missing.empty()) {
    const PathQueryResult g = query(solver, tracer, from, missing_ends, astar);
    for (std::size_t i = 0; i < missing.size(); ++i)
      if (g.paths[i].found()) r.paths[missing[i]] = g.paths[i], ++r.astar_fallbacks;
    r.compute_seconds += g.compute_seconds, r.trace_seconds += g.trace_seconds;
    r.edge_fallbacks += g.edge_fallbacks, r.reversed += g.reversed;
  }
  // The others against GSP's path from `from` only: the windows' paths came from both ends
  // already, and an A* walk back from every end doubled the check's cost (gsp-path, 10 ends,
  // over the corpus: the whole run 1.20x the run without the check (median; worst 1.84x) from
  // both ends, 1.11x (1.66x) from one).
  std::vector<std::size_t> found;
  std::vector<Endpoint> found_ends;
  for (std::size_t k = 0; k < to.size(); ++k)
    if (r.paths[k].found()) found.push_back(k), found_ends.push_back(to[k]);
  if (found.empty()) return;
  astar.both_ends = false;
  PathQueryResult g;
  try {
    g = query(solver, tracer, from, found_ends, astar);
  } catch (const Error&) {
    return;   // GSP refused what the windows took (its preparation's limits): their paths stand
  }
  std::vector<std::size_t> suspect;
  std::vector<Endpoint> suspect_ends;
  auto keep_shorter = [&](const GeodesicPath& a, GeodesicPath& p) {
    if (!a.found() || !(a.length < p.length * (1 - 1e-9))) return;
    const double field_distance = p.field_distance;
    p = a;
    p.field_distance = field_distance;   // the windows' value: the field this query reports
    ++r.astar_shorter;
  };
  for (std::size_t i = 0; i < found.size(); ++i) keep_shorter(g.paths[i], r.paths[found[i]]);
  r.compute_seconds += g.compute_seconds, r.trace_seconds += g.trace_seconds;
  // Still more than 1% over the lowest of three fields: GSP's walk back from that end as well
  // (the house wall STL at 10x: windows 13.2%, A* from `from` 32% over, A* from the end
  // 0.000%). The two fields the paths were traced in can both be high where GSP's full field
  // is not (the wall at 1x: both 12.52 at vertex 94, the full field 12.289, A* from the end
  // 12.289): the full field's vertex relaxation and order differ from a goal-directed run's.
  // Rare (no corpus path with an exact value is 0.1% over), so the walk back is nearly free;
  // the full field, bounded by the longest path, costs one more GSP query.
  if (!options.both_ends) return;
  const std::vector<double> full_field = full_field_at(solver, from, found_ends, r.paths, found, r);
  for (std::size_t i = 0; i < found.size(); ++i) {
    const GeodesicPath& p = r.paths[found[i]];
    const double field = std::min({p.field_distance, g.paths[i].field_distance, full_field[i]});
    if (std::isfinite(field) && p.length > 1.01 * field)
      suspect.push_back(found[i]), suspect_ends.push_back(to[found[i]]);
  }
  if (suspect.empty()) return;
  astar.both_ends = true;
  try {
    g = query(solver, tracer, from, suspect_ends, astar);
  } catch (const Error&) {
    return;
  }
  for (std::size_t i = 0; i < suspect.size(); ++i) keep_shorter(g.paths[i], r.paths[suspect[i]]);
  r.compute_seconds += g.compute_seconds, r.trace_seconds += g.trace_seconds;
  r.reversed += g.reversed;
}

PathQueryResult query(LazySolver& solver, const PathTracer& tracer, const Endpoint& from,
                      const std::vector<Endpoint>& to, const PathQueryOptions& options) {
  if (options.method == PathMethod::dijkstra_edges) throw InvalidInput("use edge_paths() for Dijkstra on edges");
  const TriangleMesh& mesh = tracer.mesh();
  PathQueryResult r;
  auto t0 = Clock::now();
  const Field field = propagate(solver, tracer, from, to, options, r.stats);
  r.compute_seconds = seconds_since(t0);
  t0 = Clock::now();
  Query q{solver, tracer, mesh, from, to, field, 1e-6 * bounding_box(mesh).diagonal(), from.position(mesh),
          std::vector<std::exception_ptr>(to.size()), std::vector<bool>(to.size(), false)};
  trace_forward(q, r);
  r.trace_seconds = seconds_since(t0);
  if (options.both_ends)
    for (std::size_t k = 0; k < to.size(); ++k) trace_back(q, options, k, r);
  edge_safety_net(mesh, tracer, from, to, field, q.invalid, q.failed, r);
  if (options.method == PathMethod::windows) shorter_astar_paths(solver, tracer, from, to, options, r);
  edge_paths_for_unreached(mesh, tracer, from, to, r);
  return r;
}

}  // namespace

PathQueryResult shortest_paths(const GeodesicSolver& solver, const PathTracer& tracer, const Endpoint& from,
                               const std::vector<Endpoint>& to, const PathQueryOptions& options) {
  LazySolver lazy(&solver, tracer);
  return query(lazy, tracer, from, to, options);
}

PathQueryResult shortest_paths(const PathTracer& tracer, const Endpoint& from, const std::vector<Endpoint>& to,
                               const PathQueryOptions& options) {
  LazySolver lazy(nullptr, tracer);
  return query(lazy, tracer, from, to, options);
}

}  // namespace gsp::pathfinding
