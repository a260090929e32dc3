#pragma once
// A checked copy of a mesh in the shape CGAL's halfedge algorithms need: every component a
// consistently oriented 2-manifold (with or without boundary), without degenerate faces and
// without isolated vertices. Internal to gsp::reference; CGAL-free, so the checks compile fast.
#include <gsp/mesh.hpp>

#include <vector>

namespace gsp::reference::detail {

struct SurfaceComponent {
  TriangleMesh mesh;            // compact numbering; faces re-oriented where needed
  std::vector<Index> vertices;  // local vertex -> input vertex (ascending)
  std::vector<Index> faces;     // local face -> input face (ascending)
};

struct ManifoldSurface {
  std::size_t num_input_vertices = 0;
  std::size_t num_input_faces = 0;
  std::vector<SurfaceComponent> components;
  // Input vertex -> component and local index; kInvalidIndex for vertices no face references.
  std::vector<Index> vertex_component, vertex_local;
  // Input face -> component and local index.
  std::vector<Index> face_component, face_local;
  std::size_t isolated_vertices = 0;
  std::size_t flipped_faces = 0;  // faces turned around to make the orientation consistent
};

// Throws InvalidInput (see gsp::validate) or TopologyError naming the first offending face,
// edge or vertex: no faces, a face repeating a vertex, a zero-area face (area <= 1e-12 *
// bbox diagonal^2, the definition of topology.hpp), an edge with more than two faces, a
// vertex whose faces form more than one fan, or a component that cannot be oriented.
ManifoldSurface make_manifold_surface(const TriangleMesh& mesh);

}  // namespace gsp::reference::detail
