#pragma once
// gsp::TriangleMesh <-> OpenMesh::TriMesh_ArrayKernelT (target gsp::openmesh_adapter).
//
// OpenMesh's default mesh stores float points: converting to it rounds positions to float.
// OpenMeshTriMeshD keeps doubles. Like every halfedge structure, OpenMesh refuses faces that
// would make an edge or vertex non-manifold (and faces naming a vertex twice); those faces are
// skipped and reported instead of printed.
#include <gsp/mesh.hpp>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <vector>

namespace gsp::adapters {

using OpenMeshTriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

struct OpenMeshDoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OpenMeshTriMeshD = OpenMesh::TriMesh_ArrayKernelT<OpenMeshDoubleTraits>;

template <class Mesh>
struct ToOpenMeshResult {
  Mesh mesh;                         // vertex i is input vertex i (isolated vertices kept)
  std::vector<Index> face_map;       // OpenMesh face index -> input face
  std::vector<Index> skipped_faces;  // input faces OpenMesh refused, ascending
};

// Faces are added in input order. Vertex normals are requested and filled when the mesh
// has normals. OpenMesh's own error stream is silenced during the conversion (it would
// print one line per refused face); that stream is process-wide, so other threads' OpenMesh
// messages are muted meanwhile too. Throws InvalidInput for indices out of range.
ToOpenMeshResult<OpenMeshTriMesh> to_openmesh(const TriangleMesh& mesh);
ToOpenMeshResult<OpenMeshTriMeshD> to_openmesh_double(const TriangleMesh& mesh);

// Vertices in handle order, deleted elements skipped; vertex normals copied when present.
TriangleMesh from_openmesh(const OpenMeshTriMesh& mesh);
TriangleMesh from_openmesh(const OpenMeshTriMeshD& mesh);

}  // namespace gsp::adapters
