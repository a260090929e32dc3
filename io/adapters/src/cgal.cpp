#include <gsp/adapters/cgal.hpp>
#include <gsp/errors.hpp>

#include <array>
#include <string>

namespace gsp::adapters {

namespace {
using VertexIndex = CgalSurfaceMesh::Vertex_index;
using FaceIndex = CgalSurfaceMesh::Face_index;
using Vector3 = CgalKernel::Vector_3;
}  // namespace

ToCgalResult to_cgal(const TriangleMesh& mesh) {
  validate(mesh);
  ToCgalResult out;
  CgalSurfaceMesh& sm = out.mesh;
  sm.reserve(static_cast<CgalSurfaceMesh::size_type>(mesh.num_vertices()),
             static_cast<CgalSurfaceMesh::size_type>(3 * mesh.num_faces()),
             static_cast<CgalSurfaceMesh::size_type>(mesh.num_faces()));
  for (const Vec3& p : mesh.positions) sm.add_vertex(CgalKernel::Point_3(p.x, p.y, p.z));
  if (!mesh.normals.empty()) {
    auto normals = sm.add_property_map<VertexIndex, Vector3>("v:normal").first;
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
      const Vec3& n = mesh.normals[i];
      normals[VertexIndex(static_cast<CgalSurfaceMesh::size_type>(i))] = Vector3(n.x, n.y, n.z);
    }
  }
  out.face_map.reserve(mesh.num_faces());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    // Euler::add_face checks repeated corners, complex vertices and edges itself and answers
    // null_face() instead of breaking the structure.
    const FaceIndex added = sm.add_face(VertexIndex(t[0]), VertexIndex(t[1]), VertexIndex(t[2]));
    if (added == CgalSurfaceMesh::null_face())
      out.skipped_faces.push_back(static_cast<Index>(f));
    else
      out.face_map.push_back(static_cast<Index>(f));
  }
  return out;
}

TriangleMesh from_cgal(const CgalSurfaceMesh& sm) {
  TriangleMesh out;
  std::vector<Index> new_index(sm.num_vertices(), kInvalidIndex);
  out.positions.reserve(sm.number_of_vertices());
  for (VertexIndex v : sm.vertices()) {
    new_index[static_cast<std::size_t>(v)] = static_cast<Index>(out.positions.size());
    const auto& p = sm.point(v);
    out.positions.push_back({p.x(), p.y(), p.z()});
  }
  // CGAL 5.5 answers (map, found); later versions an optional.
  const auto normals = sm.property_map<VertexIndex, Vector3>("v:normal");
  if (normals.second) {
    out.normals.reserve(out.positions.size());
    for (VertexIndex v : sm.vertices()) {
      const Vector3& n = normals.first[v];
      out.normals.push_back({n.x(), n.y(), n.z()});
    }
  }
  out.triangles.reserve(sm.number_of_faces());
  std::vector<Index> corners;
  for (FaceIndex f : sm.faces()) {
    corners.clear();
    for (VertexIndex v : sm.vertices_around_face(sm.halfedge(f)))
      corners.push_back(new_index[static_cast<std::size_t>(v)]);
    for (std::size_t i = 1; i + 1 < corners.size(); ++i)
      out.triangles.push_back({corners[0], corners[i], corners[i + 1]});
  }
  return out;
}

}  // namespace gsp::adapters
