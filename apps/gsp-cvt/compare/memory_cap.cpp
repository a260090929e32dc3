#include "memory_cap.hpp"

#include <gsp/available_memory.hpp>

#include <sys/resource.h>

#include <fstream>
#include <string>

namespace gsp::cvt_compare {

namespace {

// VmSize of /proc/self/status in bytes (0 if it cannot be read): the address space the limit
// counts, far more than the resident memory once Embree and the thread pools have reserved.
std::size_t address_space_in_use() {
  std::ifstream in("/proc/self/status");
  std::string key;
  while (in >> key) {
    if (key == "VmSize:") {
      std::size_t kb = 0;
      in >> kb;
      return kb * 1024;
    }
    std::getline(in, key);
  }
  return 0;
}

}  // namespace

AddressSpaceCap::AddressSpaceCap(double fraction) {
  const std::size_t free = available_memory(), used = address_space_in_use();
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
