#include "vertex_rings.hpp"
#include "triangle_geometry.hpp"

#include <gsp/connectivity.hpp>

#include <unordered_map>

namespace gsp::cvt::detail {

void VertexRings::rebuild_rings(const TriangleMesh& m) {
  const std::size_t V = m.num_vertices();
  corner_begin.assign(V + 1, 0);
  for (const Triangle& t : m.triangles)
    for (Index v : t) ++corner_begin[v + 1];
  for (std::size_t v = 0; v < V; ++v) corner_begin[v + 1] += corner_begin[v];
  corners.assign(corner_begin.back(), 0);
  std::vector<Index> fill(corner_begin.begin(), corner_begin.end() - 1);
  for (Index f = 0; f < m.num_faces(); ++f)
    for (Index i = 0; i < 3; ++i) corners[fill[m.triangles[f][i]]++] = 3 * f + i;
}

void VertexRings::rebuild(const TriangleMesh& m) {
  const std::size_t V = m.num_vertices();
  rebuild_rings(m);
  std::unordered_map<std::uint64_t, Index> directed;
  for (Index f = 0; f < m.num_faces(); ++f)
    for (Index i = 0; i < 3; ++i) directed[edge_key(m.triangles[f][i], m.triangles[f][(i + 1) % 3])] = f;
  BoundaryLinks links = boundary_links(m, directed);
  next_b = std::move(links.next);
  prev_b = std::move(links.prev);
  for (std::size_t v = 0; v < V; ++v)
    if (links.out_count[v] > 1) next_b[v] = prev_b[v] = kInvalidIndex;
}

void VertexRings::mark_ring(const TriangleMesh& m, Index v, std::vector<bool>& flag) const {
  for (Index c : around(v))
    for (Index w : m.triangles[face_of(c)]) flag[w] = true;
}

}  // namespace gsp::cvt::detail
