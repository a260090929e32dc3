#pragma once
// Boundary loops of the working mesh as ordered lists of boundary halfedges.
#include "working_geometry.hpp"

#include <vector>

namespace gsp::cvt::detail {

// Each loop follows the halfedges head to tail (v -> w, then the boundary halfedge leaving w).
// At a vertex with several boundary halfedges leaving it, the first unused one is taken.
std::vector<std::vector<Index>> boundary_loops(const WorkingGeometry& g);

}  // namespace gsp::cvt::detail
