#include "descent_faces.hpp"
#include "sleeve.hpp"

#include <gsp/surface_point.hpp>

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
    if (!has(t, w) || repeats_vertex(t)) continue;
    if (x != kInvalidIndex && has(t, x)) return f;
    if (any == kInvalidIndex) any = f;
  }
  return any;
}


// The vertex chain from the end's best corner down the field, stopping at a vertex of
// `stop_face` (or, with kInvalidIndex, where no neighbour is lower); empty when stuck.
std::vector<Index> descend(const TriangleMesh& mesh, const Connectivity& conn, const std::vector<double>& d,
                           const PathPoint& end, Index stop_face) {
  const Triangle& te = mesh.triangles[end.point.element];
  Index u = kInvalidIndex;
  double best = std::numeric_limits<double>::infinity();
  for (Index v : te)
    if (d[v] + distance(mesh.positions[v], end.position) < best) best = d[v] + distance(mesh.positions[v], end.position), u = v;
  if (u == kInvalidIndex) return {};
  std::vector<Index> chain{u};   // vertices from the end towards the source
  for (std::size_t steps = 0; stop_face == kInvalidIndex || !has(mesh.triangles[stop_face], u); ++steps) {
    if (steps > mesh.num_vertices()) return {};
    Index next = kInvalidIndex;
    double key = std::numeric_limits<double>::infinity();
    for (Index k = conn.vertex_corner_begin[u]; k < conn.vertex_corner_begin[u + 1]; ++k)
      for (Index w : mesh.triangles[face_of(conn.vertex_corners[k])])
        if (w != u && d[w] < d[u] && d[w] + distance(mesh.positions[w], mesh.positions[u]) < key)
          key = d[w] + distance(mesh.positions[w], mesh.positions[u]), next = w;
    if (next == kInvalidIndex) {
      if (stop_face == kInvalidIndex) break;   // the bottom
      return {};
    }
    chain.push_back(u = next);
  }
  std::reverse(chain.begin(), chain.end());
  return chain;
}

// Faces from the source end: the start's face, one per edge step, the end's face.
std::vector<Index> chain_faces(const TriangleMesh& mesh, const Connectivity& conn, const std::vector<Index>& chain,
                               Index start_face, Index end_face) {
  std::vector<Index> faces{start_face};
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    const Index f = edge_face(mesh, conn, chain[i], chain[i + 1], i + 2 < chain.size() ? chain[i + 2] : kInvalidIndex);
    if (f == kInvalidIndex) return {};
    faces.push_back(f);
  }
  faces.push_back(end_face);
  return faces;
}

// The points of the descent itself: start, the chain's vertices, end; each in the face
// holding the segment that ends there (faces as chain_faces gives them).
std::vector<PathPoint> edge_route(const TriangleMesh& mesh, const std::vector<Index>& chain, const std::vector<Index>& faces,
                                  const PathPoint& start, const PathPoint& end) {
  std::vector<PathPoint> points{start};
  auto push = [&](const PathPoint& q) {
    if (distance(points.back().position, q.position) > 0) points.push_back(q);
  };
  for (std::size_t i = 0; i < chain.size(); ++i) {
    PathPoint q;
    q.point = SurfacePoint::in_face(faces[i], {0, 0, 0});   // start's face for the bottom vertex, then the edge's face
    q.position = mesh.positions[chain[i]];
    for (int c = 0; c < 3; ++c)
      if (mesh.triangles[faces[i]][c] == chain[i]) q.point.barycentric[c] = 1;
    push(q);
  }
  push(end);
  return points;
}

// The descent's bottom u as the path's start, in the first face round it (a vertex source);
// `scale`, the longest first edge of u's faces, sizes what counts as at u.
PathPoint vertex_start(const TriangleMesh& mesh, const Connectivity& conn, Index u, double& scale) {
  PathPoint start;
  for (Index k = conn.vertex_corner_begin[u]; k < conn.vertex_corner_begin[u + 1]; ++k) {
    const Index c = conn.vertex_corners[k];
    const Index f = face_of(c);
    const Triangle& t = mesh.triangles[f];
    scale = std::max(scale, distance(mesh.positions[t[0]], mesh.positions[t[1]]));
    if (start.point.element == kInvalidIndex) {
      start.point = SurfacePoint::in_face(f, {0, 0, 0});
      start.point.barycentric[corner_of(c)] = 1;
      start.position = mesh.positions[u];
    }
  }
  return start;
}

