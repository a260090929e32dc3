#include <gsp/available_memory.hpp>

#include <sys/resource.h>

#include <gsp/errors.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

namespace gsp {

std::size_t available_memory() {
  std::size_t bytes = 0;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::size_t value = 0;
  std::string unit;
  while (meminfo >> key >> value >> unit)
    if (key == "MemAvailable:") {
      bytes = value * 1024;   // the kernel writes kB
      break;
    }
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    bytes = bytes ? std::min<std::size_t>(bytes, limit.rlim_cur) : std::size_t(limit.rlim_cur);
  return bytes;
}

void require_memory(const std::string& what, double bytes, const std::string& fewer, std::size_t budget) {
  if (!budget) budget = available_memory();
  if (!budget || !(bytes > double(budget))) return;
  char message[120];
  std::snprintf(message, sizeof message, ": about %.3g GB needed; %.3g GB of memory is available: ask for fewer",
                bytes * 1e-9, double(budget) * 1e-9);
  throw InvalidInput(what + message + (fewer.empty() ? "" : " " + fewer));
}

}  // namespace gsp
