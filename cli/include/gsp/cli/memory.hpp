#pragma once
// This process's resident memory as the kernel counts it (Linux /proc/self/status: VmRSS now,
// VmHWM its peak so far): what --stats reports per phase, so a run's peak can be set against
// the mesh size (bytes per vertex) and against another method's run on the same mesh.
#include <cstddef>

namespace gsp::cli {

struct ResidentMemory {
  std::size_t current = 0, peak = 0;   // bytes; 0 where the system does not say
};

ResidentMemory resident_memory();

}  // namespace gsp::cli
