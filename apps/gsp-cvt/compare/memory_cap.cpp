#include "memory_cap.hpp"

#include <gsp/available_memory.hpp>
#include <gsp/cli/memory.hpp>

#include <sys/resource.h>

namespace gsp::cvt_compare {

AddressSpaceCap::AddressSpaceCap(double fraction) {
  const std::size_t free = available_memory(), used = cli::resident_memory().address_space;
  rlimit r{};
  if (free == 0 || used == 0 || getrlimit(RLIMIT_AS, &r) != 0) return;
  const std::size_t cap = used + std::size_t(fraction * double(free));
  if (r.rlim_cur != RLIM_INFINITY && r.rlim_cur <= cap) return;
  old_soft_ = r.rlim_cur;
  r.rlim_cur = cap;
  if (setrlimit(RLIMIT_AS, &r) != 0) return;
  set_ = true;
  headroom_ = cap - used;
}

AddressSpaceCap::~AddressSpaceCap() {
  if (!set_) return;
  rlimit r{};
  if (getrlimit(RLIMIT_AS, &r) != 0) return;
  r.rlim_cur = old_soft_;
  setrlimit(RLIMIT_AS, &r);
}

}  // namespace gsp::cvt_compare
