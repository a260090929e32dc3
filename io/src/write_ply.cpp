// PLY writer: binary little-endian (default) or ascii. Vertex: float x y z, float nx ny nz when
// the mesh has normals, `float NAME` per scalar attribute, `int NAME` per label, uchar
// red green blue alpha for colours. Face: list uchar int vertex_indices.
#include <gsp/io/atomic_file.hpp>

#include "writers.hpp"

#include <cstring>

namespace gsp::io::detail {

namespace {

template <class T>
void put(std::string& out, T v) {   // little-endian hosts only (x86/ARM), like the readers
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}

}  // namespace

void write_ply(const std::string& path, const TriangleMesh& mesh, const VertexAttributes& attributes, bool ascii) {
  const bool normals = !mesh.normals.empty();
  const bool colors = !attributes.colors.empty();
  std::string out = "ply\n";
  out += ascii ? "format ascii 1.0\n" : "format binary_little_endian 1.0\n";
  out += "comment written by gsp\n";
  out += "element vertex " + std::to_string(mesh.num_vertices()) + "\n";
  out += "property float x\nproperty float y\nproperty float z\n";
  if (normals) out += "property float nx\nproperty float ny\nproperty float nz\n";
  for (const auto& s : attributes.scalars) out += "property float " + s.first + "\n";
  for (const auto& l : attributes.labels) out += "property int " + l.first + "\n";
  if (colors) out += "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n";
  out += "element face " + std::to_string(mesh.num_faces()) + "\n";
  out += "property list uchar int vertex_indices\nend_header\n";

  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    float f[6] = {float(mesh.positions[v].x), float(mesh.positions[v].y), float(mesh.positions[v].z)};
    if (normals) {
      f[3] = float(mesh.normals[v].x);
      f[4] = float(mesh.normals[v].y);
      f[5] = float(mesh.normals[v].z);
    }
    const int nf = normals ? 6 : 3;
    if (ascii) {
      for (int k = 0; k < nf; ++k) {
        if (k) out += ' ';
        append_number(out, f[k]);
      }
      for (const auto& s : attributes.scalars) {
        out += ' ';
        append_number(out, s.second[v]);
      }
      for (const auto& l : attributes.labels) {
        out += ' ';
        append_number(out, static_cast<long long>(l.second[v]));
      }
      if (colors)
        for (int k = 0; k < 4; ++k) {
          out += ' ';
          append_number(out, static_cast<long long>(attributes.colors[v][k]));
        }
      out += '\n';
    } else {
      for (int k = 0; k < nf; ++k) put(out, f[k]);
      for (const auto& s : attributes.scalars) put(out, s.second[v]);
      for (const auto& l : attributes.labels) put(out, l.second[v]);
      if (colors) out.append(reinterpret_cast<const char*>(attributes.colors[v].data()), 4);
    }
  }
  for (const Triangle& t : mesh.triangles) {
    if (ascii) {
      out += '3';
      for (Index i : t) {
        out += ' ';
        append_number(out, static_cast<long long>(i));
      }
      out += '\n';
    } else {
      put(out, std::uint8_t(3));
      for (Index i : t) put(out, static_cast<std::int32_t>(i));
    }
  }
  AtomicFile file(path);
  file.write(out.data(), out.size());
  file.commit();
}

}  // namespace gsp::io::detail
