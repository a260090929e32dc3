// The Dijkstra-on-edges baseline: paths along mesh edges, for comparison with traced GSP paths.
#include <gsp/pathfinding/shortest_path.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <unordered_set>

namespace gsp::pathfinding {

namespace {

using Clock = std::chrono::steady_clock;

// A point of the path at vertex v, placed in a face that also holds `other` (so consecutive
// points share a face), else any face of v; faces with an area first (a zero-area face has no
// plane to hold a point: the poles of a UV sphere).
PathPoint vertex_point(const TriangleMesh& mesh, const Connectivity& conn, Index v, Index other) {
  PathPoint p;
  p.position = mesh.positions[v];
  int rank = -1;   // 3: shares `other` and has an area, 2: shares, 1: has an area, 0: any
  for (Index k = conn.vertex_corner_begin[v]; k < conn.vertex_corner_begin[v + 1]; ++k) {
    const Index c = conn.vertex_corners[k];
    const Triangle& t = mesh.triangles[face_of(c)];
    const bool shares = other == kInvalidIndex || t[0] == other || t[1] == other || t[2] == other;
    const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], d = mesh.positions[t[2]];
    const bool area = norm(cross(b - a, d - a)) > 0;
    const int r = 2 * int(shares) + int(area);
    if (r > rank) {
      rank = r;
      p.point = SurfacePoint::in_face(face_of(c), {0, 0, 0});
      p.point.barycentric[corner_of(c)] = 1;
      if (r == 3) break;
    }
  }
  return p;
}

// The neighbour w of u with d[w] < d[u] that explains d[u] best (d[w] + |wu| smallest, within
// rounding of d[u]); kInvalidIndex when none.
Index predecessor(const TriangleMesh& mesh, const Connectivity& conn, const std::vector<double>& d, Index u) {
  Index next = kInvalidIndex;
  double best = d[u];
  for (Index k = conn.vertex_corner_begin[u]; k < conn.vertex_corner_begin[u + 1]; ++k) {
    const Triangle& t = mesh.triangles[face_of(conn.vertex_corners[k])];
    for (Index w : t)
      if (w != u && d[w] < d[u] && d[w] + distance(mesh.positions[w], mesh.positions[u]) <= best * (1 + 1e-12))
        best = d[w] + distance(mesh.positions[w], mesh.positions[u]), next = w;
  }
  return next;
}

// Of the vertices joined to u by edges of length zero (breadth first), the first where the
// path starts (`is_start`) or that has a predecessor; kInvalidIndex when none.
template <class IsStart>
Index copy_with_predecessor(const TriangleMesh& mesh, const Connectivity& conn, const std::vector<double>& d, Index u,
                            IsStart&& is_start) {
  std::vector<Index> queue{u};
  std::unordered_set<Index> seen{u};
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const Index x = queue[i];
    if (x != u && (is_start(x) || predecessor(mesh, conn, d, x) != kInvalidIndex)) return x;
    for (Index k = conn.vertex_corner_begin[x]; k < conn.vertex_corner_begin[x + 1]; ++k)
      for (Index w : mesh.triangles[face_of(conn.vertex_corners[k])])
        if (!seen.count(w) && mesh.positions[w].x == mesh.positions[x].x && mesh.positions[w].y == mesh.positions[x].y &&
            mesh.positions[w].z == mesh.positions[x].z && d[w] <= d[u])
          seen.insert(w), queue.push_back(w);
  }
  return kInvalidIndex;
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
  // Where the path starts: the source vertex, or a corner of the source's face whose distance
  // is the straight line from the source point.
  auto is_start = [&](Index x) {
    if (from.is_vertex()) return x == from.element;
    const Triangle& t = mesh.triangles[from.element];
    const bool corner = t[0] == x || t[1] == x || t[2] == x;
    return corner && std::abs(d[x] - distance(mesh.positions[x], from_pos)) <= 1e-12 * (1 + d[x]);
  };
  for (std::size_t steps = 0; steps <= mesh.num_vertices(); ++steps) {
    if (is_start(u)) {
      if (!from.is_vertex()) path.points.push_back({from, from_pos});
      break;
    }
    Index next = predecessor(mesh, conn, d, u);
    if (next == kInvalidIndex) {
      // u's distance came over edges of length zero (the poles of a UV sphere stored with
      // zero-area faces: a chain of copies of one point): go to the copy that has one, or
      // that is where the path starts (a corner of a source face at the pole).
      const Index x = copy_with_predecessor(mesh, conn, d, u, is_start);
      if (x == kInvalidIndex) throw Error("edge path: no predecessor at vertex " + std::to_string(u));
      next = x;
    }
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
