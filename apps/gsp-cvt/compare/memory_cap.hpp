#pragma once
// A cap on the process' address space while a foreign method runs: CGAL's isotropic remeshing
// grew to 24 GB on a corpus part (manifold's twin, valence-969 fans) until the kernel killed
// the whole comparison; capped at the memory that is free when it starts, its allocations fail
// (std::bad_alloc) and the method becomes a row with that reason.
#include <cstddef>

namespace gsp::cvt_compare {

class AddressSpaceCap {
 public:
  // Caps the soft RLIMIT_AS at the address space in use plus `fraction` of the free memory
  // (gsp::available_memory), unless a lower cap is set already; no cap when either is unknown.
  explicit AddressSpaceCap(double fraction = 0.9);
  ~AddressSpaceCap();   // the limit as it was
  AddressSpaceCap(const AddressSpaceCap&) = delete;
  AddressSpaceCap& operator=(const AddressSpaceCap&) = delete;

  // The bytes the method may add (0: no cap set).
  std::size_t headroom() const { return headroom_; }

 private:
  bool set_ = false;
  std::size_t old_soft_ = 0;
  std::size_t headroom_ = 0;
};

}  // namespace gsp::cvt_compare
