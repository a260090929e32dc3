#pragma once
// Delaunay flips of the working mesh inside planes. A CAD export's flat faces are fans of
// slivers (a gear's face: triangles 11 units long and 0.1 wide from the hub to the teeth), and
// the split and the bisection keep their shape: children of a sliver are slivers. GSP with
// sources inside faces runs on the working mesh's own triangles (no intrinsic Delaunay flips:
// the labels are per working face), and on such faces its values were several percent too long
// (the gear's working mesh: 2.4% mean, 30% at worst, against 1e-13 on the same mesh's intrinsic
// Delaunay flip), so its Voronoi regions were wrong at hundreds of places. Flipping edges
// whose four corners lie in one plane does not move the surface and makes the same triangles
// the intrinsic flips would.
#include "input_walk.hpp"

#include <gsp/cvt/cvt.hpp>

#include <cstddef>
#include <memory>

namespace gsp::cvt::detail {

// Flips (flips.hpp, delaunay_flips_in_planes) with corners off each other's planes by at most
// max_height; a rewritten face gets the input face holding its centroid as its parent (found
// by a walk on the input from the old one: `walk`, made here when there was a flip) and its
// corners' affine coordinates there (outside [0, 1] where a corner lies in another face of the
// plane). Returns the number of flips.
std::size_t flip_in_planes(WorkingMesh& w, const TriangleMesh& input, double max_height,
                           std::unique_ptr<InputWalk>& walk);

}  // namespace gsp::cvt::detail
