#include <gsp/batch.hpp>

#include <gsp/available_memory.hpp>
#include <gsp/errors.hpp>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

#include "parallel_propagation.hpp"

namespace gsp {

unsigned resolve_threads(unsigned threads, std::size_t jobs) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  return static_cast<unsigned>(std::max<std::size_t>(1, std::min<std::size_t>(threads, jobs)));
}

namespace detail {

bool& inside_parallel_region() {
  thread_local bool flag = false;
  return flag;
}

}  // namespace detail

void parallel_for(std::size_t n, unsigned threads, const std::function<void(std::size_t)>& job) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    // Queries run here are already spread over the cores: an automatic thread count inside
    // them means one (detail::inside_parallel_region).
    const bool outer = detail::inside_parallel_region();
    detail::inside_parallel_region() = threads > 1 || outer;
    struct Restore {
      bool value;
      ~Restore() { detail::inside_parallel_region() = value; }
    } restore{outer};
    for (std::size_t i; (i = next.fetch_add(1)) < n;) {
      try {
        job(i);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = n;   // stop handing out work
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}


std::vector<GeodesicResult> compute_many(const GeodesicSolver& solver,
                                         const std::vector<std::vector<Source>>& queries,
                                         const GeodesicOptions& options, unsigned threads) {
  // Each result holds a distance and a label per vertex (and per face when asked for).
  const double per_result = 12.0 * double(solver.num_vertices()) + (options.want_face_distances ? 12.0 * double(solver.num_faces()) : 0.0);
  require_memory(std::to_string(queries.size()) + " fields", per_result * double(queries.size()));
  std::vector<GeodesicResult> results(queries.size());
  parallel_for(queries.size(), resolve_threads(threads, queries.size()),
               [&](std::size_t i) { results[i] = solver.compute(queries[i], options); });
  return results;
}

std::vector<double> distance_matrix(const GeodesicSolver& solver, const std::vector<Index>& vertices,
                                    const GeodesicOptions& options, unsigned threads) {
  const std::size_t n = vertices.size();
  require_memory("a " + std::to_string(n) + " x " + std::to_string(n) + " distance matrix", 8.0 * double(n) * double(n));
  std::vector<double> matrix(n * n);
  parallel_for(n, resolve_threads(threads, n), [&](std::size_t i) {
    const GeodesicResult r = solver.compute({Source::at_vertex(vertices[i])}, options);
    for (std::size_t j = 0; j < n; ++j) matrix[i * n + j] = r.vertex_distance[vertices[j]];
  });
  return matrix;
}

}  // namespace gsp
