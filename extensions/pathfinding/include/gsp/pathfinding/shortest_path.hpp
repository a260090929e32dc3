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
  // A few windows per face (gsp/window_geodesics.hpp) on the input's faces, stopped once the
  // end points are settled; the walk back follows, at each point, the window that explains
  // it. Slower than astar, and it keeps to the right corridor where GSP's one source per face
  // does not (docs/pathfinding.md, "Windows").
  windows,
};

struct PathQueryOptions {
  // Windows by default: over 61 corpus meshes (20 paths each, from both ends) no path more than
  // 0.04% over CGAL's exact length, against 12 pairs above 0.5% (worst 14.6%) with astar, at
  // 7x astar's time (median; docs/pathfinding.md, "Windows").
  PathMethod method = PathMethod::windows;
  Precision precision = Precision::automatic;   // as GeodesicOptions: double where faces need it
  // Also propagate from every end point back towards `from` (same method), trace that field
  // from `from`, and keep the shorter of the two taut paths. A path traced from one field
  // follows that field round a feature; where two routes are almost equally long, the
  // field's error can pick the longer one, and the other end's field, whose errors build up
  // from the other end, usually does not (docs/pathfinding.md). Costs one more propagation
  // and trace per end point (2.05-2.2x one A* query for one end point).
  bool both_ends = true;
  unsigned windows = 3;   // per face, for PathMethod::windows (1 to 8)
};

struct PathQueryResult {
  std::vector<GeodesicPath> paths;   // one per end point; empty (found() false) if unreachable
  PropagationStats stats;            // of the propagation from `from` (faces_reached, update_steps, ...)
  PropagationStats reverse_stats;    // summed over the propagations from the end points (both_ends)
  std::size_t reversed = 0;          // paths taken from the end point's field (shorter than the other)
  // Paths replaced by the edge path (the safety net of shortest_paths): no traced path was a
  // valid surface polyline from `from` to the end point within 1% of the field's distance
  // there, and the path along the edges was shorter.
  std::size_t edge_fallbacks = 0;
  // Method windows: paths to end points the windows did not reach (they cross only shared
  // edges; GSP also joins vertices at one position, as on open seams) taken from GSP's A*.
  std::size_t astar_fallbacks = 0;
  // Method windows: paths replaced by GSP's A* path to the same end, a shorter polyline on the
  // surface (the windows the walk follows can miss a corridor GSP's field finds).
  std::size_t astar_shorter = 0;
  double compute_seconds = 0, trace_seconds = 0;   // both directions together
};

// Every path returned is a polyline on the surface (consecutive points in one face) from
// `from` to its end point. A traced path that is not (a walk gone astray in a field of CAD
// needles), or that is more than 1% longer than the field's distance at its end, is compared
// with the shortest path along the edges and the shorter valid one is kept
// (PathQueryResult::edge_fallbacks counts the replacements). Throws InvalidInput for malformed
// end points (missing vertex or face, bad barycentrics). Unreachable end points give empty
// paths, never NoPath.
PathQueryResult shortest_paths(const GeodesicSolver& solver, const PathTracer& tracer, const Endpoint& from,
                               const std::vector<Endpoint>& to, const PathQueryOptions& options = {});

// The same without a prepared GeodesicSolver (one-shot runs: gsp-path). One is built from
// tracer.mesh() for GSP's methods, and for PathMethod::windows too, whose paths are set against
// GSP's A* paths to the same ends (astar_shorter, astar_fallbacks).
PathQueryResult shortest_paths(const PathTracer& tracer, const Endpoint& from, const std::vector<Endpoint>& to,
                               const PathQueryOptions& options = {});

// The baseline: paths along edges from Dijkstra's distances (each vertex steps to the neighbour
// that explains its distance). `mesh` is the one `tracer` was built for.
PathQueryResult edge_paths(const TriangleMesh& mesh, const PathTracer& tracer, const Endpoint& from,
                           const std::vector<Endpoint>& to);

}  // namespace gsp::pathfinding
