// OBJ writer: `v x y z` (with ` r g b` in 0..1 when there are colours, MeshLab's extension),
// `vn` when the mesh has normals, `f a b c` 1-based (`a//a` with normals). Numbers are the
// shortest text that reads back to the same double, so positions round-trip exactly.
#include <gsp/io/atomic_file.hpp>

#include "writers.hpp"

namespace gsp::io::detail {

void write_obj(const std::string& path, const TriangleMesh& mesh, const VertexAttributes& attributes) {
  const bool normals = !mesh.normals.empty();
  const bool colors = !attributes.colors.empty();
  std::string out = "# written by gsp: " + std::to_string(mesh.num_vertices()) + " vertices, " +
                    std::to_string(mesh.num_faces()) + " faces\n";
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    out += "v ";
    append_number(out, mesh.positions[v].x);
    out += ' ';
    append_number(out, mesh.positions[v].y);
    out += ' ';
    append_number(out, mesh.positions[v].z);
    if (colors)
      for (int k = 0; k < 3; ++k) {
        out += ' ';
        append_number(out, attributes.colors[v][k] / 255.0);
      }
    out += '\n';
  }
  if (normals)
    for (const Vec3& n : mesh.normals) {
      out += "vn ";
      append_number(out, n.x);
      out += ' ';
      append_number(out, n.y);
      out += ' ';
      append_number(out, n.z);
      out += '\n';
    }
  for (const Triangle& t : mesh.triangles) {
    out += 'f';
    for (Index i : t) {
      out += ' ';
      append_number(out, static_cast<long long>(i) + 1);
      if (normals) {
        out += "//";
        append_number(out, static_cast<long long>(i) + 1);
      }
    }
    out += '\n';
  }
  AtomicFile file(path);
  file.write(out.data(), out.size());
  file.commit();
}

}  // namespace gsp::io::detail
