// The apps' global operator new: allocations of 2 MB or more are aligned to 2 MB and advised
// as transparent huge pages (madvise), every other one is plain malloc. Compiled into each app
// (cmake/GspModule.cmake, gsp_app), never into a library: how a process allocates is the
// program's choice, and a library that replaced operator new would impose it on its users.
//
// Why: on Linux's default THP mode "madvise" every 4 KB page of a fresh array costs a page
// fault on first touch, and a one-shot run touches fresh arrays all the time (the file, the
// mesh, the connectivity, the intrinsic triangulation, the records): on a 2-core VM the kernel's
// fault path took 17% of a gsp-geodesic run at 557k vertices and the zeroing it triggers 12%.
// With 2 MB pages there is one fault per 512 pages (measured: docs/scale.md, "Huge pages").
// The face records already were advised so (libgsp/src/state_allocator.hpp); this reaches the
// rest without changing the library's types. glibc's free() releases aligned_alloc's memory,
// so the library's (and libstdc++'s) operator delete needs no replacement. Where huge pages
// are off, the advice is ignored; where they are always on, it changes nothing.
//
// A huge page is faulted in whole, so an array rounded up to whole huge pages wastes up to
// 2 MB: from 8 MB (at most 25% of it) the array is rounded, and its tail is a huge page too;
// from 2 MB to 8 MB it is not, so its whole 2 MB ranges are huge pages and its tail stays on
// 4 KB pages, and no memory is wasted (docs/scale.md, "From 2 MB, not rounded").
#include <cstddef>
#include <cstdlib>
#include <new>
#if defined(__linux__)
#include <sys/mman.h>
#endif

// Sanitizer builds (GSP_SANITIZE) keep the sanitizer's own operator new: AddressSanitizer
// would see malloc'd memory released by operator delete and report a mismatch.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define GSP_KEEP_OPERATOR_NEW 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define GSP_KEEP_OPERATOR_NEW 1
#endif
#endif

#if !defined(GSP_KEEP_OPERATOR_NEW)
namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kHugeFrom = std::size_t(2) << 20;
constexpr std::size_t kRoundFrom = std::size_t(8) << 20;

void* try_allocate(std::size_t n) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (n >= kHugeFrom) {
    const std::size_t rounded = n >= kRoundFrom ? (n + kHugePage - 1) / kHugePage * kHugePage : n;
    if (void* p = std::aligned_alloc(kHugePage, rounded)) {
      madvise(p, rounded, MADV_HUGEPAGE);   // advice only: failure leaves ordinary pages
      return p;
    }
    return nullptr;
  }
#endif
  return std::malloc(n == 0 ? 1 : n);
}

void* allocate(std::size_t n) {
  for (;;) {
    if (void* p = try_allocate(n)) return p;
    std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return allocate(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return allocate(n);
  } catch (...) {
    return nullptr;
  }
}
#endif  // !GSP_KEEP_OPERATOR_NEW
