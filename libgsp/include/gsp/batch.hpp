#pragma once
// Many independent geodesic queries on one prepared mesh, in parallel: each query gets its own
// propagation state (GeodesicSolver::compute is const and thread-safe), a small pool of
// std::threads takes queries from a shared counter (no spinning, no work stealing needed: the
// queries are independent). Standard library only, like the rest of the core.
#include <gsp/geodesics.hpp>

#include <functional>
#include <vector>

namespace gsp {

// threads = 0: std::thread::hardware_concurrency(); never more threads than queries.
unsigned resolve_threads(unsigned threads, std::size_t jobs);

// Runs job(i) for every i in [0, n) on `threads` threads (the calling thread is one of them),
// taking indices from a shared counter. Inside, a query's automatic thread count means one
// (the cores are taken). The first exception thrown by a job stops the handing out of work
// and is rethrown once all threads have stopped. The pool of compute_many and
// distance_matrix below, and of the extensions' (point clouds' many queries, the CVT's
// components side by side).
void parallel_for(std::size_t n, unsigned threads, const std::function<void(std::size_t)>& job);

// One GeodesicResult per query, in the order given. The first exception thrown by any query
// is rethrown after all threads have stopped.
std::vector<GeodesicResult> compute_many(const GeodesicSolver& solver,
                                         const std::vector<std::vector<Source>>& queries,
                                         const GeodesicOptions& options = {}, unsigned threads = 0);

// The n x n matrix of distances between the given vertices (row i: distances from vertex i),
// row-major. Not exactly symmetric: each row is its own approximate propagation.
std::vector<double> distance_matrix(const GeodesicSolver& solver, const std::vector<Index>& vertices,
                                    const GeodesicOptions& options = {}, unsigned threads = 0);

}  // namespace gsp
