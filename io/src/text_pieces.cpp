#include "text_pieces.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <thread>

namespace gsp::io::detail {

namespace {

// Line ends in `t`, eight bytes at a time (std::count compares byte by byte: 16% of reading a
// PLY ascii body on two threads went to it).
std::size_t count_line_ends(std::string_view t) {
  constexpr std::uint64_t ones = 0x0101010101010101ull, low7 = 0x7f7f7f7f7f7f7f7full;
  std::size_t n = 0, i = 0;
  for (; i + 8 <= t.size(); i += 8) {
    std::uint64_t w;
    std::memcpy(&w, t.data() + i, 8);
    const std::uint64_t x = w ^ (ones * '\n');   // a zero byte where there was a line end
    const std::uint64_t zero = ~(((x & low7) + low7) | x | low7);
    n += static_cast<std::size_t>(__builtin_popcountll(zero));
  }
  for (; i < t.size(); ++i) n += t[i] == '\n';
  return n;
}

}  // namespace

unsigned reading_threads(const ReadOptions& options, std::size_t bytes) {
  if (bytes < options.parallel_from_bytes) return 1;
  const unsigned wanted = options.threads > 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  // At least half the threshold per thread: a 1 MB file is not cut in 64 on a big machine.
  const std::size_t most = std::max<std::size_t>(1, bytes / std::max<std::size_t>(1, options.parallel_from_bytes / 2));
  return unsigned(std::min<std::size_t>(wanted, most));
}

std::vector<TextPiece> cut_at_lines(std::string_view text, unsigned parts) {
  std::vector<TextPiece> pieces;
  parts = std::max(1u, parts);
  std::size_t begin = 0;
  for (unsigned p = 0; p < parts && begin < text.size(); ++p) {
    std::size_t end = text.size();
    if (p + 1 < parts) {
      const std::size_t aim = std::max(begin, text.size() / parts * (p + 1));
      const std::size_t nl = text.find('\n', aim);
      end = nl == std::string_view::npos ? text.size() : nl + 1;
    }
    pieces.push_back({text.substr(begin, end - begin), 0, 0});
    begin = end;
  }
  for_each_piece(pieces.size(), [&](std::size_t i) {
    const std::string_view t = pieces[i].text;
    pieces[i].lines = count_line_ends(t) + (!t.empty() && t.back() != '\n' ? 1 : 0);
  });
  for (std::size_t i = 1; i < pieces.size(); ++i) pieces[i].first_line = pieces[i - 1].first_line + pieces[i - 1].lines;
  return pieces;
}

}  // namespace gsp::io::detail
