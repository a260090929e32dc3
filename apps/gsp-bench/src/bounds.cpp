#include "bounds.hpp"

#include <algorithm>
#include <cmath>

namespace gsp::bench {

BoundStats physical_bounds(const TriangleMesh& mesh, Index source, const std::vector<double>& distance,
                           const std::vector<double>& edge) {
  BoundStats s;
  const Vec3 at = mesh.positions[source];
  const std::size_t n = std::min(distance.size(), mesh.num_vertices());
  for (std::size_t v = 0; v < n; ++v) {
    const double d = distance[v];
    if (std::isnan(d)) {
      ++s.nan;
      continue;
    }
    const double e = v < edge.size() ? edge[v] : std::nan("");
    if (!std::isfinite(d)) {
      if (std::isfinite(e)) ++s.unreached;
      continue;
    }
    ++s.checked;
    // Vertices at the source's position (duplicates, the source itself) have no line to
    // compare with: any d >= 0 is fine there.
    const double line = gsp::distance(mesh.positions[v], at);
    if (line > 0) {
      s.below_line = std::max(s.below_line, (line - d) / line);
      if (d < (1 - kBoundTolerance) * line) ++s.below_count;
    }
    if (std::isfinite(e) && e > 0) {
      s.above_edge = std::max(s.above_edge, (d - e) / e);
      if (d > (1 + kBoundTolerance) * e) ++s.above_count;
    }
  }
  return s;
}

BoundStats worst_of(const BoundStats& a, const BoundStats& b) {
  BoundStats s;
  s.below_line = std::max(a.below_line, b.below_line);
  s.above_edge = std::max(a.above_edge, b.above_edge);
  s.below_count = a.below_count + b.below_count;
  s.above_count = a.above_count + b.above_count;
  s.unreached = a.unreached + b.unreached;
  s.nan = a.nan + b.nan;
  s.checked = a.checked + b.checked;
  return s;
}

bool violates(const BoundStats& s) {
  return s.below_line > kBoundTolerance || s.above_edge > kBoundTolerance || s.nan > 0;
}

}  // namespace gsp::bench
