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

// Map per-welded-vertex values back to the input's vertices.
template <class T>
std::vector<T> unweld_values(const std::vector<T>& welded, const std::vector<Index>& vertex_map) {
  std::vector<T> out(vertex_map.size());
  for (std::size_t i = 0; i < vertex_map.size(); ++i) out[i] = welded[vertex_map[i]];
  return out;
}

}  // namespace gsp
