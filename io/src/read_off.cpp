// OFF and its variants (COFF colours, NOFF normals, CNOFF both; ST/4/n prefixes are not
// supported). Line based: one vertex or face per line, '#' starts a comment, blank lines are
// skipped; counts may sit on the header line ("OFF 8 6 12") or the next one.
#include "parse_util.hpp"
#include "readers.hpp"

#include <algorithm>
#include <cmath>

namespace gsp::io::detail {

namespace {

// The next line with content, comments removed; false at the end.
bool next_content(LineScanner& lines, std::vector<std::string_view>& tok) {
  std::string_view line;
  while (lines.next(line)) {
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    split(line, tok);
    if (!tok.empty()) return true;
  }
  return false;
}

bool is_integer_text(std::string_view s) {
  return s.find_first_of(".eE") == std::string_view::npos;
}

}  // namespace

ReadResult read_off(const std::string& path, const std::string& bytes) {
  ReadResult r;
  r.info.format = Format::off;
  LineScanner lines(path, bytes);
  std::vector<std::string_view> tok;
  if (!next_content(lines, tok)) throw IoError(path, "", "empty OFF file");
  std::string key(tok[0]);
  bool colored = false, normals = false;
  if (key.size() >= 3 && key.compare(key.size() - 3, 3, "OFF") == 0) {
    const std::string prefix = key.substr(0, key.size() - 3);
    if (prefix == "C") colored = true;
    else if (prefix == "N") normals = true;
    else if (prefix == "CN" || prefix == "NC") colored = normals = true;
    else if (!prefix.empty()) lines.fail("unsupported OFF variant '" + key.substr(0, 16) + "'");
  } else {
    lines.fail("not an OFF file (no OFF magic)");
  }
  if (tok.size() > 1 && tok[1] == "BINARY") lines.fail("binary OFF is not supported");
  // Counts on the same line as the magic, or on the next content line.
  std::vector<std::string_view> counts(tok.begin() + 1, tok.end());
  if (counts.empty()) {
    if (!next_content(lines, tok)) throw IoError(path, line_at(lines.line_number()), "file ends before the vertex/face counts");
    counts = tok;
  }
  long long nv = 0, nf = 0;
  if (counts.size() < 2 || !parse_int(counts[0], nv) || !parse_int(counts[1], nf) || nv < 0 || nf < 0)
    lines.fail("expected vertex and face counts");
  const std::size_t count_line = lines.line_number();
  // Each vertex line holds at least "0 0 0\n", each face line "3 0 0 0\n".
  const std::uint64_t need = static_cast<std::uint64_t>(nv) * 6 + static_cast<std::uint64_t>(nf) * 8;
  if (nv >= static_cast<long long>(kInvalidIndex) || nf > static_cast<long long>(bytes.size()) ||
      need > lines.remaining_bytes() + 2)
    throw IoError(path, line_at(count_line), "counts " + std::to_string(nv) + " vertices / " + std::to_string(nf) +
                                                 " faces cannot fit in the " + std::to_string(lines.remaining_bytes()) +
                                                 " bytes that follow");
  TriangleMesh& m = r.mesh;
  m.positions.reserve(static_cast<std::size_t>(nv));
  if (normals) m.normals.reserve(static_cast<std::size_t>(nv));
  const std::size_t first = 3 + (normals ? 3 : 0);
  std::vector<std::array<double, 4>> colors;
  bool integer_colors = true;
  for (long long i = 0; i < nv; ++i) {
    if (!next_content(lines, tok)) throw IoError(path, line_at(lines.line_number()), "file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    if (tok.size() < first) lines.fail("vertex " + std::to_string(i) + " needs " + std::to_string(first) + " numbers");
    double v[6] = {};
    for (std::size_t k = 0; k < first; ++k)
      if (!parse_double(tok[k], v[k])) lines.fail("'" + std::string(tok[k].substr(0, 40)) + "' is not a number");
    if (!finite3(v[0], v[1], v[2])) lines.fail("vertex " + std::to_string(i) + " has a non-finite coordinate");
    m.positions.push_back({v[0], v[1], v[2]});
    if (normals) m.normals.push_back({v[3], v[4], v[5]});
    if (colored) {
      std::array<double, 4> c = {0, 0, 0, -1};
      if (tok.size() < first + 3) lines.fail("COFF vertex " + std::to_string(i) + " has no colour");
      for (std::size_t k = 0; k < 4 && first + k < tok.size(); ++k) {
        if (!parse_double(tok[first + k], c[k])) lines.fail("colour value is not a number");
        integer_colors = integer_colors && is_integer_text(tok[first + k]);
      }
      colors.push_back(c);
    }
  }
  std::vector<Index> corners;
  for (long long f = 0; f < nf; ++f) {
    if (!next_content(lines, tok)) throw IoError(path, line_at(lines.line_number()), "file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    long long n;
    if (!parse_int(tok[0], n)) lines.fail("face " + std::to_string(f) + " does not start with a corner count");
    if (n < 3) lines.fail("face " + std::to_string(f) + " has " + std::to_string(n) + " corners (at least 3 needed)");
    if (static_cast<unsigned long long>(n) + 1 > tok.size())
      lines.fail("face " + std::to_string(f) + " announces " + std::to_string(n) + " corners but lists " + std::to_string(tok.size() - 1));
    corners.clear();
    for (long long k = 0; k < n; ++k) {
      long long idx;
      if (!parse_int(tok[1 + k], idx)) lines.fail("face " + std::to_string(f) + ": '" + std::string(tok[1 + k].substr(0, 40)) + "' is not an index");
      if (idx < 0 || idx >= nv)
        lines.fail("face " + std::to_string(f) + ": vertex index " + std::to_string(idx) + " out of range (" + std::to_string(nv) + " vertices)");
      corners.push_back(static_cast<Index>(idx));
    }
    if (n > 3) ++r.info.polygons_split;
    add_fan(m.triangles, corners.data(), corners.size());
  }
  if (colored) {
    const double scale = integer_colors ? 1.0 : 255.0;
    for (const auto& c : colors) {
      auto byte = [&](double x) {
        return static_cast<std::uint8_t>(std::isfinite(x) ? std::lround(std::clamp(x * scale, 0.0, 255.0)) : 0);
      };
      r.attributes.colors.push_back({byte(c[0]), byte(c[1]), byte(c[2]), c[3] < 0 ? std::uint8_t(255) : byte(c[3])});
    }
  }
  r.info.file_vertices = m.positions.size();
  r.info.file_faces = static_cast<std::size_t>(nf);
  r.info.has_normals = normals;
  return r;
}

}  // namespace gsp::io::detail
