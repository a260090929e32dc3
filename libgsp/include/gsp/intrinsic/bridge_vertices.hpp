#pragma once
// Bridge vertices (internal layer shared by the core's propagation and the extensions; not a
// stable API): vertices whose faces form several fans that share no edge, such as bow-ties
// and CAD parts touching at a corner. A wavefront never crosses from one such fan to the
// next over an edge, so the propagation passes the vertex's distance on as a point source.
#include <gsp/connectivity.hpp>
#include <gsp/mesh.hpp>

#include <vector>

namespace gsp::intrinsic {

// In increasing order. Faces with skipped_face[f] set take no part. Linear in the mesh size:
// one union-find over all corners, joining the corners at v of two faces that share an edge
// through v.
std::vector<Index> bridge_vertices(const TriangleMesh& mesh, const Connectivity& conn,
                                   const std::vector<bool>& skipped_face);

}  // namespace gsp::intrinsic
