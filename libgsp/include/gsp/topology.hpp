#pragma once
// What is wrong (or merely unusual) with a mesh: counted, never repaired.
#include <gsp/connectivity.hpp>

#include <cstdint>

namespace gsp {

struct TopologyReport {
  std::size_t vertices = 0;
  std::size_t faces = 0;
  std::size_t edges = 0;                  // undirected edges (loops from repeated indices excluded)
  std::size_t boundary_edges = 0;         // ring of one
  std::size_t nonmanifold_edges = 0;      // ring of more than two
  std::size_t nonmanifold_vertices = 0;   // faces around the vertex form more than one fan, or it touches a non-manifold edge
  std::size_t inconsistent_edges = 0;     // manifold edges whose two halfedges run the same direction
  std::size_t boundary_loops = 0;         // connected components of the boundary-edge graph
  std::size_t components = 0;             // faces connected through shared vertices (isolated vertices not counted)
  std::size_t repeated_index_faces = 0;   // a face naming the same vertex twice
  std::size_t zero_area_faces = 0;        // area <= 1e-12 * bbox_diagonal^2 (repeated-index faces excluded)
  std::size_t duplicate_faces = 0;        // same vertex set as an earlier face (any order/orientation)
  std::size_t isolated_vertices = 0;      // referenced by no face
  std::int64_t euler_characteristic = 0;  // V - E + F over referenced vertices

  bool is_manifold() const { return nonmanifold_edges == 0 && nonmanifold_vertices == 0; }
  bool is_closed() const { return boundary_edges == 0; }
};

TopologyReport analyze_topology(const TriangleMesh& mesh, const Connectivity& conn);

// Per-face flag: true when the face cannot carry geometry (repeated index or zero area).
std::vector<bool> degenerate_faces(const TriangleMesh& mesh);

// Per-face flag: true when an earlier face (in input order) has the same three vertex indices,
// in any order or orientation (what TopologyReport::duplicate_faces counts).
std::vector<bool> duplicate_faces(const TriangleMesh& mesh);

}  // namespace gsp
