#pragma once
// Pixel statistics for the gsp::render tests: pictures are checked by counting and locating
// pixels, never by eye.
#include <gsp/render/image.hpp>

#include <cstdlib>
#include <functional>

namespace gsp::test {

inline bool same(render::Rgba a, render::Rgba b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2] && a[3] == b[3];
}

inline bool near(render::Rgba a, render::Rgba b, int tolerance) {
  for (int k = 0; k < 4; ++k)
    if (std::abs(int(a[k]) - int(b[k])) > tolerance) return false;
  return true;
}

inline double luminance(render::Rgba c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

inline std::size_t count_if(const render::Image& im, const std::function<bool(int, int, render::Rgba)>& pred) {
  std::size_t n = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) n += pred(x, y, im.pixel(x, y)) ? 1 : 0;
  return n;
}

// Bounding box of the pixels that satisfy pred; false when there are none.
struct PixelBox {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  bool empty() const { return x1 < 0; }
};
inline PixelBox box_of(const render::Image& im, const std::function<bool(render::Rgba)>& pred) {
  PixelBox b;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      if (pred(im.pixel(x, y))) {
        b.x0 = std::min(b.x0, x);
        b.y0 = std::min(b.y0, y);
        b.x1 = std::max(b.x1, x);
        b.y1 = std::max(b.y1, y);
      }
  return b;
}

}  // namespace gsp::test
