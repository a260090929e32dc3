#include <gsp/anisotropic/metric_sources.hpp>

#include <gsp/errors.hpp>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace gsp::anisotropic {
namespace {

// The line without its comment and surrounding blanks.
std::string strip(const std::string& line) {
  std::string s = line.substr(0, line.find('#'));
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

}  // namespace

MetricField parse_metric_text(std::istream& in, const std::string& name, std::size_t num_vertices,
                              std::size_t num_faces) {
  MetricField field;
  bool keyword = false;
  std::size_t line_no = 0;
  std::string line;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string s = strip(line);
    if (s.empty()) continue;
    const std::string where = "line " + std::to_string(line_no);
    if (std::isalpha(static_cast<unsigned char>(s[0]))) {
      if (keyword || !field.tensors.empty())
        throw IoError(name, where, "\"" + s + "\": a location keyword is only allowed before the first tensor");
      if (s == "constant") field.location = MetricLocation::constant;
      else if (s == "per-face") field.location = MetricLocation::per_face;
      else if (s == "per-vertex") field.location = MetricLocation::per_vertex;
      else throw IoError(name, where, "\"" + s + "\" is not constant, per-face, per-vertex or six numbers");
      keyword = true;
      continue;
    }
    double v[6];
    const char* p = s.c_str();
    for (int k = 0; k < 6; ++k) {
      char* end = nullptr;
      errno = 0;
      v[k] = std::strtod(p, &end);
      if (end == p || !std::isfinite(v[k]))
        throw IoError(name, where, "expected six finite numbers xx xy xz yy yz zz");
      p = end;
    }
    while (*p == ' ' || *p == '\t') ++p;
    if (*p != '\0') throw IoError(name, where, "more than six numbers");
    field.tensors.push_back({v[0], v[1], v[2], v[3], v[4], v[5]});
  }
  const std::size_t n = field.tensors.size();
  if (n == 0) throw IoError(name, "", "no tensors");
  if (!keyword) {
    if (n == 1) field.location = MetricLocation::constant;
    else if (n == num_faces && n == num_vertices)
      throw IoError(name, "", std::to_string(n) + " tensors: the mesh has as many faces as vertices; "
                              "say per-face or per-vertex on the first line");
    else if (n == num_faces) field.location = MetricLocation::per_face;
    else if (n == num_vertices) field.location = MetricLocation::per_vertex;
    else
      throw IoError(name, "", std::to_string(n) + " tensors: expected 1, " + std::to_string(num_faces) +
                                  " (faces) or " + std::to_string(num_vertices) + " (vertices)");
  }
  const std::size_t expected = field.location == MetricLocation::constant   ? 1
                               : field.location == MetricLocation::per_face ? num_faces
                                                                            : num_vertices;
  if (n != expected)
    throw IoError(name, "", std::to_string(n) + " tensors, the keyword asks for " + std::to_string(expected));
  for (std::size_t i = 0; i < n; ++i)
    if (!field.tensors[i].is_positive_definite())
      throw IoError(name, "tensor " + std::to_string(i + 1), "not symmetric positive definite");
  return field;
}

MetricField read_metric_file(const std::string& path, std::size_t num_vertices, std::size_t num_faces) {
  std::ifstream in(path);
  if (!in) throw IoError(path, "", std::string("cannot open: ") + std::strerror(errno));
  return parse_metric_text(in, path, num_vertices, num_faces);
}

}  // namespace gsp::anisotropic
