#include "disjoint_sets.hpp"
#include "prefetch_corners.hpp"

#include <gsp/intrinsic/bridge_vertices.hpp>

namespace gsp::intrinsic {

std::vector<Index> bridge_vertices(const TriangleMesh& mesh, const Connectivity& conn,
                                   const std::vector<bool>& skipped_face) {
  // Corner ids are halfedge ids: corner h of face f is where halfedge h leaves its vertex.
  const Index nh = Index(conn.num_halfedges());
  detail::DisjointSets sets(nh);
  auto unite = [&](Index a, Index b) { sets.unite(a, b); };
  for (Index h = 0; h < nh; ++h) {
    if (h + detail::kHalfedgesAhead < nh) {   // the partner's corners and sets ahead
      const Index g = conn.radial_next[h + detail::kHalfedgesAhead];
      __builtin_prefetch(mesh.triangles.data() + face_of(g));
      __builtin_prefetch(sets.parent.data() + g);
    }
    if (skipped_face[face_of(h)]) continue;
    const Index from = from_vertex(mesh, h);
    for (Index g = conn.radial_next[h]; g != h; g = conn.radial_next[g]) {
      if (g < h || skipped_face[face_of(g)]) continue;   // each pair once
      // h runs from -> to in its face; g runs the same way or the other.
      if (from_vertex(mesh, g) == from) {
        unite(h, g), unite(next_halfedge(h), next_halfedge(g));
      } else {
        unite(h, next_halfedge(g)), unite(next_halfedge(h), g);
      }
    }
  }
  std::vector<Index> bridges;
  for (Index v = 0; v < Index(mesh.num_vertices()); ++v) {
    Index first = kInvalidIndex;
    for (Index k = conn.vertex_corner_begin[v]; k < conn.vertex_corner_begin[v + 1]; ++k) {
      const Index c = conn.vertex_corners[k];
      if (skipped_face[face_of(c)]) continue;
      const Index r = sets.find(c);
      if (first == kInvalidIndex) {
        first = r;
      } else if (r != first) {
        bridges.push_back(v);
        break;
      }
    }
  }
  return bridges;
}

}  // namespace gsp::intrinsic
