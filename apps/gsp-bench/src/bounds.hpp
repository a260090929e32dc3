#pragma once
// Physical bounds every geodesic distance must respect, checked without exact distances:
// no surface path is shorter than the straight line from the source, and every path along
// mesh edges is a surface path, so the geodesic is at most the edge-path (Dijkstra) distance.
// A method that breaks either is wrong on that mesh, whatever its error against exact says.
#include <gsp/mesh.hpp>

#include <cstddef>
#include <vector>

namespace gsp::bench {

struct BoundStats {
  double below_line = 0;         // max (|x-s| - d) / |x-s| over vertices off the source point, >= 0
  std::size_t below_count = 0;   // vertices with d < 0.99 |x-s|
  double above_edge = 0;         // max (d - e) / e over vertices with finite e > 0, >= 0
  std::size_t above_count = 0;   // vertices with d > 1.01 e
  std::size_t unreached = 0;     // d = +inf where an edge path exists (e finite)
  std::size_t nan = 0;           // d is NaN
  std::size_t checked = 0;       // vertices with a finite d (what below_line looked at)
};

// The 1% margin of the counts: below it a deviation is rounding (single-precision state,
// flat triangles), above it a wrong distance.
constexpr double kBoundTolerance = 0.01;

// `distance` and `edge` per mesh vertex (mesh order); `source` a vertex of `mesh`.
BoundStats physical_bounds(const TriangleMesh& mesh, Index source, const std::vector<double>& distance,
                           const std::vector<double>& edge);

// The worst of two (max of the ratios, sum of the counts): the figure over several sources.
BoundStats worst_of(const BoundStats& a, const BoundStats& b);

// A bound broken by more than kBoundTolerance, or a NaN distance.
bool violates(const BoundStats& s);

}  // namespace gsp::bench
