#include <gsp/cli/parse.hpp>

#include <gsp/cli/app.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace gsp::cli {

namespace {

[[noreturn]] void bad(std::string_view option, std::string_view text, const std::string& why) {
  throw UsageError(std::string(option) + ": \"" + std::string(text) + "\": " + why);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// Comma-separated items, trimmed; an empty item (",," or a trailing comma) is an error.
std::vector<std::string_view> split(std::string_view text, std::string_view option) {
  std::vector<std::string_view> items;
  if (trim(text).empty()) bad(option, text, "empty value");
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string_view item = trim(text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (item.empty()) bad(option, text, "empty item in a comma-separated list");
    items.push_back(item);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return items;
}

bool to_double(std::string_view item, double& out) {
  const std::string s(item);
  char* end = nullptr;
  errno = 0;
  out = std::strtod(s.c_str(), &end);
  return !s.empty() && end == s.c_str() + s.size() && errno != ERANGE && std::isfinite(out);
}

Index to_index(std::string_view item, std::string_view option, std::string_view text,
               const char* what) {
  // Digits only: strtoul would accept "-1" (wrapping) and "+1".
  std::uint64_t value = 0;
  bool ok = !item.empty();
  for (char c : item) {
    if (c < '0' || c > '9') { ok = false; break; }
    value = value * 10 + static_cast<unsigned>(c - '0');
    if (value >= kInvalidIndex) { ok = false; break; }
  }
  if (!ok) bad(option, text, "\"" + std::string(item) + "\" is not " + what + " (a non-negative integer below 2^32-1)");
  return static_cast<Index>(value);
}

const char* extension(io::Format f) {
  switch (f) {
    case io::Format::obj: return ".obj";
    case io::Format::ply: return ".ply";
    case io::Format::off: return ".off";
    case io::Format::stl: return ".stl";
    case io::Format::gltf: return ".gltf";
    case io::Format::glb: return ".glb";
    case io::Format::xyz: return ".xyz";
    case io::Format::txt: return ".txt";
    case io::Format::unknown: break;
  }
  return "?";
}

}  // namespace

std::vector<Index> parse_index_list(std::string_view text, std::string_view option) {
  std::vector<Index> out;
  for (std::string_view item : split(text, option)) out.push_back(to_index(item, option, text, "an index"));
  return out;
}

std::vector<double> parse_number_list(std::string_view text, std::string_view option) {
  std::vector<double> out;
  for (std::string_view item : split(text, option)) {
    double d;
    if (!to_double(item, d)) bad(option, text, "\"" + std::string(item) + "\" is not a finite number");
    out.push_back(d);
  }
  return out;
}

double parse_number(std::string_view text, std::string_view option) {
  double d;
  if (!to_double(trim(text), d)) bad(option, text, "not a finite number");
  return d;
}

Vec3 parse_vec3(std::string_view text, std::string_view option) {
  const std::vector<double> v = parse_number_list(text, option);
  if (v.size() != 3) bad(option, text, "expected three numbers x,y,z, got " + std::to_string(v.size()));
  return {v[0], v[1], v[2]};
}

SurfacePoint parse_face_point(std::string_view text, std::string_view option) {
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos) bad(option, text, "expected F:u,v (face index, then two barycentric weights)");
  const Index face = to_index(trim(text.substr(0, colon)), option, text, "a face index");
  const std::vector<double> uv = parse_number_list(text.substr(colon + 1), option);
  if (uv.size() != 2) bad(option, text, "expected two barycentric weights u,v after the colon, got " + std::to_string(uv.size()));
  const double u = uv[0], v = uv[1];
  constexpr double eps = 1e-9;
  if (u < -eps || v < -eps || u + v > 1.0 + eps)
    bad(option, text, "barycentric weights must satisfy u >= 0, v >= 0, u + v <= 1");
  return SurfacePoint::in_face(face, {std::max(0.0, 1 - u - v), u, v});
}

io::Format output_format(const std::string& path, std::initializer_list<io::Format> allowed,
                         std::string_view option) {
  const io::Format f = io::format_from_path(path);
  for (io::Format a : allowed)
    if (a == f) return f;
  std::string list;
  for (io::Format a : allowed) list += std::string(list.empty() ? "" : ", ") + extension(a);
  bad(option, path, "unsupported output format (use one of " + list + ")");
}

}  // namespace gsp::cli
