// Polylines from text: OBJ `v`/`l` elements, or plain "x y z" lines (polyline_text.hpp).
#include <gsp/errors.hpp>
#include <gsp/lines/polyline_text.hpp>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace gsp::lines {

namespace {

std::vector<std::string> tokens(const std::string& line) {
  std::string s = line;
  for (char& c : s)
    if (c == ',' || c == '\t' || c == '\r') c = ' ';
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

struct Reader {
  const std::string& file;
  std::size_t line_no = 0;

  [[noreturn]] void fail(const std::string& what) const { throw IoError(file, "line " + std::to_string(line_no), what); }

  double number(const std::string& t) const {
    char* end = nullptr;
    const double x = std::strtod(t.c_str(), &end);
    if (end == t.c_str() || *end != '\0') fail("\"" + t + "\" is not a number");
    if (!std::isfinite(x)) fail("\"" + t + "\" is not a finite number");
    return x;
  }
  Vec3 point(const std::vector<std::string>& t, std::size_t first) const {
    if (t.size() < first + 3) fail("expected three coordinates x y z");
    return {number(t[first]), number(t[first + 1]), number(t[first + 2])};
  }
  void finish(std::vector<Polyline>& out, Polyline& current) const {
    if (current.empty()) return;
    if (current.size() < 2) fail("a polyline needs at least two points, this one has 1");
    out.push_back(std::move(current));
    current.clear();
  }
};

bool looks_like_obj(const std::string& text) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> t = tokens(line);
    if (!t.empty() && (t[0] == "v" || t[0] == "l")) return true;
  }
  return false;
}

}  // namespace

std::vector<Polyline> parse_polylines(const std::string& text, const std::string& file_name) {
  Reader r{file_name};
  std::vector<Polyline> out;
  const bool obj = looks_like_obj(text);
  std::vector<Vec3> vertices;   // OBJ
  Polyline current;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    ++r.line_no;
    const std::vector<std::string> t = tokens(line);
    if (!t.empty() && t[0][0] == '#') continue;
    if (!obj) {
      if (t.empty()) r.finish(out, current);
      else if (t.size() != 3) r.fail("expected three coordinates x y z, found " + std::to_string(t.size()) + " values");
      else current.push_back(r.point(t, 0));
      continue;
    }
    if (t.empty()) continue;
    if (t[0] == "v") vertices.push_back(r.point(t, 1));
    if (t[0] != "l") continue;
    for (std::size_t i = 1; i < t.size(); ++i) {
      const std::string index = t[i].substr(0, t[i].find('/'));
      char* end = nullptr;
      const long k = std::strtol(index.c_str(), &end, 10);
      if (end == index.c_str() || *end != '\0' || k == 0) r.fail("\"" + t[i] + "\" is not a vertex index");
      const long n = long(vertices.size());
      const long v = k > 0 ? k - 1 : n + k;   // OBJ: 1-based, negative counts back
      if (v < 0 || v >= n) r.fail("vertex " + std::to_string(k) + " does not exist (" + std::to_string(n) + " so far)");
      current.push_back(vertices[std::size_t(v)]);
    }
    r.finish(out, current);
  }
  r.finish(out, current);
  if (out.empty())
    throw IoError(file_name, "", obj ? "no `l` element (an OBJ polyline is `l i j k ...`)"
                                     : "no polyline (expected one \"x y z\" per line)");
  return out;
}

}  // namespace gsp::lines
