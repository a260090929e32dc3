#include "prefetch_corners.hpp"

#include <gsp/intrinsic/bridge_vertices.hpp>

#include <algorithm>

namespace gsp::intrinsic {

namespace {

// The corner at v of halfedge g, one of whose ends is v: g's own corner where g leaves v,
// the next one where g arrives at v.
inline Index corner_at(const TriangleMesh& mesh, Index g, Index v) {
  return from_vertex(mesh, g) == v ? g : next_halfedge(g);
}

// Whether v's unskipped corners (`corners`, sorted) form more than one fan: a search over them,
// two joined when their faces share an edge through v, whatever the edge's face count or the
// faces' orientations (both edges of a corner meet v: the halfedge leaving v and the one
// arriving).
bool splits_into_fans(const TriangleMesh& mesh, const Connectivity& conn, const std::vector<bool>& skipped_face,
                      Index v, const std::vector<Index>& corners, std::vector<char>& reached, std::vector<Index>& stack) {
  reached.assign(corners.size(), 0);
  reached[0] = 1;
  stack.assign(1, corners[0]);
  std::size_t count = 1;
  while (!stack.empty() && count < corners.size()) {
    const Index c = stack.back();
    stack.pop_back();
    for (const Index x : {c, prev_halfedge(c)}) {
      for (Index g = conn.radial_next[x]; g != x; g = conn.radial_next[g]) {
        if (skipped_face[face_of(g)]) continue;
        const Index d = corner_at(mesh, g, v);
        const std::size_t slot = std::size_t(std::lower_bound(corners.begin(), corners.end(), d) - corners.begin());
        if (slot == corners.size() || corners[slot] != d || reached[slot]) continue;
        reached[slot] = 1;
        ++count;
        stack.push_back(d);
      }
    }
  }
  return count < corners.size();
}

}  // namespace

// Most vertices are the centre of one closed fan of two-face edges: their corners form one
// cycle of "the next corner round" (across the edge arriving at v, to the corner at v of the
// face beyond). That successor is found for every corner in one pass in face order, and a
// vertex whose cycle from its first corner takes all its corners has one fan; only the others
// (boundary, non-manifold, skipped faces, bridges) are searched corner by corner. One
// union-find over all corners gives the same answer but waits on a cache miss per corner, and
// a search at every vertex on several (docs/gsp-core.md, "Bridges").
std::vector<Index> bridge_vertices(const TriangleMesh& mesh, const Connectivity& conn,
                                   const std::vector<bool>& skipped_face) {
  const Index nh = Index(conn.num_halfedges()), nf = Index(mesh.num_faces());
  std::vector<Index> round(nh, kInvalidIndex);   // corner -> the next corner round its vertex
  for (Index f = 0; f < nf; ++f) {
    if (f + Index(detail::kFacesAhead) < nf)   // the faces beyond the edges ahead
      for (Index i = 0; i < 3; ++i) {
        const Index g = conn.radial_next[3 * (f + Index(detail::kFacesAhead)) + i];
        __builtin_prefetch(conn.radial_next.data() + g);
        __builtin_prefetch(mesh.triangles.data() + face_of(g));
      }
    if (skipped_face[f]) continue;
    const Triangle& t = mesh.triangles[f];
    for (Index i = 0; i < 3; ++i) {
      const Index c = 3 * f + i, x = prev_halfedge(c), g = conn.radial_next[x];
      if (g == x || conn.radial_next[g] != x || skipped_face[face_of(g)]) continue;
      round[c] = corner_at(mesh, g, t[i]);
    }
  }
  std::vector<Index> bridges, corners, stack;
  std::vector<char> reached;
  const Index nv = Index(mesh.num_vertices());
  constexpr Index kAhead = 8;
  for (Index v = 0; v < nv; ++v) {
    if (v + kAhead < nv)
      for (Index k = conn.vertex_corner_begin[v + kAhead]; k < conn.vertex_corner_begin[v + kAhead + 1]; ++k)
        __builtin_prefetch(round.data() + conn.vertex_corners[k]);
    const Index begin = conn.vertex_corner_begin[v], end = conn.vertex_corner_begin[v + 1];
    if (end - begin < 2) continue;
    const Index first = conn.vertex_corners[begin];
    Index c = first, steps = 0;
    if (!skipped_face[face_of(first)])
      do {
        c = round[c], ++steps;
      } while (c != kInvalidIndex && c != first && steps <= end - begin);
    if (c == first && steps == end - begin) continue;   // one cycle through every corner
    corners.clear();
    for (Index k = begin; k < end; ++k)
      if (!skipped_face[face_of(conn.vertex_corners[k])]) corners.push_back(conn.vertex_corners[k]);
    if (corners.size() >= 2 && splits_into_fans(mesh, conn, skipped_face, v, corners, reached, stack))
      bridges.push_back(v);
  }
  return bridges;
}

}  // namespace gsp::intrinsic
