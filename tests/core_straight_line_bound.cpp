// detail::raise_to_straight_line (libgsp/src, internal): a value below the straight line to
// the sources is raised to it. Clearly below: to the nearest source's line, with that source's
// label. Within 1e-6 of its own source's line (rounding of a straight geodesic): to that line,
// label kept, no search over the sources. Values above stay; unreached ones stay; several
// threads give the values of one.
#include "straight_line_bound.hpp"   // internal (libgsp/src)

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace gsp::detail {
namespace {

const std::vector<SourcePoint> kSources = {{{0, 0, 0}, 0.0}, {{10, 0, 0}, 0.5}};

TEST(CoreStraightLineBound, ClearlyBelowGoesToTheNearestSourcesLine) {
  // x = (6, 0, 0): 6 from source 0, 4 + 0.5 from source 1. Labelled 0 with 3 (far below 6).
  std::vector<Vec3> positions = {{6, 0, 0}};
  std::vector<double> d = {3.0};
  std::vector<Index> label = {0};
  EXPECT_EQ(raise_to_straight_line<double>(1, nullptr, positions, d.data(), label.data(), 1.0, false, kSources), 1u);
  EXPECT_DOUBLE_EQ(d[0], 4.5);
  EXPECT_EQ(label[0], 1u);
}

TEST(CoreStraightLineBound, WithinRoundingOfItsOwnLineGoesToThatLine) {
  // x = (3, 4, 0): 5 from source 0; the value 5 less 3e-7 of it, labelled 0.
  std::vector<Vec3> positions = {{3, 4, 0}};
  std::vector<double> d = {5.0 * (1 - 3e-7)};
  std::vector<Index> label = {0};
  EXPECT_EQ(raise_to_straight_line<double>(1, nullptr, positions, d.data(), label.data(), 1.0, false, kSources), 0u);
  EXPECT_GE(d[0], 5.0);
  EXPECT_LE(d[0], 5.0 * (1 + 1e-12));
  EXPECT_EQ(label[0], 0u);
}

TEST(CoreStraightLineBound, ValuesAboveAndUnreachedStay) {
  std::vector<Vec3> positions = {{3, 4, 0}, {1, 1, 1}};
  std::vector<double> d = {5.5, std::numeric_limits<double>::infinity()};
  std::vector<Index> label = {0, kInvalidIndex};
  EXPECT_EQ(raise_to_straight_line<double>(2, nullptr, positions, d.data(), label.data(), 1.0, false, kSources), 0u);
  EXPECT_EQ(d[0], 5.5);
  EXPECT_TRUE(std::isinf(d[1]));
  EXPECT_EQ(label[1], kInvalidIndex);
}

TEST(CoreStraightLineBound, SeveralThreadsGiveTheValuesOfOne) {
  // 40,000 points on a line through both sources, values a mix of above, within rounding and
  // clearly below; scaled float values as a full query keeps them (mean edge 0.25).
  const std::size_t n = 40000;
  std::vector<Vec3> positions(n);
  std::vector<float> d(n);
  std::vector<Index> label(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = 12.0 * double(i) / double(n);
    positions[i] = {x, 0.1, 0};
    const double line = std::min(std::hypot(x, 0.1), std::hypot(x - 10, 0.1) + 0.5);
    const double factor = i % 3 == 0 ? 1.01 : i % 3 == 1 ? 1 - 2e-7 : 0.7;
    d[i] = float(line * factor / 0.25);
    label[i] = Index(i % 2);
  }
  std::vector<float> d1 = d, d2 = d;
  std::vector<Index> l1 = label, l2 = label;
  const std::size_t r1 = raise_to_straight_line<float>(n, nullptr, positions, d1.data(), l1.data(), 0.25, true, kSources);
  const std::size_t r2 =
      raise_to_straight_line<float>(n, nullptr, positions, d2.data(), l2.data(), 0.25, true, kSources, 2);
  EXPECT_GT(r1, n / 4);
  EXPECT_EQ(r1, r2);
  EXPECT_EQ(d1, d2);
  EXPECT_EQ(l1, l2);
  for (std::size_t i = 0; i < n; ++i) {
    const double line = std::min(distance(positions[i], kSources[0].position),
                                 distance(positions[i], kSources[1].position) + 0.5);
    ASSERT_GE(double(d1[i]) * 0.25, line) << i;
  }
}

}  // namespace
}  // namespace gsp::detail

// Many sources go through a k-d tree: the same bound and the same source as a scan over all of
// them, the first in source order on ties (sources at one place, bounds equal through offsets).
TEST(CoreStraightLineBound, NearestOfManySourcesIsTheScansNearest) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const bool offsets : {false, true}) {
    std::vector<gsp::detail::SourcePoint> sources;
    for (int i = 0; i < 700; ++i) {
      const gsp::Vec3 p{u(rng), u(rng), 0.1 * u(rng)};
      const double o = offsets ? 0.2 * (u(rng) + 1) : 0.0;
      sources.push_back({p, o});
      if (i % 50 == 0) sources.push_back({p, o});   // the same source twice: the first wins
    }
    const gsp::detail::NearestSource nearest(sources);
    for (int k = 0; k < 3000; ++k) {
      const gsp::Vec3 x = k < 40 ? sources[std::size_t(k) * 17].position : gsp::Vec3{1.5 * u(rng), 1.5 * u(rng), u(rng)};
      double bound = std::numeric_limits<double>::infinity();
      gsp::Index index = gsp::kInvalidIndex;
      for (std::size_t s = 0; s < sources.size(); ++s) {
        const double b = gsp::distance(x, sources[s].position) + sources[s].offset;
        if (b < bound) bound = b, index = gsp::Index(s);
      }
      const auto [got_bound, got_index] = nearest(x);
      ASSERT_EQ(got_bound, bound) << "point " << k << " offsets " << offsets;
      ASSERT_EQ(got_index, index) << "point " << k << " offsets " << offsets;
    }
  }
}
