// The Dijkstra-on-edges baseline: paths along mesh edges, for comparison with traced GSP paths.
#include <gsp/pathfinding/shortest_path.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace gsp::pathfinding {

namespace {

using Clock = std::chrono::steady_clock;

// A point of the path at vertex v, placed in a face that also holds `other` (so consecutive
// points share a face); any face of v when there is none.
PathPoint vertex_point(const TriangleMesh& mesh, const Connectivity& conn, Index v, Index other) {
  PathPoint p;
  p.position = mesh.positions[v];
  for (Index k = conn.vertex_corner_begin[v]; k < conn.vertex_corner_begin[v + 1]; ++k) {
    const Index c = conn.vertex_corners[k];
    const Triangle& t = mesh.triangles[face_of(c)];
    const bool shares = other == kInvalidIndex || t[0] == other || t[1] == other || t[2] == other;
    if (p.point.element == kInvalidIndex || shares) {
      p.point = SurfacePoint::in_face(face_of(c), {0, 0, 0});
      p.point.barycentric[corner_of(c)] = 1;
      if (shares) break;
    }
  }
  return p;
}

GeodesicPath backtrack(const TriangleMesh& mesh, const Connectivity& conn, const std::vector<double>& d,
                       const Endpoint& from, const Vec3 from_pos, const Endpoint& end) {
  GeodesicPath path;
  Index u = kInvalidIndex;
  if (end.is_vertex()) {
    u = end.element;
    path.field_distance = d[u];
    path.points.push_back(vertex_point(mesh, conn, u, kInvalidIndex));
  } else {
    const Triangle& t = mesh.triangles[end.element];
    const Vec3 p = end.position(mesh);
    double best = std::numeric_limits<double>::infinity();
    for (Index v : t)
      if (d[v] + distance(mesh.positions[v], p) < best) best = d[v] + distance(mesh.positions[v], p), u = v;
    path.field_distance = best;
    path.points.push_back({end, p});
    if (std::isfinite(best)) path.points.push_back(vertex_point(mesh, conn, u, t[0] == u ? t[1] : t[0]));
  }
  if (!std::isfinite(path.field_distance)) return {};
  for (std::size_t steps = 0; steps <= mesh.num_vertices(); ++steps) {
    if (from.is_vertex() && u == from.element) break;
    if (!from.is_vertex()) {
      const Triangle& t = mesh.triangles[from.element];
      const bool corner = t[0] == u || t[1] == u || t[2] == u;
      if (corner && std::abs(d[u] - distance(mesh.positions[u], from_pos)) <= 1e-12 * (1 + d[u])) {
        path.points.push_back({from, from_pos});
        break;
      }
    }
    Index next = kInvalidIndex;
    double best = d[u];
    for (Index k = conn.vertex_corner_begin[u]; k < conn.vertex_corner_begin[u + 1]; ++k) {
      const Triangle& t = mesh.triangles[face_of(conn.vertex_corners[k])];
      for (Index w : t)
        if (w != u && d[w] < d[u] && d[w] + distance(mesh.positions[w], mesh.positions[u]) <= best * (1 + 1e-12))
          best = d[w] + distance(mesh.positions[w], mesh.positions[u]), next = w;
    }
    if (next == kInvalidIndex) throw Error("edge path: no predecessor at vertex " + std::to_string(u));
    path.points.push_back(vertex_point(mesh, conn, next, u));
    u = next;
  }
  std::reverse(path.points.begin(), path.points.end());
  path.length = polyline_length(path.points);
  path.source = 0;
  return path;
}

}  // namespace

PathQueryResult edge_paths(const TriangleMesh& mesh, const PathTracer& tracer, const Endpoint& from,
                           const std::vector<Endpoint>& to) {
  check_endpoint(mesh, from);
  const Vec3 from_pos = from.position(mesh);
  for (const Endpoint& e : to) check_endpoint(mesh, e);
  PathQueryResult r;
  auto t0 = Clock::now();
  const DijkstraSolver solver(mesh);
  const GeodesicResult field = solver.compute({Source::at(from)});
  r.compute_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  r.stats = field.stats;
  t0 = Clock::now();
  for (const Endpoint& e : to) r.paths.push_back(backtrack(mesh, tracer.connectivity(), field.vertex_distance, from, from_pos, e));
  r.trace_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return r;
}

}  // namespace gsp::pathfinding
