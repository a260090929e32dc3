// A PLY ascii body read on several threads (ply_header.hpp): the plain layout that scanners
// and most tools write, one vertex per line, then one triangle per line, and nothing else.
// Every value goes through the same conversions as in the serial reader, so the result is the
// same to the bit; at the first irregularity (a polygon, a blank or split line, a value that
// is not a number, an index out of range) the whole attempt is dropped and the serial reader
// reads the file, naming the error.
#include "parse_util.hpp"
#include "ply_header.hpp"
#include "text_pieces.hpp"

#include <atomic>

namespace gsp::io::detail {

namespace {

// One property value of an ascii body, converted as the serial reader converts it.
bool ascii_value(std::string_view token, PlyType type, double& out) {
  if (is_integer(type)) {
    long long v;
    if (!parse_int_or_whole(token, v)) return false;
    out = static_cast<double>(v);
    return true;
  }
  if (!parse_double(token, out)) return false;
  if (type == PlyType::f32) out = static_cast<float>(out);
  return true;
}

struct Target {
  const PlyElement& vertices;
  const VertexRoles& roles;
  ReadResult& r;

  bool vertex(std::string_view line, std::size_t i) const {
    std::size_t pos = 0;
    std::string_view token;
    double v[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 255};
    for (std::size_t k = 0; k < vertices.props.size(); ++k) {
      if (!next_token(line, pos, token)) return false;
      const Role role = roles.role[k];
      if (role == Role::skip) continue;
      double x;
      if (!ascii_value(token, vertices.props[k].type, x)) return false;
      if (role == Role::scalar) r.attributes.scalars[roles.slot[k]].second[i] = static_cast<float>(x);
      else if (role == Role::label) r.attributes.labels[roles.slot[k]].second[i] = label_value(x);
      else v[static_cast<int>(role) - 1] = role_value(role, vertices.props[k].type, x);
    }
    if (next_token(line, pos, token) || !finite3(v[0], v[1], v[2])) return false;
    r.mesh.positions[i] = {v[0], v[1], v[2]};
    if (roles.normals) r.mesh.normals[i] = {v[3], v[4], v[5]};
    if (roles.colors) r.attributes.colors[i] = {color_byte(v[6]), color_byte(v[7]), color_byte(v[8]), color_byte(v[9])};
    return true;
  }

  bool face(std::string_view line, std::size_t i) const {
    std::size_t pos = 0;
    std::string_view token;
    long long n;
    if (!next_token(line, pos, token) || !parse_int_or_whole(token, n) || n != 3) return false;
    const double limit = static_cast<double>(r.mesh.positions.size());
    Triangle& t = r.mesh.triangles[i];
    for (int c = 0; c < 3; ++c) {
      long long idx;
      if (!next_token(line, pos, token) || !parse_int_or_whole(token, idx)) return false;
      if (!(idx >= 0 && static_cast<double>(idx) < limit)) return false;
      t[c] = static_cast<Index>(idx);
    }
    return !next_token(line, pos, token);
  }
};

// Face indices are read as integers here; the serial reader reads them as the list's type,
// which is the same for the integer types PLY writers use for indices.
bool plain_layout(const PlyHeader& header) {
  if (header.elements.size() != 2) return false;
  const PlyElement& v = header.elements[0];
  const PlyElement& f = header.elements[1];
  if (v.name != "vertex" || f.name != "face" || f.props.size() != 1) return false;
  for (const PlyProperty& p : v.props)
    if (p.list) return false;
  const PlyProperty& list = f.props[0];
  return list.list && is_integer(list.type) && (list.name == "vertex_indices" || list.name == "vertex_index");
}

}  // namespace

bool read_ply_ascii_parallel(std::string_view body, const PlyHeader& header, const VertexRoles& roles,
                             unsigned threads, ReadResult& r) {
  if (!plain_layout(header)) return false;
  const PlyElement& vertices = header.elements[0];
  const PlyElement& faces = header.elements[1];
  const std::vector<TextPiece> pieces = cut_at_lines(body, threads);
  const std::size_t lines = pieces.empty() ? 0 : pieces.back().first_line + pieces.back().lines;
  if (lines != vertices.count + faces.count) return false;   // also bounds the counts by the file's size

  const std::size_t nv = static_cast<std::size_t>(vertices.count);
  r.mesh.positions.resize(nv);
  if (roles.normals) r.mesh.normals.resize(nv);
  if (roles.colors) r.attributes.colors.resize(nv);
  for (auto& s : r.attributes.scalars) s.second.resize(nv);
  for (auto& l : r.attributes.labels) l.second.resize(nv);
  r.mesh.triangles.resize(static_cast<std::size_t>(faces.count));

  const Target target{vertices, roles, r};
  std::atomic<bool> ok{true};
  for_each_piece(pieces.size(), [&](std::size_t p) {
    PieceLines in(pieces[p].text);
    std::string_view line;
    for (std::size_t g = pieces[p].first_line; in.next(line) && ok.load(std::memory_order_relaxed); ++g) {
      const bool good = g < nv ? target.vertex(line, g) : target.face(line, g - nv);
      if (!good) ok = false;
    }
  });
  if (!ok) return false;
  r.info.file_vertices = nv;
  r.info.file_faces = static_cast<std::size_t>(faces.count);
  r.info.has_normals = roles.normals;
  return true;
}

}  // namespace gsp::io::detail
