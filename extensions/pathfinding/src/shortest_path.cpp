#include <gsp/pathfinding/shortest_path.hpp>

#include <chrono>

namespace gsp::pathfinding {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

Source to_source(const Endpoint& e) {
  return e.is_vertex() ? Source::at_vertex(e.vertex) : Source::in_face(e.face, e.barycentric);
}

}  // namespace

PathQueryResult shortest_paths(const GeodesicSolver& solver, const PathTracer& tracer, const Endpoint& from,
                               const std::vector<Endpoint>& to, const PathQueryOptions& options) {
  if (options.method == PathMethod::dijkstra_edges) throw InvalidInput("use edge_paths() for Dijkstra on edges");
  GeodesicOptions go;
  go.want_face_sources = true;   // the walk back needs every face's virtual source
  go.precision = options.precision;
  if (options.method != PathMethod::full) {
    // Vertices as they are; a point inside a face is settled once its face's corners are.
    for (const Endpoint& e : to) {
      endpoint_position(tracer.mesh(), e);   // validates before indexing
      if (e.is_vertex()) {
        go.targets.push_back(e.vertex);
      } else {
        const Triangle& t = tracer.mesh().triangles[e.face];
        go.targets.insert(go.targets.end(), t.begin(), t.end());
      }
    }
    go.goal_directed = options.method == PathMethod::astar && !go.targets.empty();
  }
  PathQueryResult r;
  auto t0 = Clock::now();
  const GeodesicResult field = solver.compute({to_source(from)}, go);
  r.compute_seconds = seconds_since(t0);
  r.stats = field.stats;
  t0 = Clock::now();
  r.paths = tracer.trace_all(field, to);
  r.trace_seconds = seconds_since(t0);
  return r;
}

}  // namespace gsp::pathfinding
