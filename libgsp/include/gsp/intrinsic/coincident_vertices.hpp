#pragma once
// Coincident vertices (internal layer shared by the core's propagation and the extensions; not
// a stable API): distinct vertices joined by zero-length edges (CAD exports, compound models),
// one point of the surface. A zero-length edge has no direction, so no face frame unfolds
// across it; each group passes the front on like a bridge vertex, and has no single angle sum
// (gsp/intrinsic/vertex_kinds.hpp).
#include <gsp/connectivity.hpp>
#include <gsp/mesh.hpp>

#include <vector>

namespace gsp::intrinsic {

// CSR: group g is vertices[begin[g]] .. vertices[begin[g + 1] - 1]; groups of two or more.
struct CoincidentVertices {
  std::vector<Index> begin{0};
  std::vector<Index> vertices;
};

// The ends of the zero-length edges (length[h] == 0 after snap_zero_lengths, h the edge's
// Connectivity::edge_halfedge) of faces that take part, united into groups.
CoincidentVertices coincident_vertices(const TriangleMesh& mesh, const Connectivity& conn,
                                       const std::vector<bool>& skipped_face, const std::vector<double>& length);

}  // namespace gsp::intrinsic
