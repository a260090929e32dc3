#pragma once
// Large benchmark meshes from small ones: Loop subdivision (CGAL's Subdivision_method_3) or
// midpoint splitting (what a scan refined for simulation looks like: flat regions and needles
// kept, the case where the speed limiter stops being linear).
// The speed targets are for 100k-1M-vertex meshes and the shared meshes are 2k-36k;
// Loop subdivision quadruples the faces per step and moves every vertex (the result stays
// curved everywhere, unlike midpoint splitting, whose new vertices lie on flat triangles).
#include <gsp/mesh.hpp>
#include <gsp/subdivide.hpp>   // midpoint splitting: gsp::midpoint_subdivide

namespace gsp::bench {

// `times` rounds of Loop subdivision. Throws InvalidInput when the mesh is not a manifold the
// halfedge structure can hold (CGAL's subdivision needs one).
TriangleMesh loop_subdivide(const TriangleMesh& mesh, int times);

}  // namespace gsp::bench
