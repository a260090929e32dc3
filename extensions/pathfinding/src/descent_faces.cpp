#include "descent_faces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gsp::pathfinding::detail {

namespace {

bool has(const Triangle& t, Index v) { return t[0] == v || t[1] == v || t[2] == v; }

// A face holding the edge (u, w), preferring one that also holds `x` (the step after).
Index edge_face(const TriangleMesh& mesh, const Connectivity& conn, Index u, Index w, Index x) {
  Index any = kInvalidIndex;
  for (Index k = conn.vertex_corner_begin[u]; k < conn.vertex_corner_begin[u + 1]; ++k) {
    const Index f = face_of(conn.vertex_corners[k]);
    const Triangle& t = mesh.triangles[f];
    if (!has(t, w) || t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    if (x != kInvalidIndex && has(t, x)) return f;
    if (any == kInvalidIndex) any = f;
  }
  return any;
}

}  // namespace

std::vector<Index> descent_faces(const TriangleMesh& mesh, const Connectivity& conn, const std::vector<double>& d,
                                 const PathPoint& start, const PathPoint& end) {
  if (d.size() != mesh.num_vertices() || start.face >= mesh.num_faces() || end.face >= mesh.num_faces()) return {};
  const Triangle& ts = mesh.triangles[start.face];
  // The end's nearest corner (by field distance plus the straight step to it).
  const Triangle& te = mesh.triangles[end.face];
  Index u = kInvalidIndex;
  double best = std::numeric_limits<double>::infinity();
  for (Index v : te)
    if (d[v] + distance(mesh.positions[v], end.position) < best) best = d[v] + distance(mesh.positions[v], end.position), u = v;
  if (u == kInvalidIndex) return {};
  std::vector<Index> chain{u};   // vertices from the end towards the source
  for (std::size_t steps = 0; !has(ts, u); ++steps) {
    if (steps > mesh.num_vertices()) return {};
    Index next = kInvalidIndex;
    double key = std::numeric_limits<double>::infinity();
    for (Index k = conn.vertex_corner_begin[u]; k < conn.vertex_corner_begin[u + 1]; ++k)
      for (Index w : mesh.triangles[face_of(conn.vertex_corners[k])])
        if (w != u && d[w] < d[u] && d[w] + distance(mesh.positions[w], mesh.positions[u]) < key)
          key = d[w] + distance(mesh.positions[w], mesh.positions[u]), next = w;
    if (next == kInvalidIndex) return {};
    chain.push_back(u = next);
  }
  // Faces from the source end: the start's face, one per edge step, the end's face.
  std::reverse(chain.begin(), chain.end());
  std::vector<Index> faces{start.face};
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    const Index f = edge_face(mesh, conn, chain[i], chain[i + 1], i + 2 < chain.size() ? chain[i + 2] : kInvalidIndex);
    if (f == kInvalidIndex) return {};
    faces.push_back(f);
  }
  faces.push_back(end.face);
  return faces;
}

}  // namespace gsp::pathfinding::detail
