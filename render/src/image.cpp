#include <gsp/render/image.hpp>

#include <gsp/errors.hpp>

#include <cstddef>
#include <string>

namespace gsp::render {

Image::Image(int w, int h, Rgba fill) : width(w), height(h) {
  if (w < 0 || h < 0) throw InvalidInput("image size " + std::to_string(w) + "x" + std::to_string(h) + " is negative");
  rgba.resize(std::size_t(w) * std::size_t(h) * 4);
  for (std::size_t i = 0; i < rgba.size(); i += 4)
    for (int c = 0; c < 4; ++c) rgba[i + c] = fill[c];
}

Rgba Image::pixel(int x, int y) const {
  const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
  return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
}

void Image::set(int x, int y, Rgba c) {
  const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
  for (int k = 0; k < 4; ++k) rgba[i + k] = c[k];
}

}  // namespace gsp::render
