// PLY in all three encodings. The header is parsed into elements and properties first
// (ply_header.cpp); the body is then read element by element with one generic property reader,
// so that properties and elements we do not use (lists included) are skipped exactly as they
// are laid out. A big ascii body of the plain layout is read on several threads first
// (read_ply_parallel.cpp); this serial reader is the reference and names every error.
#include "parse_util.hpp"
#include "ply_header.hpp"
#include "readers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace gsp::io::detail {

namespace {

struct Reader {
  const std::string& path;
  PlyEncoding enc;
  ByteCursor* bin = nullptr;
  TokenScanner* text = nullptr;

  double scalar(PlyType t) {
    if (enc == PlyEncoding::ascii) {
      if (is_integer(t)) return static_cast<double>(text->need_int("an integer property value"));
      const double v = text->need_double("a property value");
      return t == PlyType::f32 ? static_cast<float>(v) : v;   // a float property holds a float
    }
    const bool be = enc == PlyEncoding::big;
    switch (t) {
      case PlyType::i8: return bin->read<std::int8_t>(be, "a char property");
      case PlyType::u8: return bin->read<std::uint8_t>(be, "a uchar property");
      case PlyType::i16: return bin->read<std::int16_t>(be, "a short property");
      case PlyType::u16: return bin->read<std::uint16_t>(be, "a ushort property");
      case PlyType::i32: return bin->read<std::int32_t>(be, "an int property");
      case PlyType::u32: return bin->read<std::uint32_t>(be, "a uint property");
      case PlyType::f32: return bin->read<float>(be, "a float property");
      case PlyType::f64: return bin->read<double>(be, "a double property");
    }
    return 0;
  }
  // A list length: validated against what the rest of the file can hold.
  std::uint64_t list_count(const PlyProperty& p) {
    if (enc == PlyEncoding::ascii) {
      const long long n = text->need_int("a list length");
      if (n < 0) text->fail("negative list length " + std::to_string(n));
      if (static_cast<std::uint64_t>(n) > text->remaining_bytes())
        text->fail("list length " + std::to_string(n) + " exceeds the rest of the file");
      return static_cast<std::uint64_t>(n);
    }
    const std::size_t at = bin->pos();
    const double v = scalar(p.count_type);
    if (v < 0) throw IoError(path, byte_at(at), "negative list length " + std::to_string(static_cast<long long>(v)));
    const auto n = static_cast<std::uint64_t>(v);
    if (n * type_size(p.type) > bin->remaining())
      throw IoError(path, byte_at(at), "truncated: list of " + std::to_string(n) + " entries needs " +
                                           std::to_string(n * type_size(p.type)) + " bytes, " +
                                           std::to_string(bin->remaining()) + " left");
    return n;
  }
  void skip(const PlyProperty& p) {
    const std::uint64_t n = p.list ? list_count(p) : 1;
    if (enc == PlyEncoding::ascii) {
      for (std::uint64_t i = 0; i < n; ++i) text->need("a property value");
    } else {
      bin->skip(static_cast<std::size_t>(n * type_size(p.type)), "a property");
    }
  }
  // Where the next value starts (a line or a byte), kept per element as a number and spelt
  // out only for an error: formatting it for every vertex and face cost 5% of a whole
  // gsp-geodesic run on a binary PLY.
  std::size_t mark() { return enc == PlyEncoding::ascii ? text->next_line_number() : bin->pos(); }
  std::string describe(std::size_t mark) const { return enc == PlyEncoding::ascii ? line_at(mark) : byte_at(mark); }
  std::size_t remaining() const { return enc == PlyEncoding::ascii ? text->remaining_bytes() : bin->remaining(); }
};

// An index as read, for a message: a float list can hold values no integer type holds (casting
// 4e22 to long long is undefined; a fuzz finding), and NaN.
std::string index_text(double idx) {
  if (!std::isfinite(idx)) return "-1";
  if (std::abs(idx) < 9e18 && idx == std::floor(idx)) return std::to_string(static_cast<long long>(idx));
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", idx);
  return text;
}

// Fewest bytes one instance of `e` can occupy; used to reject absurd counts before reserving.
std::uint64_t min_instance_bytes(const PlyElement& e, PlyEncoding enc) {
  std::uint64_t b = 0;
  for (const PlyProperty& p : e.props)
    b += enc == PlyEncoding::ascii ? 2 : type_size(p.list ? p.count_type : p.type);
  return b;
}

void read_vertices(const std::string& path, const PlyElement& e, const VertexRoles& roles, std::size_t can_hold,
                   Reader& rd, ReadResult& r) {
  TriangleMesh& m = r.mesh;
  m.positions.reserve(can_hold);
  if (roles.normals) m.normals.reserve(can_hold);
  if (roles.colors) r.attributes.colors.reserve(can_hold);
  for (auto& s : r.attributes.scalars) s.second.reserve(can_hold);
  for (auto& l : r.attributes.labels) l.second.reserve(can_hold);
  for (std::uint64_t i = 0; i < e.count; ++i) {
    const std::size_t where = rd.mark();
    double v[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 255};
    for (std::size_t k = 0; k < e.props.size(); ++k) {
      const PlyProperty& p = e.props[k];
      const Role role = roles.role[k];
      if (role == Role::skip) {
        rd.skip(p);
        continue;
      }
      const double x = rd.scalar(p.type);
      if (role == Role::scalar) {
        r.attributes.scalars[roles.slot[k]].second.push_back(static_cast<float>(x));
      } else if (role == Role::label) {
        r.attributes.labels[roles.slot[k]].second.push_back(label_value(x));
      } else {
        v[static_cast<int>(role) - 1] = role_value(role, p.type, x);
      }
    }
    if (!finite3(v[0], v[1], v[2]))
      throw IoError(path, rd.describe(where), "vertex " + std::to_string(i) + " has a non-finite coordinate");
    m.positions.push_back({v[0], v[1], v[2]});
    if (roles.normals) m.normals.push_back({v[3], v[4], v[5]});
    if (roles.colors) r.attributes.colors.push_back({color_byte(v[6]), color_byte(v[7]), color_byte(v[8]), color_byte(v[9])});
  }
}

void read_faces(const std::string& path, const PlyElement& e, std::uint64_t num_vertices, std::size_t can_hold,
                Reader& rd, ReadResult& r) {
  TriangleMesh& m = r.mesh;
  std::size_t index_prop = e.props.size();
  for (std::size_t k = 0; k < e.props.size(); ++k)
    if (e.props[k].list && (e.props[k].name == "vertex_indices" || e.props[k].name == "vertex_index")) index_prop = k;
  if (index_prop == e.props.size() && e.count > 0)
    throw IoError(path, line_at(e.header_line), "face element has no vertex_indices list");
  m.triangles.reserve(can_hold);
  std::vector<Index> corners;
  for (std::uint64_t i = 0; i < e.count; ++i) {
    for (std::size_t k = 0; k < e.props.size(); ++k) {
      const PlyProperty& p = e.props[k];
      if (k != index_prop) {
        rd.skip(p);
        continue;
      }
      const std::size_t where = rd.mark();
      const std::uint64_t n = rd.list_count(p);
      if (n < 3)
        throw IoError(path, rd.describe(where), "face " + std::to_string(i) + " has " + std::to_string(n) + " corners (at least 3 needed)");
      corners.clear();
      for (std::uint64_t c = 0; c < n; ++c) {
        const double idx = rd.scalar(p.type);
        if (!(idx >= 0 && idx < static_cast<double>(num_vertices)) || idx != std::floor(idx))
          throw IoError(path, rd.describe(where), "face " + std::to_string(i) + ": vertex index " + index_text(idx) +
                                         " out of range (" + std::to_string(num_vertices) + " vertices)");
        corners.push_back(static_cast<Index>(idx));
      }
      if (n > 3) ++r.info.polygons_split;
      add_fan(m.triangles, corners.data(), corners.size());
    }
  }
}

}  // namespace

