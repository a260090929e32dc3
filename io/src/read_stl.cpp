// STL, ascii and binary. Binary is recognised by its size (84 + 50 n bytes for the n it
// declares) before looking at the text: many binary files start their header with "solid".
// STL stores every triangle with its own three corners; they are returned unshared (3 vertices
// per face, in file order) and welding is left to gsp::weld.
#include "parse_util.hpp"
#include "readers.hpp"

#include <cctype>

namespace gsp::io::detail {

namespace {

ReadResult read_binary(const std::string& path, const std::string& bytes, std::uint32_t n) {
  ReadResult r;
  r.info.format = Format::stl;
  r.info.binary = true;
  ByteCursor cur(path, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), 84);
  TriangleMesh& m = r.mesh;
  m.positions.reserve(3 * static_cast<std::size_t>(n));
  m.triangles.reserve(n);
  for (std::uint32_t f = 0; f < n; ++f) {
    cur.skip(12, "a facet normal");
    for (int c = 0; c < 3; ++c) {
      const std::size_t at = cur.pos();
      const float x = cur.read<float>(false, "a vertex");
      const float y = cur.read<float>(false, "a vertex");
      const float z = cur.read<float>(false, "a vertex");
      if (!finite3(x, y, z))
        throw IoError(path, byte_at(at), "vertex " + std::to_string(m.positions.size()) + " (facet " + std::to_string(f) + ") has a non-finite coordinate");
      m.positions.push_back({x, y, z});
    }
    const auto v = static_cast<Index>(3 * f);
    m.triangles.push_back({v, v + 1, v + 2});
    cur.skip(2, "the attribute byte count");
  }
  if (cur.remaining() > 0) r.info.notes.push_back(std::to_string(cur.remaining()) + " trailing bytes ignored");
  r.info.file_vertices = m.positions.size();
  r.info.file_faces = n;
  return r;
}

ReadResult read_ascii(const std::string& path, const std::string& bytes) {
  ReadResult r;
  r.info.format = Format::stl;
  LineScanner lines(path, bytes);
  std::vector<std::string_view> tok;
  std::vector<Index> loop;
  TriangleMesh& m = r.mesh;
  bool in_facet = false, in_loop = false;
  std::string_view line;
  while (lines.next(line)) {
    split(line, tok);
    if (tok.empty()) continue;
    const std::string_view key = tok[0];
    if (key == "facet") {
      if (in_facet) lines.fail("'facet' inside a facet");
      in_facet = true;
      loop.clear();
    } else if (key == "outer") {
      if (!in_facet || in_loop) lines.fail("'outer loop' outside a facet");
      in_loop = true;
    } else if (key == "vertex") {
      if (!in_loop) lines.fail("'vertex' outside 'outer loop'");
      if (tok.size() < 4) lines.fail("vertex needs 3 coordinates");
      double p[3];
      for (int i = 0; i < 3; ++i)
        if (!parse_double(tok[1 + i], p[i])) lines.fail("'" + std::string(tok[1 + i].substr(0, 40)) + "' is not a number");
      if (!finite3(p[0], p[1], p[2])) lines.fail("vertex " + std::to_string(m.positions.size()) + " has a non-finite coordinate");
      if (m.positions.size() >= kInvalidIndex) lines.fail("too many vertices");
      loop.push_back(static_cast<Index>(m.positions.size()));
      m.positions.push_back({p[0], p[1], p[2]});
    } else if (key == "endloop") {
      if (!in_loop) lines.fail("'endloop' without 'outer loop'");
      in_loop = false;
    } else if (key == "endfacet") {
      if (!in_facet || in_loop) lines.fail("'endfacet' without a closed facet");
      if (loop.size() < 3) lines.fail("facet " + std::to_string(r.info.file_faces) + " has " + std::to_string(loop.size()) + " vertices (at least 3 needed)");
      if (loop.size() > 3) ++r.info.polygons_split;
      add_fan(m.triangles, loop.data(), loop.size());
      ++r.info.file_faces;
      in_facet = false;
    } else if (key == "solid" || key == "endsolid") {
      if (in_facet) lines.fail("'" + std::string(key) + "' inside a facet");
    } else {
      lines.fail("unexpected '" + std::string(key.substr(0, 40)) + "' in ascii STL");
    }
  }
  if (in_facet) throw IoError(path, line_at(lines.line_number()), "file ends inside a facet");
  r.info.file_vertices = m.positions.size();
  return r;
}

}  // namespace

ReadResult read_stl(const std::string& path, const std::string& bytes) {
  std::uint32_t n = 0;
  if (bytes.size() >= 84) std::memcpy(&n, bytes.data() + 80, 4);   // little-endian hosts only (x86/ARM)
  const std::uint64_t binary_size = 84 + 50 * static_cast<std::uint64_t>(n);
  if (bytes.size() >= 84 && binary_size == bytes.size()) return read_binary(path, bytes, n);
  std::size_t s = 0;
  while (s < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[s]))) ++s;
  // "solid" at the start is not enough: binary headers often say it too. Text has no NUL.
  if (bytes.compare(s, 5, "solid") == 0 && bytes.find('\0') == std::string::npos) return read_ascii(path, bytes);
  if (bytes.size() < 84) throw IoError(path, byte_at(bytes.size()), "truncated: binary STL header needs 84 bytes, file has " + std::to_string(bytes.size()));
  if (binary_size > bytes.size())
    throw IoError(path, byte_at(bytes.size()), "truncated: binary STL declares " + std::to_string(n) + " triangles (" +
                                                   std::to_string(binary_size) + " bytes) but the file has " +
                                                   std::to_string(bytes.size()) + " bytes");
  return read_binary(path, bytes, n);   // trailing bytes after the last triangle are noted
}

}  // namespace gsp::io::detail
