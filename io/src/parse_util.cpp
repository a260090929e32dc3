#include "parse_util.hpp"

#include <charconv>
#include <cmath>

namespace gsp::io::detail {

std::string line_at(std::size_t line) { return "line " + std::to_string(line); }
std::string byte_at(std::size_t byte) { return "byte " + std::to_string(byte); }

bool parse_double(std::string_view s, double& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);   // from_chars rejects a leading '+'
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

bool parse_int(std::string_view s, long long& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

void split(std::string_view line, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
}

bool LineScanner::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) end = text_.size();
  line = text_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = end < text_.size() ? end + 1 : end;
  ++line_;
  return true;
}

void LineScanner::fail(const std::string& what) const { throw IoError(path_, line_at(line_), what); }

void TokenScanner::skip_space() {
  while (pos_ < text_.size() && is_space(text_[pos_])) {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }
}

bool TokenScanner::next(std::string_view& token) {
  skip_space();
  if (pos_ >= text_.size()) return false;
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
  token = text_.substr(start, pos_ - start);
  return true;
}

std::string_view TokenScanner::need(const char* what) {
  std::string_view t;
  if (!next(t)) fail(std::string("file ends where ") + what + " was expected");
  return t;
}

double TokenScanner::need_double(const char* what) {
  const std::string_view t = need(what);
  double v;
  if (!parse_double(t, v)) fail("'" + std::string(t.substr(0, 40)) + "' is not a number (" + what + ")");
  return v;
}

bool parse_int_or_whole(std::string_view s, long long& out) {
  if (parse_int(s, out)) return true;
  // Some writers store integers as "3.0"; accept them when they are whole numbers.
  double d;
  if (parse_double(s, d) && std::isfinite(d) && std::abs(d) < 9e15 && d == std::floor(d)) {
    out = static_cast<long long>(d);
    return true;
  }
  return false;
}

long long TokenScanner::need_int(const char* what) {
  const std::string_view t = need(what);
  long long v;
  if (!parse_int_or_whole(t, v)) fail("'" + std::string(t.substr(0, 40)) + "' is not an integer (" + what + ")");
  return v;
}

void TokenScanner::fail(const std::string& what) const { throw IoError(path_, line_at(line_), what); }

void ByteCursor::fail(const std::string& what) const { throw IoError(path_, byte_at(pos_), what); }

void ByteCursor::truncated(std::size_t bytes, const char* what) const {
  throw IoError(path_, byte_at(pos_),
                std::string("truncated: ") + what + " needs " + std::to_string(bytes) + " bytes, " +
                    std::to_string(size_ - pos_) + " left");
}

}  // namespace gsp::io::detail