ReadResult read_ply(const std::string& path, const std::string& bytes, unsigned threads) {
  ReadResult r;
  r.info.format = Format::ply;
  const PlyHeader header = read_ply_header(path, bytes);
  const PlyEncoding enc = header.encoding;
  r.info.binary = enc != PlyEncoding::ascii;

  ByteCursor bin(path, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), header.body);
  const std::string_view body = std::string_view(bytes).substr(header.body);
  TokenScanner text(path, body, header.body_line);
  Reader rd{path, enc, &bin, &text};

  const PlyElement* vertex_el = nullptr;
  for (const PlyElement& e : header.elements)
    if (e.name == "vertex") vertex_el = &e;
  const std::uint64_t num_vertices = vertex_el ? vertex_el->count : 0;
  if (num_vertices >= kInvalidIndex) throw IoError(path, line_at(vertex_el->header_line), "too many vertices for 32-bit indices");

  if (enc == PlyEncoding::ascii && vertex_el && threads > 1) {
    ReadResult fast = r;
    bool plain = true;
    VertexRoles roles;
    try {
      roles = vertex_roles(path, *vertex_el, fast);
    } catch (const IoError&) {
      plain = false;   // the serial reader reports it, after the checks that come first
    }
    if (plain && read_ply_ascii_parallel(body, header, roles, threads, fast)) return fast;
  }

  for (const PlyElement& e : header.elements) {
    // Reject counts the file cannot hold before anything is reserved for them.
    const std::uint64_t min_bytes = min_instance_bytes(e, enc);
    if (min_bytes > 0 && e.count > rd.remaining() / min_bytes + (enc == PlyEncoding::ascii ? 1 : 0))
      throw IoError(path, line_at(e.header_line),
                    "element " + e.name + " claims " + std::to_string(e.count) + " entries but only " +
                        std::to_string(rd.remaining()) + " bytes follow the header");
    const std::size_t can_hold = static_cast<std::size_t>(std::min<std::uint64_t>(e.count, rd.remaining() / std::max<std::uint64_t>(min_bytes, 1) + 1));

    if (e.name == "vertex") {
      const VertexRoles roles = vertex_roles(path, e, r);
      read_vertices(path, e, roles, can_hold, rd, r);
      r.info.file_vertices = r.mesh.positions.size();
      r.info.has_normals = roles.normals;
    } else if (e.name == "face") {
      read_faces(path, e, num_vertices, can_hold, rd, r);
      r.info.file_faces = e.count;
    } else {
      if (e.count > 0) r.info.notes.push_back("skipped element '" + e.name + "' (" + std::to_string(e.count) + ")");
      if (e.props.empty()) continue;   // nothing stored per entry: no loop over a huge count
      for (std::uint64_t i = 0; i < e.count; ++i)
        for (const PlyProperty& p : e.props) rd.skip(p);
    }
  }
  if (!vertex_el) throw IoError(path, "", "no vertex element");
  return r;
}

}  // namespace gsp::io::detail
