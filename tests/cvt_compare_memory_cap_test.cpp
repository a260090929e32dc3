// gsp-cvt-compare's cap on the address space around CGAL's remeshing (memory_cap.hpp): an
// allocation larger than the free memory fails with std::bad_alloc while the cap holds (instead
// of the kernel killing the process later), and the limit is back as it was afterwards.
#include "memory_cap.hpp"

#include <gsp/available_memory.hpp>

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>

namespace {

rlim_t soft_limit() {
  rlimit r{};
  getrlimit(RLIMIT_AS, &r);
  return r.rlim_cur;
}

char* volatile sink = nullptr;   // the allocation escapes, so the compiler cannot drop it

// Allocates `bytes` (touching the first page); true if the allocation succeeded.
bool allocate(std::size_t bytes) {
  try {
    std::unique_ptr<char[]> p(new char[bytes]);
    sink = p.get();
    sink[0] = 1;
    return true;
  } catch (const std::bad_alloc&) {
    return false;
  }
}

TEST(CvtCompareMemoryCap, AllocationsBeyondTheFreeMemoryFailWhileCapped) {
  const std::size_t free = gsp::available_memory();
  if (free == 0) GTEST_SKIP() << "MemAvailable cannot be read here";
  const rlim_t before = soft_limit();
  {
    const gsp::cvt_compare::AddressSpaceCap cap(0.5);
    if (before != RLIM_INFINITY && cap.headroom() == 0) GTEST_SKIP() << "a lower limit is set already";
    ASSERT_GT(cap.headroom(), 0u);
    // The cap reads MemAvailable itself: other processes (ctest -j) may have freed memory
    // between the two reads, so it is held against the larger of this one and one after.
    EXPECT_LE(cap.headroom(), std::max(free, gsp::available_memory()) / 2 + 1);
    EXPECT_NE(soft_limit(), before);
    // Twice the headroom cannot fit under the cap; a small block still can.
    EXPECT_FALSE(allocate(2 * cap.headroom()));
    EXPECT_TRUE(allocate(std::size_t(1) << 20));
  }
  EXPECT_EQ(soft_limit(), before);
}

}  // namespace
