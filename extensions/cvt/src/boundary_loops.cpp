#include "boundary_loops.hpp"

namespace gsp::cvt::detail {

std::vector<std::vector<Index>> boundary_loops(const WorkingGeometry& g) {
  const TriangleMesh& m = g.mesh;
  std::vector<Index> begin(m.num_vertices() + 1, 0);
  for (Index h = 0; h < g.boundary_halfedge.size(); ++h)
    if (g.boundary_halfedge[h]) ++begin[from_vertex(m, h) + 1];
  for (std::size_t v = 0; v < m.num_vertices(); ++v) begin[v + 1] += begin[v];
  std::vector<Index> leaving(begin.back());
  std::vector<Index> fill(begin.begin(), begin.end() - 1);
  for (Index h = 0; h < g.boundary_halfedge.size(); ++h)
    if (g.boundary_halfedge[h]) leaving[fill[from_vertex(m, h)]++] = h;
  std::vector<bool> used(g.boundary_halfedge.size(), false);
  std::vector<std::vector<Index>> loops;
  for (Index start = 0; start < g.boundary_halfedge.size(); ++start) {
    if (!g.boundary_halfedge[start] || used[start]) continue;
    std::vector<Index> loop;
    Index h = start;
    while (h != kInvalidIndex && !used[h]) {
      used[h] = true;
      loop.push_back(h);
      const Index w = to_vertex(m, h);
      h = kInvalidIndex;
      for (Index i = begin[w]; i < begin[w + 1]; ++i)
        if (!used[leaving[i]]) {
          h = leaving[i];
          break;
        }
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace gsp::cvt::detail
