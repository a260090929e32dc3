#include <gsp/cli/memory.hpp>

#include <cstdio>
#include <cstring>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace gsp::cli {

ResidentMemory resident_memory() {
  ResidentMemory m;
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return m;
  char line[256];
  while (std::fgets(line, sizeof line, f)) {
    unsigned long long kb = 0;
    if (std::sscanf(line, "VmRSS: %llu kB", &kb) == 1) m.current = std::size_t(kb) * 1024;
    if (std::sscanf(line, "VmHWM: %llu kB", &kb) == 1) m.peak = std::size_t(kb) * 1024;
    if (std::sscanf(line, "VmSize: %llu kB", &kb) == 1) m.address_space = std::size_t(kb) * 1024;
  }
  std::fclose(f);
  return m;
}

void return_large_frees_to_system() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
}

}  // namespace gsp::cli
