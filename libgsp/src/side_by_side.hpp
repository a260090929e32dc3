#pragma once
// Two pieces of work at once (internal): `beside` on a thread of its own, `here` on the
// caller's; returns when both are done and rethrows the first failure (the caller's first).
// The solver's preparation pairs independent steps with it on big meshes.
#include <exception>
#include <thread>

namespace gsp::detail {

template <class Beside, class Here>
void side_by_side(Beside&& beside, Here&& here) {
  std::exception_ptr failed;
  std::thread thread([&] {
    try {
      beside();
    } catch (...) {
      failed = std::current_exception();
    }
  });
  try {
    here();
  } catch (...) {
    thread.join();
    throw;
  }
  thread.join();
  if (failed) std::rethrow_exception(failed);
}

}  // namespace gsp::detail
