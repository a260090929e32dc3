#pragma once
// Shortest paths between surface points in one call: a GSP field from `from` (goal-directed
// towards the end points, or over the whole mesh), traced back from every end point. The
// Dijkstra-on-edges baseline walks the edge graph instead (zig-zag paths along edges).
//
//   gsp::GeodesicSolver solver(mesh);
//   gsp::pathfinding::PathTracer tracer(mesh);
//   auto r = gsp::pathfinding::shortest_paths(solver, tracer, Endpoint::at_vertex(0),
//                                             {Endpoint::at_vertex(42)}, PathMethod::astar);
//   r.paths[0].points, r.paths[0].length
#include <gsp/dijkstra.hpp>
#include <gsp/geodesics.hpp>
#include <gsp/pathfinding/path.hpp>
#include <gsp/pathfinding/path_tracer.hpp>

#include <vector>

namespace gsp::pathfinding {

enum class PathMethod : std::uint8_t {
  astar,            // GSP in A* order, stopped once the end points are settled (Fig. 12b)
  settle,           // GSP in Dijkstra order, stopped once the end points are settled (Fig. 12a)
  full,             // GSP over the whole mesh (default strategy)
  dijkstra_edges,   // Dijkstra on the edge graph: paths along edges (baseline)
};

struct PathQueryOptions {
  PathMethod method = PathMethod::astar;
  Precision precision = Precision::single;
};

struct PathQueryResult {
  std::vector<GeodesicPath> paths;   // one per end point; empty (found() false) if unreachable
  PropagationStats stats;            // of the propagation (faces_reached, update_steps, ...)
  double compute_seconds = 0, trace_seconds = 0;
};

// Throws InvalidInput for malformed end points (missing vertex or face, bad barycentrics).
// Unreachable end points give empty paths, never NoPath.
PathQueryResult shortest_paths(const GeodesicSolver& solver, const PathTracer& tracer, const Endpoint& from,
                               const std::vector<Endpoint>& to, const PathQueryOptions& options = {});

// The baseline: paths along edges from Dijkstra's distances (each vertex steps to the neighbour
// that explains its distance). `mesh` is the one `tracer` was built for.
PathQueryResult edge_paths(const TriangleMesh& mesh, const PathTracer& tracer, const Endpoint& from,
                           const std::vector<Endpoint>& to);

}  // namespace gsp::pathfinding
