#pragma once
// The connected components of a triangle soup and the topology of each: what a remesh must
// keep per component (Euler characteristic, boundary loops) and what makes a component
// unfit for remeshing (non-manifold edges or vertices, faces that cannot be oriented alike).
//
//   gsp::cvt::ComponentSplit s = gsp::cvt::split_components(mesh);
//   for (const TriangleMesh& c : s.meshes) ... component_topology(c) ...
#include <gsp/mesh.hpp>
#include <gsp/topology.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gsp::cvt {

// Faces connected through shared vertices (as TopologyReport::components counts them), each
// component as its own mesh with only the vertices it uses, in order of first appearance.
// Components are numbered by their first face.
struct ComponentSplit {
  std::vector<TriangleMesh> meshes;
  std::vector<Index> face_component;                 // input face -> component
  std::vector<std::vector<Index>> vertex_ids;        // per component: its vertex -> input vertex
  std::vector<std::vector<Index>> face_ids;          // per component: its face -> input face
};
ComponentSplit split_components(const TriangleMesh& mesh);

// The topology of one component, and the reason it cannot be remeshed as a surface ("" when
// it can): non-manifold edges or vertices, or no consistent orientation (a Moebius-like
// component).
struct ComponentTopology {
  TopologyReport report;
  double area = 0;
  bool orientable = true;    // its faces can be oriented alike (after flipping some)
};
ComponentTopology component_topology(const TriangleMesh& component);

// Flips faces so that every manifold edge is crossed in opposite directions by its two faces,
// keeping the orientation of the first face of each edge-connected part. Returns the number
// of faces flipped, or -1 (and leaves the mesh as it was) when no consistent orientation
// exists.
std::int64_t orient_consistently(TriangleMesh& mesh);

// Boundary vertices at the same position (bit-identical) joined into one: a seam that an
// exporter split (OBJ and PLY files duplicate vertices along texture seams and between the
// parts of a model; the apps weld STL and glTF inputs whole already). Only vertices on a
// boundary edge take part, so two sheets that touch at an interior vertex stay apart (welded,
// they would make a non-manifold edge and the component could not be remeshed). Faces keep
// their order; vertex_map maps every input vertex to its vertex in the result, whose vertices
// keep the input's order less the joined ones.
struct VertexStitch {
  TriangleMesh mesh;
  std::vector<Index> vertex_map;
  std::size_t stitched = 0;   // input vertices joined into an earlier one
};
VertexStitch stitch_boundary_vertices(const TriangleMesh& mesh);

// The surface an input describes, as remesh_surface remeshes it and the topology it must keep
// is measured on: stitch_boundary_vertices, drop_duplicate_faces, split_nonmanifold_vertices.
TriangleMesh described_surface(const TriangleMesh& mesh);

// Faces that are no part of the surface an input describes: a face on the same three vertices
// as an earlier one (either orientation: a soup's doubled or tripled faces, each doubling an
// edge into a non-manifold one) and a face that repeats a vertex. The rest keep their order
// and the vertices are untouched; face_source maps every face of the result to its input face.
struct FaceCleanup {
  TriangleMesh mesh;
  std::vector<Index> face_source;
  std::size_t duplicate_faces = 0, repeated_vertex_faces = 0;   // removed
};
FaceCleanup drop_duplicate_faces(const TriangleMesh& mesh);

// A vertex where two or more fans of faces meet (two cones touching at their tips, two
// boundary loops through one vertex) is one vertex per fan on the surface it describes: each
// fan gets its own copy (at the same position), so the mesh becomes manifold there. Vertices
// on a non-manifold edge are left alone (no split makes those manifold). Faces keep their
// order; vertex_source maps every vertex of the result to the input vertex it copies.
struct VertexSplit {
  TriangleMesh mesh;
  std::vector<Index> vertex_source;
  std::size_t split = 0;   // input vertices that were split
};
VertexSplit split_nonmanifold_vertices(const TriangleMesh& mesh);

// Referenced vertices whose position equals that of another referenced vertex (bit-identical):
// a remesh must have none.
std::size_t duplicate_vertices(const TriangleMesh& mesh);

// Multiset comparison of the per-component (Euler characteristic, boundary loops) of two
// meshes, plus manifoldness, consistent orientation and duplicate vertices of `output`: true
// when `output` is a manifold, consistently oriented surface with the topology of `input`
// component by component. `why` gets the first difference found; `defects`, when given, how
// many places of `output` are wrong (non-manifold edges and vertices, inconsistently oriented
// edges, duplicate vertices; 0 when only the components' topology differs).
bool same_topology_per_component(const TriangleMesh& input, const TriangleMesh& output, std::string* why = nullptr,
                                 std::size_t* defects = nullptr);

}  // namespace gsp::cvt
