#include "overlays.hpp"

#include <gsp/errors.hpp>
#include <gsp/io/mesh_io.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace gsp::render_app {

std::vector<double> read_field(const std::string& path, std::size_t expected, const char* what) {
  std::vector<double> v = io::read_values_txt(path);
  if (v.size() != expected)
    throw IoError(path, "", "has " + std::to_string(v.size()) + " values, the mesh has " + std::to_string(expected) +
                                " " + what);
  return v;
}

std::vector<double> read_property(const std::string& mesh_path, const std::string& name) {
  const io::ReadResult r = io::read_mesh(mesh_path);
  std::string names;
  for (const auto& [n, values] : r.attributes.scalars) {
    if (n == name) return std::vector<double>(values.begin(), values.end());
    names += (names.empty() ? "" : ", ") + n;
  }
  for (const auto& [n, values] : r.attributes.labels) {
    if (n == name) return std::vector<double>(values.begin(), values.end());
    names += (names.empty() ? "" : ", ") + n;
  }
  throw IoError(mesh_path, "", "no per-vertex property '" + name + "'" +
                                   (names.empty() ? std::string(" (the file has none)") : " (it has: " + names + ")"));
}

std::vector<std::int32_t> read_labels(const std::string& path, std::size_t expected) {
  const std::vector<double> v = read_field(path, expected, "faces");
  std::vector<std::int32_t> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!(std::abs(v[i]) < 2147483647.0) || v[i] != std::floor(v[i]))
      throw IoError(path, "value " + std::to_string(i + 1), "a face label must be an integer");
    out[i] = std::int32_t(v[i]);
  }
  return out;
}

std::vector<std::int32_t> face_labels_from_vertices(const std::vector<double>& vertex_labels,
                                                    const std::vector<Triangle>& triangles, const std::string& path) {
  for (double v : vertex_labels)
    if (!(std::abs(v) < 2147483647.0) || v != std::floor(v))
      throw IoError(path, "", "a vertex label must be an integer, found " + std::to_string(v));
  std::vector<std::int32_t> out;
  out.reserve(triangles.size());
  for (const Triangle& t : triangles) {
    const auto a = std::int32_t(vertex_labels[t[0]]), b = std::int32_t(vertex_labels[t[1]]),
               c = std::int32_t(vertex_labels[t[2]]);
    out.push_back((b == c && a != b) ? b : a);
  }
  return out;
}

std::vector<Vec3> read_points(const std::string& path) {
  io::ReadResult r = io::read_mesh(path);
  if (r.mesh.positions.empty()) throw IoError(path, "", "no points");
  return std::move(r.mesh.positions);
}

std::vector<std::vector<Vec3>> read_polylines(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path, "", "cannot open");
  std::vector<std::vector<Vec3>> lines(1);
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    if (const std::size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    for (char& c : line)
      if (c == ',' || c == '\t' || c == '\r') c = ' ';
    if (line.find_first_not_of(' ') == std::string::npos) {
      if (!lines.back().empty()) lines.emplace_back();
      continue;
    }
    std::istringstream s(line);
    double xyz[3];
    std::string word, extra;
    for (double& value : xyz) {
      char* end = nullptr;
      errno = 0;
      if (!(s >> word) || (value = std::strtod(word.c_str(), &end), *end != '\0') || errno == ERANGE ||
          !std::isfinite(value))
        throw IoError(path, "line " + std::to_string(number), "expected three finite numbers x y z");
    }
    if (s >> extra) throw IoError(path, "line " + std::to_string(number), "expected three numbers, found more");
    lines.back().push_back({xyz[0], xyz[1], xyz[2]});
  }
  if (in.bad()) throw IoError(path, "", "read error");
  if (lines.back().empty()) lines.pop_back();
  if (lines.empty()) throw IoError(path, "", "no points");
  return lines;
}

}  // namespace gsp::render_app
