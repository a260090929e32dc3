#pragma once
// gsp::TriangleMesh <-> CGAL::Surface_mesh (target gsp::cgal_adapter; GPL because of CGAL).
//
// A Surface_mesh is a halfedge structure: it cannot hold an edge with more than two faces, a
// vertex whose faces would close into a second fan, or a face naming a vertex twice. Such
// faces are not added; their input indices are returned so the caller can decide what to do.
#include <gsp/mesh.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <vector>

namespace gsp::adapters {

using CgalKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalSurfaceMesh = CGAL::Surface_mesh<CgalKernel::Point_3>;

struct ToCgalResult {
  CgalSurfaceMesh mesh;              // vertex i is input vertex i (isolated vertices kept)
  std::vector<Index> face_map;       // CGAL face index -> input face
  std::vector<Index> skipped_faces;  // input faces the halfedge structure refused, ascending
};

// Faces are added in input order, so which face of a non-manifold fan is skipped is the
// later one. Normals are stored as the vertex property "v:normal" when the mesh has them.
// Throws InvalidInput for indices out of range (see gsp::validate).
ToCgalResult to_cgal(const TriangleMesh& mesh);

// Vertices in the order of the Surface_mesh's valid vertex indices (removed elements that
// were not yet garbage-collected are skipped); polygons with more than three corners are
// fan-triangulated. "v:normal" (CgalKernel::Vector_3) is copied when present.
TriangleMesh from_cgal(const CgalSurfaceMesh& mesh);

}  // namespace gsp::adapters
