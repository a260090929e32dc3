// An OBJ file read on several threads (obj_parts.hpp). Each piece of whole lines collects its
// own vertices, triangles and counts; a negative (relative) index is resolved once the pieces
// before it are counted; then the pieces are copied into place side by side. Values go through
// the serial reader's conversions, so the result is the same to the bit; at the first
// irregularity the attempt is dropped and the serial reader names the error.
#include "obj_parts.hpp"
#include "parse_util.hpp"
#include "text_pieces.hpp"

#include <algorithm>
#include <atomic>
#include <cstring>

namespace gsp::io::detail {

namespace {

struct Piece {
  std::vector<Vec3> positions;
  std::vector<std::array<double, 3>> colors;
  bool all_colored = true;
  std::vector<Triangle> triangles;
  // A triangle corner given by a negative index: `back` counts from this piece's first
  // vertex (negative when it points into the pieces before).
  struct Relative {
    std::size_t corner;   // 3 * triangle + corner, in this piece
    long long back;
  };
  std::vector<Relative> relative;
  std::size_t faces = 0, polygons = 0;
  long long max_index = -1;   // of the plain (positive) indices
  std::map<std::string, std::size_t> skipped;
};

struct Corner {
  long long value;   // resolved index, or `back` (relative)
  bool relative;
};

bool vertex_line(std::string_view line, std::size_t pos, Piece& p) {
  std::string_view tok[6];
  int n = 0;
  while (n < 6 && next_token(line, pos, tok[n])) ++n;
  double c[3];
  if (n < 3) return false;
  for (int i = 0; i < 3; ++i)
    if (!parse_double(tok[i], c[i])) return false;
  if (!finite3(c[0], c[1], c[2])) return false;
  p.positions.push_back({c[0], c[1], c[2]});
  double rgb[3];
  if (n >= 6 && parse_double(tok[3], rgb[0]) && parse_double(tok[4], rgb[1]) && parse_double(tok[5], rgb[2])) {
    if (p.all_colored) p.colors.push_back({rgb[0], rgb[1], rgb[2]});
  } else {
    p.all_colored = false;
  }
  return true;
}

bool face_line(std::string_view line, std::size_t pos, Piece& p, std::vector<Corner>& corners) {
  corners.clear();
  std::string_view tok;
  while (next_token(line, pos, tok)) {
    const std::size_t slash = tok.find('/');
    if (slash != std::string_view::npos) tok = tok.substr(0, slash);
    long long idx;
    if (!parse_int(tok, idx) || idx == 0) return false;
    if (idx > 0) {
      if (idx - 1 >= static_cast<long long>(kInvalidIndex)) return false;
      p.max_index = std::max(p.max_index, idx - 1);
      corners.push_back({idx - 1, false});
    } else {
      corners.push_back({static_cast<long long>(p.positions.size()) + idx, true});
    }
  }
  if (corners.size() < 3) return false;
  ++p.faces;
  if (corners.size() > 3) ++p.polygons;
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
    const Corner fan[3] = {corners[0], corners[i], corners[i + 1]};
    Triangle t{};
    for (int c = 0; c < 3; ++c) {
      if (fan[c].relative) p.relative.push_back({3 * p.triangles.size() + c, fan[c].value});
      else t[c] = static_cast<Index>(fan[c].value);
    }
    p.triangles.push_back(t);
  }
  return true;
}

bool read_piece(std::string_view text, Piece& p, const std::atomic<bool>& ok) {
  // Reserve for lines of about 40 bytes, half of them faces: growing by doubling copied a
  // third of the work.
  p.positions.reserve(text.size() / 80);
  p.triangles.reserve(text.size() / 60);
  PieceLines in(text);
  std::string_view line, key;
  std::vector<Corner> corners;
  for (std::size_t done = 0; in.next(line); ++done) {
    if ((done & 4095) == 0 && !ok.load(std::memory_order_relaxed)) return false;
    std::size_t pos = 0;
    if (!next_token(line, pos, key) || key.front() == '#') continue;
    if (key == "v") {
      if (!vertex_line(line, pos, p)) return false;
    } else if (key == "f") {
      if (!face_line(line, pos, p, corners)) return false;
    } else {
      ++p.skipped[std::string(key.substr(0, 16))];
    }
  }
  return true;
}

}  // namespace

bool read_obj_parallel(const std::string& bytes, unsigned threads, ReadResult& r) {
  // Pieces cut at line ends without counting the lines: a piece needs none of the others'.
  std::vector<std::string_view> texts;
  const std::string_view all(bytes);
  for (std::size_t begin = 0, p = 0; begin < all.size(); ++p) {
    std::size_t end = all.size();
    if (p + 1 < threads) {
      const std::size_t nl = all.find('\n', std::max(begin, all.size() / threads * (p + 1)));
      end = nl == std::string_view::npos ? all.size() : nl + 1;
    }
    texts.push_back(all.substr(begin, end - begin));
    begin = end;
  }
  std::vector<Piece> pieces(texts.size());
  std::atomic<bool> ok{true};
  for_each_piece(pieces.size(), [&](std::size_t i) {
    if (!read_piece(texts[i], pieces[i], ok)) ok = false;
  });
  if (!ok) return false;

  // Where each piece's vertices and triangles go; the relative indices resolved.
  std::vector<std::size_t> vertex_base(pieces.size() + 1, 0), triangle_base(pieces.size() + 1, 0);
  ObjExtras x;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    Piece& p = pieces[i];
    vertex_base[i + 1] = vertex_base[i] + p.positions.size();
    triangle_base[i + 1] = triangle_base[i] + p.triangles.size();
    for (const Piece::Relative& rel : p.relative) {
      const long long resolved = static_cast<long long>(vertex_base[i]) + rel.back;
      if (resolved < 0 || resolved >= static_cast<long long>(kInvalidIndex)) return false;
      p.triangles[rel.corner / 3][rel.corner % 3] = static_cast<Index>(resolved);
      p.max_index = std::max(p.max_index, resolved);
    }
    x.max_index = std::max(x.max_index, p.max_index);
    x.all_colored = x.all_colored && p.all_colored;
    r.info.file_faces += p.faces;
    r.info.polygons_split += p.polygons;
    for (const auto& [key, count] : p.skipped) x.skipped[key] += count;
  }
  if (x.max_index >= static_cast<long long>(vertex_base.back())) return false;   // the serial reader names the line
  if (vertex_base.back() == 0 && r.info.file_faces == 0) return false;
  TriangleMesh& m = r.mesh;
  m.positions.resize(vertex_base.back());
  m.triangles.resize(triangle_base.back());
  if (x.all_colored) x.colors.resize(vertex_base.back());
  for_each_piece(pieces.size(), [&](std::size_t i) {
    const Piece& p = pieces[i];
    std::copy(p.positions.begin(), p.positions.end(), m.positions.begin() + static_cast<std::ptrdiff_t>(vertex_base[i]));
    std::copy(p.triangles.begin(), p.triangles.end(), m.triangles.begin() + static_cast<std::ptrdiff_t>(triangle_base[i]));
    if (x.all_colored)
      std::copy(p.colors.begin(), p.colors.end(), x.colors.begin() + static_cast<std::ptrdiff_t>(vertex_base[i]));
  });
  finish_obj("", x, r);   // cannot throw: both of its errors were ruled out above
  return true;
}

}  // namespace gsp::io::detail
