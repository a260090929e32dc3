#pragma once
// Shared by the readers: a line/token scanner for text formats and a bounds-checked cursor for
// binary formats. Both work on the whole file held in memory and throw gsp::IoError naming the
// file and the line or byte offset, so no reader ever reads past the end of its input.
#include <gsp/errors.hpp>
#include <gsp/types.hpp>

#include <cstdint>
#include <cmath>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace gsp::io::detail {

std::string line_at(std::size_t line);   // "line N"
std::string byte_at(std::size_t byte);   // "byte N"

// Number parsing without locale or exceptions; false when `s` is not entirely a number.
bool parse_double(std::string_view s, double& out);
bool parse_int(std::string_view s, long long& out);
// An integer, or a whole number written as a decimal ("3.0", as some writers store indices).
bool parse_int_or_whole(std::string_view s, long long& out);

// Splits `line` into whitespace-separated tokens (appended to `out` after clearing it).
void split(std::string_view line, std::vector<std::string_view>& out);

// Walks a text file line by line; strips "\r" so CRLF files read like LF files.
class LineScanner {
 public:
  LineScanner(const std::string& path, std::string_view text) : path_(path), text_(text) {}
  // The next line (without its end), or false at the end of the text.
  bool next(std::string_view& line);
  std::size_t line_number() const { return line_; }   // 1-based number of the last line returned
  std::size_t remaining_bytes() const { return text_.size() - pos_; }
  [[noreturn]] void fail(const std::string& what) const;

 private:
  const std::string& path_;
  std::string_view text_;
  std::size_t pos_ = 0, line_ = 0;
};

// A whitespace-separated token stream over text that may cross lines (PLY ascii bodies).
class TokenScanner {
 public:
  TokenScanner(const std::string& path, std::string_view text, std::size_t first_line)
      : path_(path), text_(text), line_(first_line) {}
  bool next(std::string_view& token);   // false at the end
  std::string_view need(const char* what);   // throws when the text ends
  double need_double(const char* what);
  long long need_int(const char* what);
  std::size_t line_number() const { return line_; }
  // Line of the next token (skips the whitespace before it), for messages about what follows.
  std::size_t next_line_number() {
    skip_space();
    return line_;
  }
  std::size_t remaining_bytes() const { return text_.size() - pos_; }
  [[noreturn]] void fail(const std::string& what) const;

 private:
  void skip_space();
  const std::string& path_;
  std::string_view text_;
  std::size_t pos_ = 0, line_;
};

// Reads little- or big-endian scalars from a byte range; throws at the offset where data ends.
class ByteCursor {
 public:
  ByteCursor(const std::string& path, const std::uint8_t* data, std::size_t size, std::size_t pos = 0)
      : path_(path), data_(data), size_(size), pos_(pos) {}

  std::size_t pos() const { return pos_; }
  std::size_t remaining() const { return size_ - pos_; }
  void need(std::size_t bytes, const char* what) const {
    if (bytes > size_ - pos_) truncated(bytes, what);
  }
  void skip(std::size_t bytes, const char* what) {
    need(bytes, what);
    pos_ += bytes;
  }
  template <class T>
  T read(bool big_endian, const char* what) {
    need(sizeof(T), what);
    std::uint8_t b[sizeof(T)];
    std::memcpy(b, data_ + pos_, sizeof(T));
    if (big_endian) {
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    }
    T v;
    std::memcpy(&v, b, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  [[noreturn]] void fail(const std::string& what) const;
  [[noreturn]] void truncated(std::size_t bytes, const char* what) const;

 private:
  const std::string& path_;
  const std::uint8_t* data_;
  std::size_t size_, pos_;
};

// Appends the fan triangulation (c0, ci, ci+1) of a polygon; the caller checks corners >= 3.
inline void add_fan(std::vector<Triangle>& tris, const Index* corners, std::size_t n) {
  for (std::size_t i = 1; i + 1 < n; ++i) tris.push_back({corners[0], corners[i], corners[i + 1]});
}

// "vertex 12 has a non-finite coordinate" when p is NaN or infinite.
inline bool finite3(double x, double y, double z) {
  return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

}  // namespace gsp::io::detail
