// Wavefront OBJ: `v` and `f` carry the mesh; everything else (vt, vn, vp, g, o, s, usemtl,
// mtllib, l, p, comments) is skipped. Face corners may be `i`, `i/t`, `i//n` or `i/t/n`, with
// negative indices counting back from the last vertex defined so far. A big file is read on
// several threads first (read_obj_parallel.cpp); this serial reader names every error.
#include "obj_parts.hpp"
#include "parse_util.hpp"
#include "readers.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace gsp::io::detail {

namespace {

std::uint8_t unit_to_byte(double c) {
  // Colours in OBJ are 0..1 floats (MeshLab); a file with 0..255 values is rescaled by the caller.
  if (!std::isfinite(c)) return 0;
  return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255.0));
}

}  // namespace

void finish_obj(const std::string& path, ObjExtras& x, ReadResult& r) {
  TriangleMesh& m = r.mesh;
  r.info.file_vertices = m.positions.size();
  if (m.positions.empty() && r.info.file_faces == 0) throw IoError(path, "", "no vertices or faces (not an OBJ file?)");
  if (x.max_index >= static_cast<long long>(m.positions.size()))
    throw IoError(path, line_at(x.max_index_line),
                  "vertex index " + std::to_string(x.max_index + 1) + " out of range (" +
                      std::to_string(m.positions.size()) + " vertices)");
  if (x.all_colored && !x.colors.empty()) {
    // Values above 1 mean the writer used 0..255.
    double top = 0;
    for (const auto& c : x.colors)
      for (double v : c)
        if (std::isfinite(v)) top = std::max(top, v);
    const double scale = top > 1.0 ? 1.0 / 255.0 : 1.0;
    r.attributes.colors.reserve(x.colors.size());
    for (const auto& c : x.colors)
      r.attributes.colors.push_back({unit_to_byte(c[0] * scale), unit_to_byte(c[1] * scale), unit_to_byte(c[2] * scale), 255});
  }
  for (const auto& [key, count] : x.skipped)
    r.info.notes.push_back("ignored " + std::to_string(count) + " '" + key + "' line(s)");
}

ReadResult read_obj(const std::string& path, const std::string& bytes, unsigned threads) {
  ReadResult r;
  r.info.format = Format::obj;
  if (threads > 1) {
    ReadResult fast = r;
    if (read_obj_parallel(bytes, threads, fast)) return fast;
  }
  TriangleMesh& m = r.mesh;
  LineScanner lines(path, bytes);
  std::vector<std::string_view> tok;
  std::vector<Index> corners;
  ObjExtras x;

  std::string_view line;
  while (lines.next(line)) {
    split(line, tok);
    if (tok.empty() || tok[0].front() == '#') continue;
    const std::string_view key = tok[0];
    if (key == "v") {
      if (tok.size() < 4) lines.fail("vertex needs 3 coordinates");
      double p[3];
      for (int i = 0; i < 3; ++i)
        if (!parse_double(tok[1 + i], p[i]))
          lines.fail("'" + std::string(tok[1 + i].substr(0, 40)) + "' is not a number");
      if (!finite3(p[0], p[1], p[2]))
        lines.fail("vertex " + std::to_string(m.positions.size()) + " has a non-finite coordinate");
      m.positions.push_back({p[0], p[1], p[2]});
      // `v x y z r g b` (MeshLab's colour extension); `v x y z w` is a weight and ignored.
      double c[3];
      if (tok.size() >= 7 && parse_double(tok[4], c[0]) && parse_double(tok[5], c[1]) &&
          parse_double(tok[6], c[2])) {
        if (x.all_colored) x.colors.push_back({c[0], c[1], c[2]});
      } else {
        x.all_colored = false;
      }
    } else if (key == "f") {
      ++r.info.file_faces;
      corners.clear();
      for (std::size_t i = 1; i < tok.size(); ++i) {
        std::string_view s = tok[i];
        const std::size_t slash = s.find('/');
        if (slash != std::string_view::npos) s = s.substr(0, slash);
        long long idx;
        if (!parse_int(s, idx)) lines.fail("'" + std::string(tok[i].substr(0, 40)) + "' is not a vertex index");
        if (idx == 0) lines.fail("face " + std::to_string(r.info.file_faces - 1) + ": vertex index 0 (OBJ indices start at 1)");
        const long long resolved = idx > 0 ? idx - 1 : static_cast<long long>(m.positions.size()) + idx;
        if (resolved < 0)
          lines.fail("face " + std::to_string(r.info.file_faces - 1) + ": relative index " + std::to_string(idx) +
                     " points before the first vertex (" + std::to_string(m.positions.size()) + " defined so far)");
        if (resolved >= static_cast<long long>(kInvalidIndex))
          lines.fail("face " + std::to_string(r.info.file_faces - 1) + ": vertex index " + std::to_string(idx) + " out of range");
        if (resolved > x.max_index) {
          x.max_index = resolved;
          x.max_index_line = lines.line_number();
        }
        corners.push_back(static_cast<Index>(resolved));
      }
      if (corners.size() < 3)
        lines.fail("face " + std::to_string(r.info.file_faces - 1) + " has " + std::to_string(corners.size()) +
                   " corners (at least 3 needed)");
      if (corners.size() > 3) ++r.info.polygons_split;
      add_fan(m.triangles, corners.data(), corners.size());
    } else {
      ++x.skipped[std::string(key.substr(0, 16))];
    }
  }
  finish_obj(path, x, r);
  return r;
}

}  // namespace gsp::io::detail
