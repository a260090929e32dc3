#pragma once
// A vertex joined to a vertex source by an edge of the input (internal): the edge is a path on
// the surface, so the distance there is at most the source's offset plus the edge's length,
// and when nothing nearer reaches the vertex it is exactly that. The propagation computes the
// value in its own precision (float by default: sigma + |S - corner| in mean edge lengths),
// about 1e-7 relative off the edge's length in double, so on a mesh whose every vertex is one
// edge from a source (a single triangle, a soup of triangles) GSP was less accurate than
// Dijkstra, which adds the double lengths. After the relaxation, a value that such an edge
// beats, or that lies within the propagation's rounding below it, takes the edge's value in
// double: lowered, it is the length of a surface path (the relaxation's rule without its
// rounding); raised, by at most that rounding, it is exact wherever the propagation saw no
// nearer source (where one is nearer by less than the rounding, the value moves by less than
// the rounding).
#include "solver_impl.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace gsp::detail {

// The vertex seeds and their input-edge neighbours with the smallest value a seed gives each
// along one edge (model units) and that seed's label, sorted by vertex. Faces that repeat a
// vertex have no edges.
inline std::vector<VertexSeed> source_edge_values(const Triangulation& input, const std::vector<bool>& skipped_face,
                                                  const std::vector<VertexSeed>& seeds) {
  std::vector<VertexSeed> out(seeds);
  for (const VertexSeed& s : seeds)
    for (Index k = input.corner_begin[s.vertex]; k < input.corner_begin[s.vertex + 1]; ++k) {
      const Index c = input.corners[k];
      const Index f = face_of(c);
      if (skipped_face[f]) continue;
      const Index j = corner_of(c), jn = j == 2 ? 0 : j + 1, jp = j == 0 ? 2 : j - 1;
      out.push_back({input.triangles()[f][jn], s.value + input.length[3 * f + j], s.label});
      out.push_back({input.triangles()[f][jp], s.value + input.length[3 * f + jp], s.label});
    }
  // The smallest value per vertex first (the earlier seed on ties), then one entry per vertex.
  std::stable_sort(out.begin(), out.end(), [](const VertexSeed& a, const VertexSeed& b) {
    return a.vertex != b.vertex ? a.vertex < b.vertex : a.value < b.value;
  });
  out.erase(std::unique(out.begin(), out.end(), [](const VertexSeed& a, const VertexSeed& b) { return a.vertex == b.vertex; }),
            out.end());
  return out;
}

// Whether a value d computed in the propagation's precision `Real` gives way to the edge
// path `edge`: the edge is shorter, or d lies within Real's rounding below it.
template <class Real>
bool settles_to_edge(double d, double edge) {
  constexpr double kRounding = 16 * double(std::numeric_limits<Real>::epsilon());
  return d >= edge * (1 - kRounding) && d != edge;
}

}  // namespace gsp::detail
