#include "ply_header.hpp"

#include "parse_util.hpp"

namespace gsp::io::detail {

namespace {

bool type_from_name(std::string_view s, PlyType& t) {
  if (s == "char" || s == "int8") t = PlyType::i8;
  else if (s == "uchar" || s == "uint8") t = PlyType::u8;
  else if (s == "short" || s == "int16") t = PlyType::i16;
  else if (s == "ushort" || s == "uint16") t = PlyType::u16;
  else if (s == "int" || s == "int32") t = PlyType::i32;
  else if (s == "uint" || s == "uint32") t = PlyType::u32;
  else if (s == "float" || s == "float32") t = PlyType::f32;
  else if (s == "double" || s == "float64") t = PlyType::f64;
  else return false;
  return true;
}

}  // namespace

std::size_t type_size(PlyType t) {
  switch (t) {
    case PlyType::i8: case PlyType::u8: return 1;
    case PlyType::i16: case PlyType::u16: return 2;
    case PlyType::i32: case PlyType::u32: case PlyType::f32: return 4;
    case PlyType::f64: return 8;
  }
  return 1;
}

PlyHeader read_ply_header(const std::string& path, const std::string& bytes) {
  PlyHeader h;
  LineScanner header(path, bytes);
  std::string_view line;
  std::vector<std::string_view> tok;
  if (!header.next(line) || line != "ply") throw IoError(path, line_at(1), "not a PLY file (no 'ply' magic)");
  bool have_format = false;
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
      if (tok[1] == "ascii") h.encoding = PlyEncoding::ascii;
      else if (tok[1] == "binary_little_endian") h.encoding = PlyEncoding::little;
      else if (tok[1] == "binary_big_endian") h.encoding = PlyEncoding::big;
      else header.fail("unknown PLY format '" + std::string(tok[1].substr(0, 40)) + "'");
      have_format = true;
    } else if (tok[0] == "element") {
      long long n;
      if (tok.size() < 3 || !parse_int(tok[2], n) || n < 0) header.fail("element needs a name and a count");
      for (const PlyElement& e : h.elements)
        if (e.name == tok[1] && (e.name == "vertex" || e.name == "face"))
          header.fail("a second '" + e.name + "' element");
      h.elements.push_back({std::string(tok[1]), static_cast<std::uint64_t>(n), {}, header.line_number()});
    } else if (tok[0] == "property") {
      if (h.elements.empty()) header.fail("property before any element");
      PlyProperty p;
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
      h.elements.back().props.push_back(p);
    } else {
      header.fail("unexpected header line '" + std::string(tok[0].substr(0, 40)) + "'");
    }
  }
  if (!ended) throw IoError(path, line_at(header.line_number()), "header has no end_header");
  if (!have_format) throw IoError(path, "", "header has no format line");
  h.body = bytes.size() - header.remaining_bytes();
  h.body_line = header.line_number() + 1;
  return h;
}

VertexRoles vertex_roles(const std::string& path, const PlyElement& e, ReadResult& r) {
  VertexRoles out;
  bool has[10] = {};
  out.slot.assign(e.props.size(), 0);
  for (std::size_t k = 0; k < e.props.size(); ++k) {
    const PlyProperty& p = e.props[k];
    Role role = Role::skip;
    if (!p.list) {
      static const char* known[] = {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue", "alpha"};
      for (int i = 0; i < 10; ++i)
        if (p.name == known[i]) role = static_cast<Role>(i + 1);
      if (role == Role::skip) role = is_integer(p.type) ? Role::label : Role::scalar;
    } else {
      r.info.notes.push_back("skipped vertex list property '" + p.name + "'");
    }
    if (role >= Role::x && role <= Role::alpha) has[static_cast<int>(role) - 1] = true;
    if (role == Role::scalar) {
      out.slot[k] = r.attributes.scalars.size();
      r.attributes.scalars.push_back({p.name, {}});
    } else if (role == Role::label) {
      out.slot[k] = r.attributes.labels.size();
      r.attributes.labels.push_back({p.name, {}});
    }
    out.role.push_back(role);
  }
  if (!has[0] || !has[1] || !has[2]) throw IoError(path, line_at(e.header_line), "vertex element lacks x, y or z");
  out.normals = has[3] && has[4] && has[5];
  out.colors = has[6] && has[7] && has[8];
  return out;
}

}  // namespace gsp::io::detail
