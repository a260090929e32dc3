#include "core_slots.hpp"

#include <algorithm>
#include <thread>

namespace gsp::python {
namespace {

struct Slots {
  std::mutex mutex;
  std::condition_variable freed;
  unsigned running = 0;
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
};

Slots& slots() {
  static Slots s;
  return s;
}

}  // namespace

CoreSlot::CoreSlot() {
  Slots& s = slots();
  std::unique_lock<std::mutex> lock(s.mutex);
  s.freed.wait(lock, [&] { return s.running < s.cores; });
  ++s.running;
}

CoreSlot::~CoreSlot() {
  Slots& s = slots();
  {
    std::lock_guard<std::mutex> lock(s.mutex);
    --s.running;
  }
  s.freed.notify_one();
}

}  // namespace gsp::python
