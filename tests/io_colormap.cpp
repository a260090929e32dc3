// Colour maps: published end points, grey for non-finite values, clamping, viridis' monotone
// luminance, and colorize's automatic range.
#include <gsp/io/colormap.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using gsp::io::ColorMap;
using gsp::io::colormap;
using Rgba = std::array<std::uint8_t, 4>;

TEST(Colormap, EndPoints) {
  EXPECT_EQ(colormap(ColorMap::viridis, 0.0), (Rgba{68, 1, 84, 255}));     // #440154
  EXPECT_EQ(colormap(ColorMap::viridis, 1.0), (Rgba{253, 231, 37, 255}));  // #fde725
  EXPECT_EQ(colormap(ColorMap::viridis, 0.5), (Rgba{33, 145, 140, 255}));  // #21918c
  EXPECT_EQ(colormap(ColorMap::turbo, 0.0), (Rgba{48, 18, 59, 255}));
  EXPECT_EQ(colormap(ColorMap::turbo, 1.0), (Rgba{122, 4, 3, 255}));
}

TEST(Colormap, ClampsAndGreysOut) {
  EXPECT_EQ(colormap(ColorMap::viridis, -3.0), colormap(ColorMap::viridis, 0.0));
  EXPECT_EQ(colormap(ColorMap::turbo, 7.0), colormap(ColorMap::turbo, 1.0));
  const Rgba grey{128, 128, 128, 255};
  EXPECT_EQ(colormap(ColorMap::viridis, std::nan("")), grey);
  EXPECT_EQ(colormap(ColorMap::turbo, std::numeric_limits<double>::infinity()), grey);
}

TEST(Colormap, ViridisLuminanceIncreases) {
  double last = -1;
  for (int i = 0; i <= 100; ++i) {
    const Rgba c = colormap(ColorMap::viridis, i / 100.0);
    const double y = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    EXPECT_GE(y, last) << "t = " << i / 100.0;
    last = y;
  }
}

TEST(Colormap, ColorizeScalesByFiniteRange) {
  const double inf = std::numeric_limits<double>::infinity();
  const auto c = gsp::io::colorize({2.0, 4.0, inf, 3.0});
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[0], colormap(ColorMap::viridis, 0.0));
  EXPECT_EQ(c[1], colormap(ColorMap::viridis, 1.0));
  EXPECT_EQ(c[2], (Rgba{128, 128, 128, 255}));
  EXPECT_EQ(c[3], colormap(ColorMap::viridis, 0.5));
  const auto fixed = gsp::io::colorize({0.0, 5.0, 10.0}, ColorMap::turbo, 0.0, 20.0);
  EXPECT_EQ(fixed[2], colormap(ColorMap::turbo, 0.5));
  const auto flat = gsp::io::colorize({1.0, 1.0});
  EXPECT_EQ(flat[0], colormap(ColorMap::viridis, 0.0));
}

}  // namespace
