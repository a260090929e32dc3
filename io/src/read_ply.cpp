// PLY in all three encodings. The header is parsed into elements and properties first; the
// body is then read element by element with one generic property reader, so that properties
// and elements we do not use (lists included) are skipped exactly as they are laid out.
#include "parse_util.hpp"
#include "readers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gsp::io::detail {

namespace {

enum class Type { i8, u8, i16, u16, i32, u32, f32, f64 };

bool type_from_name(std::string_view s, Type& t) {
  if (s == "char" || s == "int8") t = Type::i8;
  else if (s == "uchar" || s == "uint8") t = Type::u8;
  else if (s == "short" || s == "int16") t = Type::i16;
  else if (s == "ushort" || s == "uint16") t = Type::u16;
  else if (s == "int" || s == "int32") t = Type::i32;
  else if (s == "uint" || s == "uint32") t = Type::u32;
  else if (s == "float" || s == "float32") t = Type::f32;
  else if (s == "double" || s == "float64") t = Type::f64;
  else return false;
  return true;
}

std::size_t type_size(Type t) {
  switch (t) {
    case Type::i8: case Type::u8: return 1;
    case Type::i16: case Type::u16: return 2;
    case Type::i32: case Type::u32: case Type::f32: return 4;
    case Type::f64: return 8;
  }
  return 1;
}

bool is_integer(Type t) { return t != Type::f32 && t != Type::f64; }

struct Property {
  std::string name;
  bool list = false;
  Type count_type = Type::u8, type = Type::f32;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> props;
  std::size_t header_line = 0;
};

enum class Encoding { ascii, little, big };

// What each vertex/face property is used for.
enum class Role { skip, x, y, z, nx, ny, nz, red, green, blue, alpha, scalar, label, indices };

struct Reader {
  const std::string& path;
  Encoding enc;
  ByteCursor* bin = nullptr;
  TokenScanner* text = nullptr;

