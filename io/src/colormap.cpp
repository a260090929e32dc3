// Colour maps as small tables of control points, linearly interpolated in sRGB bytes.
// viridis: the published palette values (matplotlib / R viridisLite hex codes) at t = k/4, k/5,
//   k/7 and k/9, merged and sorted; they agree with the 256-entry map within 1/255.
// turbo: the polynomial approximation published with Turbo (A. Mikhailov, Google, 2019)
//   sampled at t = k/16, with the two end points taken from the reference 256-entry table
//   (the polynomial drifts there).
#include <gsp/io/colormap.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gsp::io {

namespace {

struct Stop {
  double t;
  std::uint8_t r, g, b;
};

constexpr Stop kViridis[] = {
    {0.0, 68, 1, 84},          {1.0 / 9, 72, 40, 120},    {1.0 / 7, 70, 51, 126},   {0.2, 65, 68, 135},
    {2.0 / 9, 62, 74, 137},    {0.25, 59, 82, 139},       {2.0 / 7, 54, 92, 141},   {1.0 / 3, 49, 104, 142},
    {0.4, 42, 120, 142},       {3.0 / 7, 39, 127, 142},   {4.0 / 9, 38, 130, 142},  {0.5, 33, 145, 140},
    {5.0 / 9, 31, 158, 137},   {4.0 / 7, 31, 161, 135},   {0.6, 34, 168, 132},      {2.0 / 3, 53, 183, 121},
    {5.0 / 7, 74, 193, 109},   {0.75, 94, 201, 98},       {7.0 / 9, 109, 205, 89},  {0.8, 122, 209, 81},
    {6.0 / 7, 159, 218, 58},   {8.0 / 9, 180, 222, 44},   {1.0, 253, 231, 37},
};

constexpr Stop kTurbo[] = {
    {0.0, 48, 18, 59},       {0.0625, 73, 62, 175},   {0.125, 68, 106, 238},  {0.1875, 50, 149, 247},
    {0.25, 38, 189, 225},    {0.3125, 41, 221, 187},  {0.375, 64, 243, 146},  {0.4375, 102, 253, 109},
    {0.5, 150, 250, 80},     {0.5625, 198, 235, 59},  {0.625, 238, 208, 45},  {0.6875, 255, 171, 36},
    {0.75, 255, 128, 29},    {0.8125, 238, 84, 21},   {0.875, 201, 45, 12},   {0.9375, 161, 18, 2},
    {1.0, 122, 4, 3},
};

constexpr std::array<std::uint8_t, 4> kGrey = {128, 128, 128, 255};

template <std::size_t N>
std::array<std::uint8_t, 4> lookup(const Stop (&stops)[N], double t) {
  const Stop* hi = std::upper_bound(stops, stops + N, t, [](double x, const Stop& s) { return x < s.t; });
  if (hi == stops) hi = stops + 1;
  if (hi == stops + N) hi = stops + N - 1;
  const Stop& a = hi[-1];
  const Stop& b = *hi;
  const double u = std::clamp((t - a.t) / (b.t - a.t), 0.0, 1.0);
  auto mix = [u](std::uint8_t x, std::uint8_t y) { return static_cast<std::uint8_t>(std::lround(x + u * (y - x))); };
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b), 255};
}

}  // namespace

std::array<std::uint8_t, 4> colormap(ColorMap map, double t) {
  if (!std::isfinite(t)) return kGrey;
  t = std::clamp(t, 0.0, 1.0);
  return map == ColorMap::turbo ? lookup(kTurbo, t) : lookup(kViridis, t);
}

std::vector<std::array<std::uint8_t, 4>> colorize(const std::vector<double>& values, ColorMap map, double lo, double hi) {
  if (!(hi > lo)) {
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (double v : values)
      if (std::isfinite(v)) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
  }
  const double range = hi - lo;
  std::vector<std::array<std::uint8_t, 4>> out;
  out.reserve(values.size());
  for (double v : values) {
    if (!std::isfinite(v)) out.push_back(kGrey);
    else out.push_back(colormap(map, range > 0 ? (v - lo) / range : 0.0));   // constant field: low end
  }
  return out;
}

}  // namespace gsp::io
