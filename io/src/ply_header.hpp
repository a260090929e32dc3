#pragma once
// A PLY header: elements, their properties and the encoding of the body (read_ply.cpp reads
// the body serially, read_ply_parallel.cpp an ascii body on several threads).
#include <gsp/io/mesh_io.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gsp::io::detail {

enum class PlyType { i8, u8, i16, u16, i32, u32, f32, f64 };

std::size_t type_size(PlyType t);
inline bool is_integer(PlyType t) { return t != PlyType::f32 && t != PlyType::f64; }

struct PlyProperty {
  std::string name;
  bool list = false;
  PlyType count_type = PlyType::u8, type = PlyType::f32;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> props;
  std::size_t header_line = 0;
};

enum class PlyEncoding { ascii, little, big };

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::ascii;
  std::vector<PlyElement> elements;
  std::size_t body = 0;          // byte offset of the body
  std::size_t body_line = 0;     // line number (1-based) where an ascii body starts
};

// Throws IoError (no magic, unknown format or type, malformed lines, no end_header).
PlyHeader read_ply_header(const std::string& path, const std::string& bytes);

// What each vertex property is used for.
enum class Role { skip, x, y, z, nx, ny, nz, red, green, blue, alpha, scalar, label };

struct VertexRoles {
  std::vector<Role> role;            // per property
  std::vector<std::size_t> slot;     // per property: index into scalars or labels
  bool normals = false, colors = false;
};

// The roles of the vertex element's properties; adds the scalar and label arrays to `r`
// (empty), notes about skipped list properties, and throws when x, y or z is missing.
VertexRoles vertex_roles(const std::string& path, const PlyElement& e, ReadResult& r);

// Colour channel or coordinate from a property value: colours stored as floats are 0..1.
inline double role_value(Role role, PlyType type, double x) {
  return role >= Role::red && !is_integer(type) ? x * 255.0 : x;
}

inline std::uint8_t color_byte(double c) {
  return static_cast<std::uint8_t>(std::isfinite(c) ? std::lround(std::clamp(c, 0.0, 255.0)) : 0);
}

inline std::int32_t label_value(double x) {
  return static_cast<std::int32_t>(std::clamp(x, -2147483648.0, 2147483647.0));
}

// A PLY ascii body read on `threads` threads into `r` (whose header-derived parts are set);
// false, with `r`'s arrays in any state, when the body is not the plain layout this handles
// (one vertex or face per line, triangles only, nothing but a vertex and a face element) or
// anything in it is irregular: the serial reader then reads it and names the error.
bool read_ply_ascii_parallel(std::string_view body, const PlyHeader& header, const VertexRoles& roles,
                             unsigned threads, ReadResult& r);

}  // namespace gsp::io::detail
