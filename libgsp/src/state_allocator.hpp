#pragma once
// The allocator of a query's face records (internal). Two things std::allocator does not do:
//
// - New elements stay uninitialised. The records are written once right after they are
//   allocated; a zeroing pass first would touch (fault in) every page on one thread, where
//   now each of a query's threads fills, and faults in, its own part.
// - Arrays of 8 MB or more are aligned to 2 MB and advised as transparent huge pages
//   (madvise; Linux's default THP mode "madvise" uses huge pages only where asked). The
//   propagation reads the records in wavefront order, all over the array: with 4 KB pages
//   most reads also miss the TLB (the gain at 8.9M vertices: docs/scale.md, "Measured").
//   Where huge pages are off or unavailable the advice is ignored.
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <utility>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace gsp::detail {

template <class T>
struct StateAllocator : std::allocator<T> {
  static constexpr std::size_t kHugePage = std::size_t(2) << 20;
  static constexpr std::size_t kHugeFrom = std::size_t(8) << 20;

  template <class U>
  struct rebind {
    using other = StateAllocator<U>;
  };
  StateAllocator() = default;
  template <class U>
  StateAllocator(const StateAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugeFrom) return std::allocator<T>::allocate(n);
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, rounded);
    if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, rounded, MADV_HUGEPAGE);   // advice only: failure leaves ordinary pages
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kHugeFrom) return std::allocator<T>::deallocate(p, n);
    std::free(p);
  }
  // Default-initialisation: nothing for the records (trivial types).
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

}  // namespace gsp::detail
