#pragma once
// Big text bodies read on several threads (the fast paths of the PLY ascii and OBJ readers):
// the text is cut at line ends into one piece per thread, each piece knows the index of its
// first line, and the pieces are parsed at once. A fast path that meets anything irregular
// gives up, and the reader's serial parser reads the file again and reports the error with
// its line: the parallel code never has to say where a file went wrong.
#include <gsp/io/mesh_io.hpp>

#include <cstddef>
#include <exception>
#include <string_view>
#include <thread>
#include <vector>

namespace gsp::io::detail {

// Threads for parsing `bytes` of text: 1 below options.parallel_from_bytes, else
// options.threads (the machine's cores when that is 0), but no more than leave each thread half
// of parallel_from_bytes.
unsigned reading_threads(const ReadOptions& options, std::size_t bytes);

struct TextPiece {
  std::string_view text;      // whole lines (the last piece may end without a line end)
  std::size_t first_line = 0; // index of its first line in the whole text, from 0
  std::size_t lines = 0;      // lines in it: line ends, plus a last line without one
};

// Cuts `text` into at most `parts` pieces of about equal size at line ends and counts their
// lines (on `parts` threads).
std::vector<TextPiece> cut_at_lines(std::string_view text, unsigned parts);

// The lines of a piece in order, without their line end (and without a '\r' before it).
class PieceLines {
 public:
  explicit PieceLines(std::string_view text) : text_(text) {}
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(pos_, end - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = end + 1;
    return true;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
};

// The next whitespace-separated token of `line` from `pos` on; false when none is left.
inline bool next_token(std::string_view line, std::size_t& pos, std::string_view& token) {
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  while (pos < line.size() && space(line[pos])) ++pos;
  if (pos >= line.size()) return false;
  const std::size_t start = pos;
  while (pos < line.size() && !space(line[pos])) ++pos;
  token = line.substr(start, pos - start);
  return true;
}

// Runs work(i) for every i < n, each on its own thread (0 on the caller's); returns when all
// are done and rethrows the first failure. (libgsp's for_ranges does the same for the core,
// which io cannot include: it is internal to gsp::core.)
template <class Work>
void for_each_piece(std::size_t n, Work&& work) {
  std::vector<std::exception_ptr> failed(n);
  std::vector<std::thread> threads;
  threads.reserve(n > 0 ? n - 1 : 0);
  for (std::size_t i = 1; i < n; ++i)
    threads.emplace_back([&, i] {
      try {
        work(i);
      } catch (...) {
        failed[i] = std::current_exception();
      }
    });
  if (n > 0) {
    try {
      work(0);
    } catch (...) {
      failed[0] = std::current_exception();
    }
  }
  for (std::thread& t : threads) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace gsp::io::detail
