#pragma once
// Large benchmark meshes from small ones: Loop subdivision (CGAL's Subdivision_method_3).
// The speed targets are for 100k-1M-vertex meshes and the shared meshes are 2k-36k;
// Loop subdivision quadruples the faces per step and moves every vertex (the result stays
// curved everywhere, unlike midpoint splitting, whose new vertices lie on flat triangles).
#include <gsp/mesh.hpp>

namespace gsp::bench {

// `times` rounds of Loop subdivision. Throws InvalidInput when the mesh is not a manifold the
// halfedge structure can hold (CGAL's subdivision needs one).
TriangleMesh loop_subdivide(const TriangleMesh& mesh, int times);

}  // namespace gsp::bench
