#pragma once
// Midpoint subdivision: every face into four, the new vertices at the edge midpoints (one per
// undirected edge, shared by its faces), nothing moved. The surface stays the same, its flat
// regions and needles too: how gsp-bench makes large meshes that keep what scans refined for
// simulation look like, and how the tests make fine meshes of known geometry.
// (gsp::cvt keeps its own split: it also carries each child's parent face and barycentric
// corners, and gives a zero-length edge of a face a vertex per halfedge.)
#include <gsp/mesh.hpp>

namespace gsp {

// `times` rounds (0: the mesh as it is). Any soup; faces keep their winding, corner 0 first:
// (a, b, c) -> (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca).
TriangleMesh midpoint_subdivide(const TriangleMesh& mesh, int times = 1);

}  // namespace gsp
