// The apps' operator new (apps/common/huge_page_new.cpp, compiled into this test as into every
// app): big allocations start on a 2 MB boundary (where a huge page can back them) and, where
// the kernel's transparent huge pages are on or on request, are backed by huge pages once
// touched; small ones are plain malloc; every one is released by the ordinary delete.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;

// This process's AnonHugePages in kB (/proc/self/smaps_rollup), or -1 where it cannot be read.
long anon_huge_kb() {
  std::ifstream in("/proc/self/smaps_rollup");
  std::string key;
  long value = -1;
  while (in >> key) {
    if (key == "AnonHugePages:") {
      in >> value;
      return value;
    }
    in.ignore(1 << 12, '\n');
  }
  return -1;
}

std::string thp_mode() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  std::getline(in, line);
  return line;
}

// Sanitizer builds keep the sanitizer's operator new (huge_page_new.cpp says why).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kReplaced = false;
#else
constexpr bool kReplaced = true;
#endif

TEST(AppHugePages, BigArraysStartOnAHugePageBoundary) {
  if (!kReplaced) GTEST_SKIP() << "sanitizer build: the sanitizer's operator new";
  for (std::size_t mb : {2, 3, 5, 8, 9, 64}) {
    std::vector<std::uint8_t> big(mb << 20);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(big.data()) % kHugePage, 0u) << mb << " MB";
  }
  // Just under 2 MB: malloc's (a 2 MB boundary would give it no huge page).
  std::size_t under_aligned = 0;
  std::vector<std::unique_ptr<char[]>> under;
  for (int i = 0; i < 8; ++i) {
    under.emplace_back(new char[(std::size_t(2) << 20) - 4096]);
    under_aligned += reinterpret_cast<std::uintptr_t>(under.back().get()) % kHugePage == 0;
  }
  EXPECT_LT(under_aligned, 8u);
  const std::unique_ptr<char[]> array(new char[std::size_t(16) << 20]);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(array.get()) % kHugePage, 0u);
  // Small ones are malloc's: nothing forces them onto the boundary.
  std::size_t aligned = 0;
  std::vector<std::unique_ptr<std::uint64_t[]>> small;
  for (int i = 0; i < 64; ++i) {
    small.emplace_back(new std::uint64_t[1000]);
    aligned += reinterpret_cast<std::uintptr_t>(small.back().get()) % kHugePage == 0;
  }
  EXPECT_LT(aligned, 64u);
  char* nothrow = new (std::nothrow) char[std::size_t(32) << 20];
  ASSERT_NE(nothrow, nullptr);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(nothrow) % kHugePage, 0u);
  delete[] nothrow;
}

TEST(AppHugePages, TouchedBigArraysAreBackedByHugePages) {
  if (!kReplaced) GTEST_SKIP() << "sanitizer build: the sanitizer's operator new";
  const std::string mode = thp_mode();
  if (mode.find("[never]") != std::string::npos || mode.empty() || anon_huge_kb() < 0)
    GTEST_SKIP() << "transparent huge pages off or not reported here: " << mode;
  const long before = anon_huge_kb();
  std::vector<std::uint8_t> big(std::size_t(64) << 20);
  std::memset(big.data(), 1, big.size());
  // Where the kernel has no huge page at hand it falls back to small pages; most of 64 MB is
  // still expected on huge ones on an idle machine.
  EXPECT_GE(anon_huge_kb() - before, 32 * 1024) << mode;
}

TEST(AppHugePages, ArraysFromTwoMegabytesGetHugePagesWithoutRounding) {
  if (!kReplaced) GTEST_SKIP() << "sanitizer build: the sanitizer's operator new";
  const std::string mode = thp_mode();
  if (mode.find("[never]") != std::string::npos || mode.empty() || anon_huge_kb() < 0)
    GTEST_SKIP() << "transparent huge pages off or not reported here: " << mode;
  // Eight arrays of 6 MB and a bit: three whole huge pages each (24 MB of 2 MB ranges in all);
  // their tails are not rounded up, so at most 48 MB of huge pages can appear.
  const long before = anon_huge_kb();
  std::vector<std::vector<std::uint8_t>> arrays;
  for (int i = 0; i < 8; ++i) {
    arrays.emplace_back((std::size_t(6) << 20) + 100000);
    std::memset(arrays.back().data(), 1, arrays.back().size());
  }
  const long gained = anon_huge_kb() - before;
  EXPECT_GE(gained, 24 * 1024) << mode;
  // In mode "always" the kernel may back a tail's neighbourhood on its own; in "madvise" only
  // the advised ranges are huge, and nothing was rounded up.
  if (mode.find("[madvise]") != std::string::npos) EXPECT_LE(gained, 48 * 1024) << mode;
}

}  // namespace
