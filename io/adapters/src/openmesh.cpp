#include <gsp/adapters/openmesh.hpp>
#include <gsp/errors.hpp>

#include <OpenMesh/Core/System/omstream.hh>

namespace gsp::adapters {

namespace {

// OpenMesh reports a refused face on its global error stream; library code must not print,
// so the stream is muted for the duration of one conversion and restored afterwards.
class MuteOpenMeshErrors {
 public:
  MuteOpenMeshErrors() : was_enabled_(omerr().is_enabled()) { omerr().disable(); }
  ~MuteOpenMeshErrors() {
    if (was_enabled_) omerr().enable();
  }
  MuteOpenMeshErrors(const MuteOpenMeshErrors&) = delete;
  MuteOpenMeshErrors& operator=(const MuteOpenMeshErrors&) = delete;

 private:
  bool was_enabled_;
};

template <class Mesh>
ToOpenMeshResult<Mesh> to_openmesh_impl(const TriangleMesh& mesh) {
  using Point = typename Mesh::Point;
  using Normal = typename Mesh::Normal;
  using Scalar = typename Point::value_type;
  validate(mesh);
  ToOpenMeshResult<Mesh> out;
  Mesh& om = out.mesh;
  om.reserve(mesh.num_vertices(), 3 * mesh.num_faces(), mesh.num_faces());
  for (const Vec3& p : mesh.positions)
    om.add_vertex(Point(static_cast<Scalar>(p.x), static_cast<Scalar>(p.y), static_cast<Scalar>(p.z)));
  if (!mesh.normals.empty()) {
    om.request_vertex_normals();
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
      const Vec3& n = mesh.normals[i];
      om.set_normal(OpenMesh::VertexHandle(static_cast<int>(i)),
                    Normal(static_cast<Scalar>(n.x), static_cast<Scalar>(n.y), static_cast<Scalar>(n.z)));
    }
  }
  MuteOpenMeshErrors mute;
  out.face_map.reserve(mesh.num_faces());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    // OpenMesh does not check for a repeated corner before linking halfedges.
    if (repeats_vertex(t)) {
      out.skipped_faces.push_back(static_cast<Index>(f));
      continue;
    }
    const auto added = om.add_face(OpenMesh::VertexHandle(static_cast<int>(t[0])),
                                   OpenMesh::VertexHandle(static_cast<int>(t[1])),
                                   OpenMesh::VertexHandle(static_cast<int>(t[2])));
    if (added.is_valid())
      out.face_map.push_back(static_cast<Index>(f));
    else
      out.skipped_faces.push_back(static_cast<Index>(f));
  }
  return out;
}

template <class Mesh>
TriangleMesh from_openmesh_impl(const Mesh& om) {
  TriangleMesh out;
  std::vector<Index> new_index(om.n_vertices(), kInvalidIndex);
  out.positions.reserve(om.n_vertices());
  const bool has_normals = om.has_vertex_normals();
  for (auto v : om.vertices()) {
    new_index[static_cast<std::size_t>(v.idx())] = static_cast<Index>(out.positions.size());
    const auto& p = om.point(v);
    out.positions.push_back({double(p[0]), double(p[1]), double(p[2])});
    if (has_normals) {
      const auto& n = om.normal(v);
      out.normals.push_back({double(n[0]), double(n[1]), double(n[2])});
    }
  }
  out.triangles.reserve(om.n_faces());
  std::vector<Index> corners;
  for (auto f : om.faces()) {
    corners.clear();
    for (auto v : om.fv_range(f)) corners.push_back(new_index[static_cast<std::size_t>(v.idx())]);
    for (std::size_t i = 1; i + 1 < corners.size(); ++i)
      out.triangles.push_back({corners[0], corners[i], corners[i + 1]});
  }
  return out;
}

}  // namespace

ToOpenMeshResult<OpenMeshTriMesh> to_openmesh(const TriangleMesh& mesh) {
  return to_openmesh_impl<OpenMeshTriMesh>(mesh);
}
ToOpenMeshResult<OpenMeshTriMeshD> to_openmesh_double(const TriangleMesh& mesh) {
  return to_openmesh_impl<OpenMeshTriMeshD>(mesh);
}
TriangleMesh from_openmesh(const OpenMeshTriMesh& mesh) { return from_openmesh_impl(mesh); }
TriangleMesh from_openmesh(const OpenMeshTriMeshD& mesh) { return from_openmesh_impl(mesh); }

}  // namespace gsp::adapters
