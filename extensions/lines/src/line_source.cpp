// Line sources made of mesh edges: explicit vertex pairs, vertex chains, the boundary.
#include <gsp/connectivity.hpp>
#include <gsp/errors.hpp>
#include <gsp/lines/line_source.hpp>
#include <gsp/mesh.hpp>

#include <string>

namespace gsp::lines {

namespace {

std::array<double, 3> unit(int corner) {
  std::array<double, 3> w{0, 0, 0};
  w[corner] = 1;
  return w;
}

// One piece per face that has the edge (u, v): the wave starts on every side of it.
std::size_t add_edge(LineSource& src, const TriangleMesh& mesh, const Connectivity& conn, Index u, Index v,
                     Index segment) {
  std::size_t found = 0;
  for (Index k = conn.vertex_corner_begin[u]; k < conn.vertex_corner_begin[u + 1]; ++k) {
    const Index corner = conn.vertex_corners[k];
    const Index f = face_of(corner);
    const Triangle& t = mesh.triangles[f];
    if (repeats_vertex(t)) continue;
    const int i = int(corner_of(corner));
    for (int step = 1; step <= 2; ++step) {
      const int j = (i + step) % 3;
      if (t[j] != v) continue;
      src.pieces.push_back({f, unit(i), unit(j), segment});
      ++found;
    }
  }
  return found;
}

void check_vertex(const TriangleMesh& mesh, Index v) {
  if (v >= mesh.num_vertices())
    throw InvalidInput("vertex " + std::to_string(v) + " does not exist (" + std::to_string(mesh.num_vertices()) +
                       " vertices)");
}

}  // namespace

LineSource edge_source(const TriangleMesh& mesh, const std::vector<std::array<Index, 2>>& edges) {
  validate(mesh);
  const Connectivity conn = build_connectivity(mesh);
  LineSource src;
  for (const auto& [u, v] : edges) {
    check_vertex(mesh, u);
    check_vertex(mesh, v);
    const std::string name = std::to_string(u) + "-" + std::to_string(v);
    if (u == v) throw InvalidInput("source edge " + name + " repeats a vertex");
    if (add_edge(src, mesh, conn, u, v, Index(src.segments.size())) == 0)
      throw InvalidInput("source edge " + name + " is not an edge of the mesh");
    src.segments.push_back({mesh.positions[u], mesh.positions[v]});
  }
  return src;
}

LineSource vertex_chain_source(const TriangleMesh& mesh, const std::vector<Index>& chain, bool closed) {
  if (chain.size() < 2) throw InvalidInput("a vertex chain needs at least two vertices");
  std::vector<std::array<Index, 2>> edges;
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) edges.push_back({chain[i], chain[i + 1]});
  if (closed && chain.size() > 2 && chain.back() != chain.front()) edges.push_back({chain.back(), chain.front()});
  return edge_source(mesh, edges);
}

LineSource boundary_source(const TriangleMesh& mesh) {
  validate(mesh);
  const Connectivity conn = build_connectivity(mesh);
  LineSource src;
  for (Index h = 0; h < Index(conn.num_halfedges()); ++h) {
    if (conn.radial_next[h] != h || conn.halfedge_edge[h] == kInvalidIndex) continue;
    const Index f = face_of(h);
    if (repeats_vertex(mesh.triangles[f])) continue;
    const int i = int(corner_of(h)), j = (i + 1) % 3;
    const Index segment = Index(src.segments.size());
    src.pieces.push_back({f, unit(i), unit(j), segment});
    src.segments.push_back({mesh.positions[mesh.triangles[f][i]], mesh.positions[mesh.triangles[f][j]]});
  }
  if (src.segments.empty()) throw InvalidInput("mesh has no boundary");
  return src;
}

void append(LineSource& a, const LineSource& b) {
  const Index offset = Index(a.segments.size());
  for (SegmentPiece p : b.pieces) {
    p.segment += offset;
    a.pieces.push_back(p);
  }
  a.segments.insert(a.segments.end(), b.segments.begin(), b.segments.end());
  a.max_snap_distance = std::max(a.max_snap_distance, b.max_snap_distance);
}

}  // namespace gsp::lines
