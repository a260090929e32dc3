#pragma once
// Connectivity of a triangle soup, built without assuming manifoldness or orientation.
//
// Halfedge h = 3*f + i runs from corner i to corner (i+1)%3 of face f. Halfedges that lie on
// the same undirected edge form a cyclic "radial ring" through radial_next: a ring of one is a
// boundary edge, two a manifold edge, more a non-manifold edge. Propagation across an edge
// visits every other member of the ring, so no face the input has is ever cut off.
#include <gsp/mesh.hpp>

#include <vector>

namespace gsp {

inline constexpr Index face_of(Index h) { return h / 3; }
inline constexpr Index corner_of(Index h) { return h % 3; }
inline constexpr Index next_halfedge(Index h) { return h % 3 == 2 ? h - 2 : h + 1; }
inline constexpr Index prev_halfedge(Index h) { return h % 3 == 0 ? h + 2 : h - 1; }

struct Connectivity {
  // Per halfedge: the next halfedge on the same undirected edge (cyclic). A halfedge whose two
  // ends are the same vertex (a face repeating an index) is a ring of its own.
  std::vector<Index> radial_next;
  // Per halfedge: its undirected edge, or kInvalidIndex for a halfedge whose ends coincide.
  std::vector<Index> halfedge_edge;
  // Per undirected edge: one of its halfedges.
  std::vector<Index> edge_halfedge;
  // The edges with more than two halfedges (non-manifold), in increasing order: what the
  // duplicate-face and non-manifold-vertex passes read instead of every edge's ring.
  std::vector<Index> nonmanifold_edges;
  // Vertex -> incident corners (3*f + i with triangles[f][i] == v), CSR: the corners of v are
  // vertex_corners[vertex_corner_begin[v] .. vertex_corner_begin[v+1]), in increasing order.
  std::vector<Index> vertex_corner_begin;
  std::vector<Index> vertex_corners;

  std::size_t num_halfedges() const { return radial_next.size(); }
  std::size_t num_edges() const { return edge_halfedge.size(); }
  // Number of halfedges on h's undirected edge (1 boundary, 2 manifold, >2 non-manifold).
  std::size_t ring_size(Index h) const;
};

Connectivity build_connectivity(const TriangleMesh& mesh);

// Vertex at the start / end of halfedge h.
inline Index from_vertex(const TriangleMesh& m, Index h) { return m.triangles[face_of(h)][corner_of(h)]; }
inline Index to_vertex(const TriangleMesh& m, Index h) {
  return m.triangles[face_of(h)][corner_of(next_halfedge(h))];
}

}  // namespace gsp
