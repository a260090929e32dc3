#pragma once
// One writer per format (write_<format>.cpp); write_mesh() in mesh_io.cpp picks one by
// extension after check_writable(). Every writer builds its output through AtomicFile.
#include <gsp/io/mesh_io.hpp>

#include <string>

namespace gsp::io::detail {

// Indices in range and one attribute entry per vertex; throws gsp::InvalidInput otherwise.
void check_writable(const TriangleMesh& mesh, const VertexAttributes& attributes);

void write_ply(const std::string& path, const TriangleMesh& mesh, const VertexAttributes& attributes, bool ascii);
void write_obj(const std::string& path, const TriangleMesh& mesh, const VertexAttributes& attributes);
void write_off(const std::string& path, const TriangleMesh& mesh, const VertexAttributes& attributes);
void write_gltf(const std::string& path, const TriangleMesh& mesh, const VertexAttributes& attributes, bool binary);

// Shortest text that reads back as exactly `v` (std::to_chars), appended to `out`.
void append_number(std::string& out, double v);
void append_number(std::string& out, float v);
void append_number(std::string& out, long long v);

}  // namespace gsp::io::detail
