#pragma once
// Merging coincident vertices: STL and glTF store no shared vertices (or split them at seams),
// so without welding no two faces would be neighbours.
#include <gsp/mesh.hpp>

#include <vector>

namespace gsp {

struct WeldResult {
  TriangleMesh mesh;               // welded: positions deduplicated, triangles renumbered
  std::vector<Index> vertex_map;   // input vertex -> welded vertex (to map results back)
  std::size_t merged = 0;          // input vertices that were merged into another one
};

// tolerance = 0 merges bit-identical positions only; > 0 merges positions closer than
// tolerance (absolute, model units) with a grid hash. Faces are kept as they are (a face may
// become degenerate and is then reported by topology, not dropped). Normals, when present,
// are those of the first vertex of each welded group.
WeldResult weld_vertices(const TriangleMesh& mesh, double tolerance = 0.0);

// The rounding noise of CAD exports, as a fraction of the bounding box's diagonal: STL files
// store coordinates that should be equal 1e-15-1e-14 apart (+-3.5e-15 where 0 was meant: the
// sine of pi), which leaves cracks along edges that look welded. On the corpus the noisy pairs
// lie within 1e-12 of the diagonal and the closest distinct vertices farther than 1e-9.
inline constexpr double kWeldNoise = 1e-10;

// Identical positions and positions that differ by rounding noise: each coordinate is rounded
// to a step of kWeldNoise times the bounding box's diagonal before the exact comparison, so
// vertices merge only within sqrt(3) steps of each other (two noisy copies of a point land on
// different sides of a step with a probability of about their distance over the step, 1e-5
// here). As fast as the exact weld (one hash per vertex); what the apps' welding does unless
// a tolerance is given (docs/cli.md).
WeldResult weld_vertices_denoised(const TriangleMesh& mesh);

// How the apps, gsp-exact and the Python package weld an input file: within `tolerance` when
// one is given (> 0), else weld_vertices_denoised.
WeldResult weld_input(const TriangleMesh& mesh, double tolerance);

// Map per-welded-vertex values back to the input's vertices.
template <class T>
std::vector<T> unweld_values(const std::vector<T>& welded, const std::vector<Index>& vertex_map) {
  std::vector<T> out(vertex_map.size());
  for (std::size_t i = 0; i < vertex_map.size(); ++i) out[i] = welded[vertex_map[i]];
  return out;
}

}  // namespace gsp
