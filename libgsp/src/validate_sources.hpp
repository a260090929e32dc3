#pragma once
// A query's sources checked at the API boundary (compute, compute_local), once, before anything
// is seeded; next to validate_options.hpp, which checks the query's options.
#include <gsp/geodesics.hpp>

#include <vector>

namespace gsp::detail {

// Throws InvalidInput naming the first bad source, in order: more sources than a face record's
// label holds (2^26 - 1), then per source an offset that is not finite and >= 0, a vertex or
// face that `mesh` does not have, or face-point weights that are not barycentric
// (gsp::are_barycentric).
void validate_sources(const std::vector<Source>& sources, const TriangleMesh& mesh);

}  // namespace gsp::detail
