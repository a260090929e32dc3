#pragma once
// for_each_piece (text_pieces.hpp): a template, so that the work is inlined into each reader.
#include <exception>
#include <thread>
#include <vector>

namespace gsp::io::detail {

template <class Work>
void for_each_piece(std::size_t n, Work&& work) {
  std::vector<std::exception_ptr> failed(n);
  std::vector<std::thread> threads;
  threads.reserve(n > 0 ? n - 1 : 0);
  for (std::size_t i = 1; i < n; ++i)
    threads.emplace_back([&, i] {
      try {
        work(i);
      } catch (...) {
        failed[i] = std::current_exception();
      }
    });
  if (n > 0) {
    try {
      work(0);
    } catch (...) {
      failed[0] = std::current_exception();
    }
  }
  for (std::thread& t : threads) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace gsp::io::detail
