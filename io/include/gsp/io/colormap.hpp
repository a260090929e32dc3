#pragma once
// Perceptually uniform colour maps for scalar fields (used by writers and the renderer).
#include <array>
#include <cstdint>
#include <vector>

namespace gsp::io {

enum class ColorMap { viridis, turbo };

// t in [0, 1] (clamped); NaN or infinite t gives a neutral grey.
std::array<std::uint8_t, 4> colormap(ColorMap map, double t);

// Colours for a field: values scaled by [lo, hi] (hi <= lo: use the finite min/max),
// non-finite values (unreached) grey.
std::vector<std::array<std::uint8_t, 4>> colorize(const std::vector<double>& values,
                                                  ColorMap map = ColorMap::viridis,
                                                  double lo = 0.0, double hi = -1.0);

}  // namespace gsp::io
