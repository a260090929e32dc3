#include <gsp/intrinsic/coincident_vertices.hpp>
#include <gsp/intrinsic/edge_lengths.hpp>

#include <algorithm>

namespace gsp::intrinsic {

CoincidentVertices coincident_vertices(const TriangleMesh& mesh, const Connectivity& conn,
                                       const std::vector<bool>& skipped_face, const std::vector<double>& length) {
  // The zero-length edges, found by reading the lengths in order (an edge's first halfedge lies
  // anywhere: asking each edge for its length is a cache miss per edge), then taken in edge
  // order: the groups come out in the edges' order.
  std::vector<Index> zero_edges;
  for (Index h = 0; h < Index(length.size()); ++h) {
    if (!zero_length_edge(length, h)) continue;
    const Index e = conn.halfedge_edge[h];
    if (e != kInvalidIndex && conn.edge_halfedge[e] == h && !skipped_face[face_of(h)]) zero_edges.push_back(e);
  }
  if (zero_edges.empty()) return {};   // most meshes: no per-vertex table at all
  // Union the ends of every zero-length edge of a face that takes part.
  std::vector<Index> parent;   // over the vertices met, by a map to local ids
  std::vector<Index> local(mesh.num_vertices(), kInvalidIndex), vertex;
  auto id = [&](Index v) {
    if (local[v] == kInvalidIndex) local[v] = Index(vertex.size()), vertex.push_back(v), parent.push_back(local[v]);
    return local[v];
  };
  auto find = [&](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::sort(zero_edges.begin(), zero_edges.end());
  for (Index e : zero_edges) {
    const Index h = conn.edge_halfedge[e];
    const Index a = id(from_vertex(mesh, h)), b = id(to_vertex(mesh, h));
    const Index ra = find(a), rb = find(b);
    if (ra != rb) parent[ra] = rb;
  }
  CoincidentVertices out;
  if (vertex.empty()) return out;
  std::vector<std::vector<Index>> groups(vertex.size());
  for (Index i = 0; i < Index(vertex.size()); ++i) groups[find(i)].push_back(vertex[i]);
  for (const auto& g : groups) {
    if (g.size() < 2) continue;
    out.vertices.insert(out.vertices.end(), g.begin(), g.end());
    out.begin.push_back(Index(out.vertices.size()));
  }
  return out;
}

}  // namespace gsp::intrinsic
