#pragma once
// At most one running query per core across the Python module; further callers wait, asleep.
//
// Why: Python threads that each call distance() on 2 cores leave the kernel to place 3-4 busy
// threads, and it may stack two on one core while the other idles. A waiting caller sleeps (no
// core used) and, woken when a query ends, is placed on a free core. With the speed limiter's
// yield (gsp/intrinsic/speed_limiter.hpp), 4 queries on 4 threads run 1.6-1.9x faster than one
// after another on 2 cores; docs/python.md ("Threads") has the figures.
#include <condition_variable>
#include <mutex>

namespace gsp::python {

class CoreSlot {
 public:
  CoreSlot();    // blocks until fewer queries than cores run; call without the GIL
  ~CoreSlot();
  CoreSlot(const CoreSlot&) = delete;
  CoreSlot& operator=(const CoreSlot&) = delete;
};

}  // namespace gsp::python
