#pragma once
// An RGBA picture in memory and its PNG form.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace gsp::render {

using Rgba = std::array<std::uint8_t, 4>;

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;   // row-major, top row first, 4 bytes per pixel

  Image() = default;
  Image(int w, int h, Rgba fill = {0, 0, 0, 0});
  Rgba pixel(int x, int y) const;
  void set(int x, int y, Rgba c);
};

// 8-bit RGBA PNG, written atomically (gsp::io::AtomicFile): an error never leaves a partial
// file and never half-overwrites an existing one. Throws gsp::IoError.
void write_png(const std::string& path, const Image& image);

// Any PNG libpng reads, converted to 8-bit RGBA. Throws gsp::IoError.
Image read_png(const std::string& path);

}  // namespace gsp::render
