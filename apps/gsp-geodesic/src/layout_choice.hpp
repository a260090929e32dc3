#pragma once
// Whether gsp-geodesic reorders the mesh for the cache (SolverOptions::optimize_layout).
// The clustering pays back over many queries, but a run that computes one field on a file
// whose own order is already coherent (scans, remeshes, subdivisions: most files) is 15-40%
// faster end to end without it, and one on a shuffled file 10-35% slower (docs/scale.md).
#include <gsp/mesh.hpp>

#include <string>

namespace gsp::geodesic_app {

struct LayoutChoice {
  bool optimize = true;
  double file_gap = 0;     // mean log2(1 + |i - j|) over the file's edges, sampled (auto only)
  double random_gap = 0;   // the same expected for a random order: log2(V) - 2
  std::string reason;      // for --stats
};

// `mode`: "auto", "on" or "off". auto: on, except for one field on a file whose mean log2
// neighbour index gap is at least kCoherentGap below a random order's.
LayoutChoice choose_layout(const std::string& mode, const TriangleMesh& mesh, bool one_field);

// log2 steps: neighbours 8x closer in the index than in a random order. The files measured
// (docs/scale.md) sit 3.1-7.0 below in their own order and about 0 shuffled.
inline constexpr double kCoherentGap = 3.0;

}  // namespace gsp::geodesic_app
