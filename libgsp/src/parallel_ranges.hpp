#pragma once
// One loop on several threads (internal): [0, n) cut into `threads` contiguous ranges,
// fn(begin, end, part) on range number `part`, the first on the caller's thread; returns when
// all are done and rethrows the first failure. A full query on several threads runs its
// per-face and per-vertex passes (starting state, vertex minima, relaxation's scan, result)
// with it.
#include <cstddef>
#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace gsp::detail {

// Below this many elements per thread a thread's start costs more than its share.
inline constexpr std::size_t kMinPerThread = 4096;

// How many ranges for_ranges(threads, n, ...) runs: `threads`, or 1 for a small loop.
inline unsigned ranges_used(unsigned threads, std::size_t n) {
  return threads > 1 && n >= threads * kMinPerThread ? threads : 1u;
}

template <class Fn>
void for_ranges(unsigned threads, std::size_t n, Fn&& fn) {
  if (ranges_used(threads, n) == 1) {
    fn(std::size_t(0), n, 0u);
    return;
  }
  auto bound = [&](unsigned k) { return n / threads * k + std::min<std::size_t>(k, n % threads); };
  std::vector<std::exception_ptr> failed(threads);
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (unsigned k = 1; k < threads; ++k)
    pool.emplace_back([&, k] {
      try {
        fn(bound(k), bound(k + 1), k);
      } catch (...) {
        failed[k] = std::current_exception();
      }
    });
  try {
    fn(bound(0), bound(1), 0u);
  } catch (...) {
    failed[0] = std::current_exception();
  }
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace gsp::detail
