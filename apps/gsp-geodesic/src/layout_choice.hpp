#pragma once
// Whether gsp-geodesic reorders the mesh for the cache (SolverOptions::optimize_layout).
// The clustering pays back over many queries, but a run that computes one field on a file
// whose own order is already coherent (scans, remeshes, subdivisions: most files) is 15-40%
// faster end to end without it, and one on a shuffled file 10-35% slower (docs/scale.md).
#include <gsp/layout.hpp>
#include <gsp/mesh.hpp>

#include <string>

namespace gsp::geodesic_app {

struct LayoutChoice {
  bool optimize = true;
  bool spatial = false;    // the Z-order layout (auto, one field), else the clustering
  bool faces_only = false; // only the faces sorted (auto, one field: coherent vertices, scattered faces)
  OrderCoherence order;    // measured for auto and one field only (else zeros)
  std::string reason;      // for --stats
};

// `mode`: "auto", "on" or "off". auto: on, except for one field on a file whose own order is
// coherent (gsp::order_coherence); where auto reorders for one field, the Z-order layout (a
// sort of the positions) does, or where only the faces are scattered, a sort of the faces by
// their smallest vertex. on: the clustering (what several fields get: it pays back over
// many queries, and a field is then identical to its --separate twin).
LayoutChoice choose_layout(const std::string& mode, const TriangleMesh& mesh, bool one_field);

}  // namespace gsp::geodesic_app
