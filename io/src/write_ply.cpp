// PLY writer: binary little-endian (default) or ascii. Vertex: float x y z, float nx ny nz when
// the mesh has normals, `float NAME` per scalar attribute, `int NAME` per label, uchar
// red green blue alpha for colours. Face: list uchar int vertex_indices.
#include <gsp/io/atomic_file.hpp>

#include "writers.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

namespace gsp::io::detail {

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

  if (!ascii) {
    // Binary: fixed-size records built in a buffer of at most 4 MB that is written out whenever
    // full (one buffer for the whole body meant zero-filling and faulting in 100 MB at 2.2M
    // vertices; appending value by value, before that, regrew and copied it). The buffer is
    // no larger than the body and left uninitialised: a zeroed 4 MB buffer was 1,024 page
    // faults, 15 ms of a 19 ms run on a single triangle.
    const std::size_t per_vertex = 4 * (3 + (normals ? 3 : 0) + attributes.scalars.size() + attributes.labels.size()) +
                                   (colors ? 4 : 0);
    const std::size_t body = per_vertex * mesh.num_vertices() + 13 * mesh.num_faces();
    const std::size_t capacity = std::max({std::min(body, std::size_t(1) << 22), per_vertex, std::size_t(13)});
    AtomicFile file(path);
    file.write(out.data(), out.size());
    const std::unique_ptr<char[]> buffer(new char[capacity]);
    char* at = buffer.get();
    auto room = [&](std::size_t n) {
      if (std::size_t(buffer.get() + capacity - at) < n) {
        file.write(buffer.get(), std::size_t(at - buffer.get()));
        at = buffer.get();
      }
    };
    auto put_raw = [&at](const void* p, std::size_t n) {   // little-endian hosts only, like the readers
      std::memcpy(at, p, n);
      at += n;
    };
    for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
      room(per_vertex);
      const float xyz[3] = {float(mesh.positions[v].x), float(mesh.positions[v].y), float(mesh.positions[v].z)};
      put_raw(xyz, sizeof xyz);
      if (normals) {
        const float n[3] = {float(mesh.normals[v].x), float(mesh.normals[v].y), float(mesh.normals[v].z)};
        put_raw(n, sizeof n);
      }
      for (const auto& sc : attributes.scalars) put_raw(&sc.second[v], 4);
      for (const auto& l : attributes.labels) put_raw(&l.second[v], 4);
      if (colors) put_raw(attributes.colors[v].data(), 4);
    }
    for (const Triangle& t : mesh.triangles) {
      room(13);
      const std::uint8_t three = 3;
      put_raw(&three, 1);
      for (Index i : t) {
        const std::int32_t k = static_cast<std::int32_t>(i);
        put_raw(&k, 4);
      }
    }
    file.write(buffer.get(), std::size_t(at - buffer.get()));
    file.commit();
    return;
  } else {
    for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
      float f[6] = {float(mesh.positions[v].x), float(mesh.positions[v].y), float(mesh.positions[v].z)};
      if (normals) {
        f[3] = float(mesh.normals[v].x);
        f[4] = float(mesh.normals[v].y);
        f[5] = float(mesh.normals[v].z);
      }
      const int nf = normals ? 6 : 3;
      for (int k = 0; k < nf; ++k) {
        if (k) out += ' ';
        append_number(out, f[k]);
      }
      for (const auto& sc : attributes.scalars) {
        out += ' ';
        append_number(out, sc.second[v]);
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
    }
    for (const Triangle& t : mesh.triangles) {
      out += '3';
      for (Index i : t) {
        out += ' ';
        append_number(out, static_cast<long long>(i));
      }
      out += '\n';
    }
  }
  AtomicFile file(path);
  file.write(out.data(), out.size());
  file.commit();
}

}  // namespace gsp::io::detail