  double scalar(Type t) {
    if (enc == Encoding::ascii) {
      if (is_integer(t)) return static_cast<double>(text->need_int("an integer property value"));
      const double v = text->need_double("a property value");
      return t == Type::f32 ? static_cast<float>(v) : v;   // a float property holds a float
    }
    const bool be = enc == Encoding::big;
    switch (t) {
      case Type::i8: return bin->read<std::int8_t>(be, "a char property");
      case Type::u8: return bin->read<std::uint8_t>(be, "a uchar property");
      case Type::i16: return bin->read<std::int16_t>(be, "a short property");
      case Type::u16: return bin->read<std::uint16_t>(be, "a ushort property");
      case Type::i32: return bin->read<std::int32_t>(be, "an int property");
      case Type::u32: return bin->read<std::uint32_t>(be, "a uint property");
      case Type::f32: return bin->read<float>(be, "a float property");
      case Type::f64: return bin->read<double>(be, "a double property");
    }
    return 0;
  }
  // A list length: validated against what the rest of the file can hold.
  std::uint64_t list_count(const Property& p) {
    if (enc == Encoding::ascii) {
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
  void skip(const Property& p) {
    const std::uint64_t n = p.list ? list_count(p) : 1;
    if (enc == Encoding::ascii) {
      for (std::uint64_t i = 0; i < n; ++i) text->need("a property value");
    } else {
      bin->skip(static_cast<std::size_t>(n * type_size(p.type)), "a property");
    }
  }
  // Where the next value starts (a line or a byte), kept per element as a number and spelt
  // out only for an error: formatting it for every vertex and face cost 5% of a whole
  // gsp-geodesic run on a binary PLY.
  std::size_t mark() { return enc == Encoding::ascii ? text->next_line_number() : bin->pos(); }
  std::string describe(std::size_t mark) const { return enc == Encoding::ascii ? line_at(mark) : byte_at(mark); }
  std::size_t remaining() const { return enc == Encoding::ascii ? text->remaining_bytes() : bin->remaining(); }
};

// Fewest bytes one instance of `e` can occupy; used to reject absurd counts before reserving.
std::uint64_t min_instance_bytes(const Element& e, Encoding enc) {
  std::uint64_t b = 0;
  for (const Property& p : e.props)
    b += enc == Encoding::ascii ? 2 : type_size(p.list ? p.count_type : p.type);
  return b;
}

}  // namespace

ReadResult read_ply(const std::string& path, const std::string& bytes) {
  ReadResult r;
  r.info.format = Format::ply;
  LineScanner header(path, bytes);
  std::string_view line;
  std::vector<std::string_view> tok;
  if (!header.next(line) || line != "ply") throw IoError(path, line_at(1), "not a PLY file (no 'ply' magic)");
  bool have_format = false;
  Encoding enc = Encoding::ascii;
  std::vector<Element> elements;
  bool ended = false;
  while (header.next(line)) {
    split(line, tok);
    if (tok.empty()) continue;
    if (tok[0] == "end_header") {
      ended = true;
      break;
    }
    if (tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "format") {
      if (tok.size() < 2) header.fail("format line without an encoding");
      if (tok[1] == "ascii") enc = Encoding::ascii;
      else if (tok[1] == "binary_little_endian") enc = Encoding::little;
      else if (tok[1] == "binary_big_endian") enc = Encoding::big;
      else header.fail("unknown PLY format '" + std::string(tok[1].substr(0, 40)) + "'");
      have_format = true;
    } else if (tok[0] == "element") {
      long long n;
      if (tok.size() < 3 || !parse_int(tok[2], n) || n < 0) header.fail("element needs a name and a count");
      for (const Element& e : elements)
        if (e.name == tok[1] && (e.name == "vertex" || e.name == "face"))
          header.fail("a second '" + e.name + "' element");
      elements.push_back({std::string(tok[1]), static_cast<std::uint64_t>(n), {}, header.line_number()});
    } else if (tok[0] == "property") {
      if (elements.empty()) header.fail("property before any element");
      Property p;
      if (tok.size() >= 5 && tok[1] == "list") {
        p.list = true;
        if (!type_from_name(tok[2], p.count_type) || !type_from_name(tok[3], p.type))
          header.fail("unknown list property type");
        if (!is_integer(p.count_type)) header.fail("list length type must be an integer type");
        p.name = std::string(tok[4]);
      } else if (tok.size() >= 3 && tok[1] != "list") {
        if (!type_from_name(tok[1], p.type)) header.fail("unknown property type '" + std::string(tok[1].substr(0, 40)) + "'");
        p.name = std::string(tok[2]);
      } else {
        header.fail("malformed property line");
      }
      elements.back().props.push_back(p);
    } else {
      header.fail("unexpected header line '" + std::string(tok[0].substr(0, 40)) + "'");
    }
  }
  if (!ended) throw IoError(path, line_at(header.line_number()), "header has no end_header");
  if (!have_format) throw IoError(path, "", "header has no format line");
  r.info.binary = enc != Encoding::ascii;

  const std::size_t body = bytes.size() - header.remaining_bytes();
  ByteCursor bin(path, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), body);
  TokenScanner text(path, std::string_view(bytes).substr(body), header.line_number() + 1);
  Reader rd{path, enc, &bin, &text};

  const Element* vertex_el = nullptr;
  for (const Element& e : elements)
    if (e.name == "vertex") vertex_el = &e;
  const std::uint64_t num_vertices = vertex_el ? vertex_el->count : 0;
  if (num_vertices >= kInvalidIndex) throw IoError(path, line_at(vertex_el->header_line), "too many vertices for 32-bit indices");

