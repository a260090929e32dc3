// The pieces a full query on several threads is made of (libgsp/src, internal): for_ranges
// covers every index once and passes failures on; the state's allocator hands out huge-page
// aligned, uninitialised arrays that behave as vectors; the relaxation's scan on several
// threads gives the one-thread values and lowered vertices.
#include "parallel_ranges.hpp"     // internal (libgsp/src)
#include "state_allocator.hpp"     // internal
#include "vertex_relaxation.hpp"   // internal

#include "helpers/geodesic_fixtures.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <thread>
#include <vector>

namespace gsp::test {
namespace {

TEST(CoreParallelPasses, RangesCoverEveryIndexOnceInOrder) {
  for (unsigned threads : {1u, 2u, 3u, 7u})
    for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(5000), std::size_t(40000), std::size_t(40001)}) {
      std::vector<std::atomic<int>> hits(n);
      std::vector<std::pair<std::size_t, std::size_t>> parts(threads, {1, 0});
      std::atomic<unsigned> calls{0};
      std::thread::id caller = std::this_thread::get_id(), first;
      detail::for_ranges(threads, n, [&](std::size_t begin, std::size_t end, unsigned part) {
        ++calls;
        parts[part] = {begin, end};
        if (part == 0) first = std::this_thread::get_id();
        for (std::size_t i = begin; i < end; ++i) ++hits[i];
      });
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(hits[i], 1) << i << " of " << n << ", " << threads << " threads";
      EXPECT_EQ(first, caller);
      // Contiguous parts in order, sizes within one of each other.
      const unsigned used = calls;
      // Small loops stay on the caller's thread (kMinPerThread elements per thread at least).
      EXPECT_EQ(used, n >= threads * detail::kMinPerThread ? threads : 1u);
      for (unsigned k = 0; k + 1 < used; ++k) {
        EXPECT_EQ(parts[k].second, parts[k + 1].first);
        const std::size_t a = parts[k].second - parts[k].first, b = parts[k + 1].second - parts[k + 1].first;
        EXPECT_LE(a > b ? a - b : b - a, 1u);
      }
    }
}

TEST(CoreParallelPasses, AFailureInAnyRangeReachesTheCallerAfterAllFinish) {
  std::atomic<int> finished{0};
  EXPECT_THROW(detail::for_ranges(3, 3 * detail::kMinPerThread,
                                  [&](std::size_t, std::size_t, unsigned part) {
                                    if (part == 2) throw std::runtime_error("range 2");
                                    ++finished;
                                  }),
               std::runtime_error);
  EXPECT_EQ(finished, 2);
}

TEST(CoreParallelPasses, StateArraysAreHugePageAlignedVectors) {
  using Array = std::vector<std::uint64_t, detail::StateAllocator<std::uint64_t>>;
  const std::size_t big = (std::size_t(9) << 20) / sizeof(std::uint64_t);   // 9 MB: huge pages
  Array a(big);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a.data()) % (std::size_t(2) << 20), 0u);
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = i * 3;
  Array b = a;   // copies, moves and growth go through the same allocator
  b.push_back(7);
  Array c = std::move(a);
  EXPECT_EQ(b.size(), big + 1);
  EXPECT_EQ(b[big], 7u);
  for (std::size_t i = 0; i < big; i += 4099) {
    ASSERT_EQ(b[i], i * 3);
    ASSERT_EQ(c[i], i * 3);
  }
  Array small(100, 5);   // ordinary allocation below 8 MB
  EXPECT_EQ(small[99], 5u);
}

// A jittered grid's vertices with values off their edge-path distances here and there; the
// first relaxation round (every edge) on two and three threads against one.
TEST(CoreParallelPasses, RelaxationScanOnSeveralThreadsMatchesOneThread) {
  const TriangleMesh m = jittered_grid(150, 0.2, 5);   // 45,000 faces: three threads' ranges
  std::vector<double> length(3 * m.num_faces());
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    for (int i = 0; i < 3; ++i)
      length[3 * f + i] = distance(m.positions[m.triangles[f][i]], m.positions[m.triangles[f][(i + 1) % 3]]);
  std::vector<Index> corner_begin(m.num_vertices() + 1, 0), corners(3 * m.num_faces());
  for (const Triangle& t : m.triangles)
    for (Index v : t) ++corner_begin[v + 1];
  for (std::size_t v = 0; v < m.num_vertices(); ++v) corner_begin[v + 1] += corner_begin[v];
  std::vector<Index> fill(corner_begin.begin(), corner_begin.end() - 1);
  for (Index c = 0; c < Index(corners.size()); ++c) corners[fill[m.triangles[c / 3][c % 3]]++] = c;
  const std::vector<bool> skipped(m.num_faces(), false);
  // Straight-line distances from vertex 0, every 7th vertex raised by 5%, every 11th by 30%.
  std::vector<float> d0(m.num_vertices());
  std::vector<Index> l0(m.num_vertices(), 0);
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    d0[v] = float(distance(m.positions[v], m.positions[0]) * (v % 11 == 3 ? 1.3 : v % 7 == 2 ? 1.05 : 1.0));
  std::vector<float> d1 = d0;
  std::vector<Index> lab1 = l0;
  std::size_t relaxed1 = 0;
  const std::vector<Index> lowered1 = detail::relax_along_edges<float>(
      m.triangles, length, 1.0, skipped, corner_begin, corners, nullptr, INFINITY, 1e-2f, d1, lab1, relaxed1);
  ASSERT_GT(lowered1.size(), 50u);
  for (unsigned threads : {2u, 3u}) {
    std::vector<float> d = d0;
    std::vector<Index> lab = l0;
    std::size_t relaxed = 0;
    const std::vector<Index> lowered = detail::relax_along_edges<float>(
        m.triangles, length, 1.0, skipped, corner_begin, corners, nullptr, INFINITY, 1e-2f, d, lab, relaxed, nullptr,
        threads);
    EXPECT_EQ(lowered, lowered1);
    for (std::size_t v = 0; v < m.num_vertices(); ++v) ASSERT_NEAR(d[v], d1[v], 1e-6 * (1 + d1[v])) << v;
  }
}

}  // namespace
}  // namespace gsp::test
