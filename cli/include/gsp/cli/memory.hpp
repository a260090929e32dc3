#pragma once
// This process's resident memory as the kernel counts it (Linux /proc/self/status: VmRSS now,
// VmHWM its peak so far): what --stats reports per phase, so a run's peak can be set against
// the mesh size (bytes per vertex) and against another method's run on the same mesh. VmSize,
// the address space, is what an RLIMIT_AS cap counts (gsp-cvt-compare's cap around CGAL).
#include <cstddef>

namespace gsp::cli {

struct ResidentMemory {
  std::size_t current = 0, peak = 0;   // bytes; 0 where the system does not say
  std::size_t address_space = 0;       // VmSize, bytes (far more than resident once thread pools reserved theirs)
};

ResidentMemory resident_memory();

// Makes every allocation of 1 MB or more its own mapping, handed back to the system when
// freed (glibc: a fixed M_MMAP_THRESHOLD; elsewhere nothing). glibc's default threshold grows
// after the first large free, and from then on large arrays come from the heap or a thread's
// arena, where a freed one stays resident and another thread's allocation cannot reuse it: the
// preparation's and the query's threads then raised a run's peak by 80 bytes per vertex
// (557k vertices: 259 MB against 210 MB with this). run_app calls it first.
void return_large_frees_to_system();

}  // namespace gsp::cli
