// XYZ point clouds: "x y z" or "x y z nx ny nz" per line ('#' comments, blank lines skipped;
// a lone integer on the first line is taken as a point count, as some writers add one).
#include "parse_util.hpp"
#include "readers.hpp"

namespace gsp::io::detail {

ReadResult read_xyz(const std::string& path, const std::string& bytes) {
  ReadResult r;
  r.info.format = Format::xyz;
  LineScanner lines(path, bytes);
  std::vector<std::string_view> tok;
  TriangleMesh& m = r.mesh;
  bool normals = true, first = true;
  std::string_view line;
  while (lines.next(line)) {
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    split(line, tok);
    if (tok.empty()) continue;
    long long count;
    if (first && tok.size() == 1 && parse_int(tok[0], count)) {
      first = false;
      r.info.notes.push_back("first line taken as a point count");
      continue;
    }
    first = false;
    if (tok.size() < 3) lines.fail("point needs 3 coordinates");
    double v[6] = {};
    const std::size_t n = tok.size() >= 6 ? 6 : 3;
    for (std::size_t k = 0; k < n; ++k)
      if (!parse_double(tok[k], v[k])) lines.fail("'" + std::string(tok[k].substr(0, 40)) + "' is not a number");
    if (!finite3(v[0], v[1], v[2])) lines.fail("vertex " + std::to_string(m.positions.size()) + " has a non-finite coordinate");
    m.positions.push_back({v[0], v[1], v[2]});
    if (n == 6 && normals) m.normals.push_back({v[3], v[4], v[5]});
    else normals = false;
  }
  if (m.positions.empty()) throw IoError(path, "", "no points");
  if (!normals) m.normals.clear();
  r.info.has_normals = normals;
  r.info.file_vertices = m.positions.size();
  return r;
}

}  // namespace gsp::io::detail
