#pragma once
// How much memory a run may plan for, for the modules that size a large structure from an
// argument (gsp::cvt's working mesh from the site count, gsp::sampling's samples from the
// count): asked for far more than the machine holds, such a structure grew until the kernel
// killed the process (gsp-cvt --vertices 3000000 on an 11k-vertex cow: 24 GB, signal 9), where
// a refusal up front, with the sizes, is what a user needs.
#include <cstddef>
#include <string>

namespace gsp {

// Bytes available to this process: MemAvailable of /proc/meminfo, lowered to the soft
// RLIMIT_AS when one is set (gsp-batch --max-memory). 0 when neither can be read: no limit
// known, no check.
std::size_t available_memory();

// Throws InvalidInput "`what`: about X GB needed; Y GB of memory is available: ask for fewer
// `fewer`" when `bytes` exceeds `budget` (0: available_memory(); nothing when that is unknown).
// The one check of every module that sizes a run from an argument.
void require_memory(const std::string& what, double bytes, const std::string& fewer = "", std::size_t budget = 0);

}  // namespace gsp
