// OFF writer (COFF with an RGBA 0..255 colour per vertex when there are colours).
#include <gsp/io/atomic_file.hpp>

#include "writers.hpp"

namespace gsp::io::detail {

void write_off(const std::string& path, const TriangleMesh& mesh, const VertexAttributes& attributes) {
  const bool colors = !attributes.colors.empty();
  std::string out = colors ? "COFF\n" : "OFF\n";
  out += std::to_string(mesh.num_vertices()) + " " + std::to_string(mesh.num_faces()) + " 0\n";
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    append_number(out, mesh.positions[v].x);
    out += ' ';
    append_number(out, mesh.positions[v].y);
    out += ' ';
    append_number(out, mesh.positions[v].z);
    if (colors)
      for (int k = 0; k < 4; ++k) {
        out += ' ';
        append_number(out, static_cast<long long>(attributes.colors[v][k]));
      }
    out += '\n';
  }
  for (const Triangle& t : mesh.triangles) {
    out += '3';
    for (Index i : t) {
      out += ' ';
      append_number(out, static_cast<long long>(i));
    }
    out += '\n';
  }
  AtomicFile file(path);
  file.write(out.data(), out.size());
  file.commit();
}

}  // namespace gsp::io::detail
