// Shared by the writers: input checks and exact number formatting.
#include "writers.hpp"

#include <charconv>

namespace gsp::io::detail {

void check_writable(const TriangleMesh& mesh, const VertexAttributes& attributes) {
  const std::size_t n = mesh.num_vertices();
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (Index v : mesh.triangles[f])
      if (v >= n)
        throw InvalidInput("cannot write: face " + std::to_string(f) + " names vertex " + std::to_string(v) + " of " +
                           std::to_string(n));
  for (std::size_t v = 0; v < n; ++v)
    if (!is_finite(mesh.positions[v]))
      throw InvalidInput("cannot write: vertex " + std::to_string(v) + " has a non-finite coordinate");
  if (!mesh.normals.empty() && mesh.normals.size() != n)
    throw InvalidInput("cannot write: " + std::to_string(mesh.normals.size()) + " normals for " + std::to_string(n) + " vertices");
  auto check = [n](const std::string& name, std::size_t size) {
    // Names become PLY property names and glTF attribute names: one plain token.
    if (name.empty() || name.find_first_of(" \t\r\n") != std::string::npos)
      throw InvalidInput("cannot write: attribute name '" + name + "' must be one word");
    if (size != n)
      throw InvalidInput("cannot write: attribute '" + name + "' has " + std::to_string(size) + " values for " +
                         std::to_string(n) + " vertices");
  };
  for (const auto& [name, v] : attributes.scalars) check(name, v.size());
  for (const auto& [name, v] : attributes.labels) check(name, v.size());
  if (!attributes.colors.empty()) check("colors", attributes.colors.size());
}

template <class T>
static void append(std::string& out, T v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void append_number(std::string& out, double v) { append(out, v); }
void append_number(std::string& out, float v) { append(out, v); }
void append_number(std::string& out, long long v) { append(out, v); }

}  // namespace gsp::io::detail