// A point source in a face round u: the face whose virtual source lies in it at sigma about 0
// replaces u as the start; false where there is none.
bool face_source_start(const TriangleMesh& mesh, const Connectivity& conn, const SourceField& field, Index u,
                       double scale, PathPoint& start) {
  const std::vector<double>& d = field.vertex_distance();
  for (Index k = conn.vertex_corner_begin[u]; k < conn.vertex_corner_begin[u + 1]; ++k) {
    const Index f = face_of(conn.vertex_corners[k]);
    if (!field.reached(f)) continue;
    const VirtualSource vs = field.source_at(f, mesh.positions[u]);
    if (vs.sigma > 1e-9 * (1 + d[u])) continue;
    const auto [b0, b1, b2] = affine_coordinates(mesh, f, vs.position);
    if (b0 == 0 && b1 == 0 && b2 == 0) continue;   // no plane (coordinates of a face sum to 1)
    if (std::min({b0, b1, b2}) < -1e-6 || distance(vs.position, mesh.positions[u]) <= 1e-9 * (1 + scale)) continue;
    start.point = SurfacePoint::in_face(f, {std::max(0.0, b0), std::max(0.0, b1), std::max(0.0, b2)});
    start.position = vs.position;
    return true;
  }
  return false;
}

}  // namespace

std::vector<Index> descent_faces(const TriangleMesh& mesh, const Connectivity& conn, const std::vector<double>& d,
                                 const PathPoint& start, const PathPoint& end) {
  const Index start_face = start.point.element, end_face = end.point.element;
  if (d.size() != mesh.num_vertices() || start_face >= mesh.num_faces() || end_face >= mesh.num_faces()) return {};
  const std::vector<Index> chain = descend(mesh, conn, d, end, start_face);
  return chain.empty() ? chain : chain_faces(mesh, conn, chain, start_face, end_face);
}

bool descent_path(const TriangleMesh& mesh, const Connectivity& conn, const SourceField& field,
                  const PathPoint& end, GeodesicPath& out) {
  const std::vector<double>& d = field.vertex_distance();
  if (d.size() != mesh.num_vertices() || end.point.element >= mesh.num_faces()) return false;
  const std::vector<Index> chain = descend(mesh, conn, d, end, kInvalidIndex);
  if (chain.empty()) return false;
  const Index u = chain.front();
  // The source near the bottom: a face round u whose virtual source lies in it at sigma about
  // 0 (a point source in a face), else u itself (a vertex source).
  double scale = 0;
  PathPoint start = vertex_start(mesh, conn, u, scale);
  if (start.point.element == kInvalidIndex) return false;
  const bool found_face_source = face_source_start(mesh, conn, field, u, scale, start);
  // Neither a point source in a face round u nor a source at u (distance 0 there): the field
  // bottoms out somewhere else than at a source, and this route cannot be trusted (a vertex
  // source with an initial offset lands here too: the walk handles those).
  if (!found_face_source && !(d[u] <= 0)) return false;
  const std::vector<Index> faces = chain_faces(mesh, conn, chain, start.point.element, end.point.element);
  if (faces.empty()) return false;
  // No sleeve through these faces (a vertex whose fan the walk round it cannot follow: a
  // non-manifold vertex, seams left open): the edge route as it is, a true surface path.
  if (!shorten_in_sleeve(mesh, conn, start, end, faces, out.points)) out.points = edge_route(mesh, chain, faces, start, end);
  out.length = polyline_length(out.points);
  const Index start_face = start.point.element;
  out.source = field.reached(start_face) ? field.source_at(start_face, start.position).source : kInvalidIndex;
  if (out.source == kInvalidIndex && u < field.vertex_source().size()) out.source = field.vertex_source()[u];
  return true;
}

}  // namespace gsp::pathfinding::detail
