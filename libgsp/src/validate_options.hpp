#pragma once
// The first step of every query (compute, compute_local): its options checked at the API
// boundary, once, before anything is seeded.
#include <gsp/geodesics.hpp>

namespace gsp::detail {

enum class QueryKind { full, local };

// Throws InvalidInput naming the first bad option: strategy parameters that are not positive,
// a negative or NaN max_distance, per-face virtual sources or A* on a solver built from edge
// lengths alone (both are 3D constructions), targets that do not exist, and for a local query
// any target at all. `custom_lengths`: the solver was built with SolverOptions::edge_lengths.
void validate_options(const GeodesicOptions& options, QueryKind kind, bool custom_lengths, std::size_t num_vertices);

}  // namespace gsp::detail
