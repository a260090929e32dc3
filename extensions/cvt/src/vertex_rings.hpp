#pragma once
// The triangles around each vertex and the boundary links of a mesh whose vertices move: the
// smoothing's moves and checks walk a vertex's ring many times, and only flips change it.
#include <gsp/mesh.hpp>

#include <vector>

namespace gsp::cvt::detail {

struct VertexRings {
  // The corners (3 * face + corner) at v are corners[corner_begin[v]] to corners[corner_begin[v + 1]].
  std::vector<Index> corner_begin, corners;
  // The next and previous boundary vertex; kInvalidIndex inside, and at a vertex the boundary
  // passes twice, so that such a vertex is left where it is.
  std::vector<Index> next_b, prev_b;

  // Lets a ring be walked with a range-for while a check can still return early.
  struct Range {
    const Index *first, *last;
    const Index* begin() const { return first; }
    const Index* end() const { return last; }
  };

  explicit VertexRings(const TriangleMesh& m) { rebuild(m); }
  // The rings and the boundary links, from the triangles.
  void rebuild(const TriangleMesh& m);
  // The rings only: after improve_by_flips' flips on a mesh where no directed edge is in two
  // faces (DirectedEdges::unique), which change no boundary edge (a flip removes an edge with
  // its only two faces and makes one with two faces), so the links stay.
  void rebuild_rings(const TriangleMesh& m);

  Range around(Index v) const { return {corners.data() + corner_begin[v], corners.data() + corner_begin[v + 1]}; }
  bool empty(Index v) const { return corner_begin[v] == corner_begin[v + 1]; }
  bool on_boundary(Index v) const { return next_b[v] != kInvalidIndex || prev_b[v] != kInvalidIndex; }
  // A move of v changes the triangles of these vertices: they are tried again, or locked.
  void mark_ring(const TriangleMesh& m, Index v, std::vector<bool>& flag) const;
};

}  // namespace gsp::cvt::detail