  TriangleMesh& m = r.mesh;
  std::vector<Index> corners;
  for (const Element& e : elements) {
    // Reject counts the file cannot hold before anything is reserved for them.
    const std::uint64_t min_bytes = min_instance_bytes(e, enc);
    if (min_bytes > 0 && e.count > rd.remaining() / min_bytes + (enc == Encoding::ascii ? 1 : 0))
      throw IoError(path, line_at(e.header_line),
                    "element " + e.name + " claims " + std::to_string(e.count) + " entries but only " +
                        std::to_string(rd.remaining()) + " bytes follow the header");
    const std::size_t can_hold = static_cast<std::size_t>(std::min<std::uint64_t>(e.count, rd.remaining() / std::max<std::uint64_t>(min_bytes, 1) + 1));

    if (e.name == "vertex") {
      std::vector<Role> roles;
      bool has[10] = {};
      for (const Property& p : e.props) {
        Role role = Role::skip;
        if (!p.list) {
          static const char* known[] = {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue", "alpha"};
          for (int k = 0; k < 10; ++k)
            if (p.name == known[k]) role = static_cast<Role>(k + 1);
          if (role == Role::skip) role = is_integer(p.type) ? Role::label : Role::scalar;
        } else {
          r.info.notes.push_back("skipped vertex list property '" + p.name + "'");
        }
        if (role >= Role::x && role <= Role::alpha) has[static_cast<int>(role) - 1] = true;
        roles.push_back(role);
      }
      if (!has[0] || !has[1] || !has[2]) throw IoError(path, line_at(e.header_line), "vertex element lacks x, y or z");
      const bool normals = has[3] && has[4] && has[5];
      const bool colors = has[6] && has[7] && has[8];
      m.positions.reserve(can_hold);
      if (normals) m.normals.reserve(can_hold);
      if (colors) r.attributes.colors.reserve(can_hold);
      std::vector<std::size_t> attr_slot(e.props.size());
      for (std::size_t k = 0; k < e.props.size(); ++k) {
        if (roles[k] == Role::scalar) {
          attr_slot[k] = r.attributes.scalars.size();
          r.attributes.scalars.push_back({e.props[k].name, {}});
          r.attributes.scalars.back().second.reserve(can_hold);
        } else if (roles[k] == Role::label) {
          attr_slot[k] = r.attributes.labels.size();
          r.attributes.labels.push_back({e.props[k].name, {}});
          r.attributes.labels.back().second.reserve(can_hold);
        }
      }
      for (std::uint64_t i = 0; i < e.count; ++i) {
        const std::size_t where = rd.mark();
        double v[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 255};
        for (std::size_t k = 0; k < e.props.size(); ++k) {
          const Property& p = e.props[k];
          const Role role = roles[k];
          if (role == Role::skip) {
            rd.skip(p);
            continue;
          }
          const double x = rd.scalar(p.type);
          if (role == Role::scalar) {
            r.attributes.scalars[attr_slot[k]].second.push_back(static_cast<float>(x));
          } else if (role == Role::label) {
            r.attributes.labels[attr_slot[k]].second.push_back(static_cast<std::int32_t>(std::clamp(x, -2147483648.0, 2147483647.0)));
          } else {
            // Colours stored as floats are 0..1.
            const bool float_color = role >= Role::red && !is_integer(p.type);
            v[static_cast<int>(role) - 1] = float_color ? x * 255.0 : x;
          }
        }
        if (!finite3(v[0], v[1], v[2]))
          throw IoError(path, rd.describe(where), "vertex " + std::to_string(i) + " has a non-finite coordinate");
        m.positions.push_back({v[0], v[1], v[2]});
        if (normals) m.normals.push_back({v[3], v[4], v[5]});
        if (colors) {
          auto byte = [](double c) {
            return static_cast<std::uint8_t>(std::isfinite(c) ? std::lround(std::clamp(c, 0.0, 255.0)) : 0);
          };
          r.attributes.colors.push_back({byte(v[6]), byte(v[7]), byte(v[8]), byte(v[9])});
        }
      }
      r.info.file_vertices = m.positions.size();
      r.info.has_normals = normals;
    } else if (e.name == "face") {
      std::size_t index_prop = e.props.size();
      for (std::size_t k = 0; k < e.props.size(); ++k)
        if (e.props[k].list && (e.props[k].name == "vertex_indices" || e.props[k].name == "vertex_index")) index_prop = k;
      if (index_prop == e.props.size() && e.count > 0)
        throw IoError(path, line_at(e.header_line), "face element has no vertex_indices list");
      m.triangles.reserve(can_hold);
      for (std::uint64_t i = 0; i < e.count; ++i) {
        for (std::size_t k = 0; k < e.props.size(); ++k) {
          const Property& p = e.props[k];
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
              throw IoError(path, rd.describe(where), "face " + std::to_string(i) + ": vertex index " +
                                             std::to_string(static_cast<long long>(std::isfinite(idx) ? idx : -1)) +
                                             " out of range (" + std::to_string(num_vertices) + " vertices)");
            corners.push_back(static_cast<Index>(idx));
          }
          if (n > 3) ++r.info.polygons_split;
          add_fan(m.triangles, corners.data(), corners.size());
        }
      }
      r.info.file_faces = e.count;
    } else {
      if (e.count > 0) r.info.notes.push_back("skipped element '" + e.name + "' (" + std::to_string(e.count) + ")");
      if (e.props.empty()) continue;   // nothing stored per entry: no loop over a huge count
      for (std::uint64_t i = 0; i < e.count; ++i)
        for (const Property& p : e.props) rd.skip(p);
    }
  }
  if (!vertex_el) throw IoError(path, "", "no vertex element");
  return r;
}

}  // namespace gsp::io::detail
