#pragma once
// The smoothing's first step: caps across creases flipped away (remove_caps in flips.hpp), each
// flip kept only where the surface stays close to the mesh both ways.
#include "smoothing_context.hpp"

#include <cstddef>

namespace gsp::cvt::detail {

// The new edge's midpoint within max(max_deviation, the old one's distance) of the surface, and
// the surface under the old pair within max(max_deviation, before) of the new pair: the point
// nearest the old edge's midpoint and every sample vertex near the pair whose nearest mesh
// triangle is one of the two (an Embree index over the mesh, rebuilt after each flip). The
// midpoint's point alone can let a flip uncover the far end of a slit (docs/cvt.md has the
// case). Returns the number of flips; the rings are rebuilt after each.
std::size_t remove_caps_keeping_surface(SmoothingContext& c, double max_deviation);

}  // namespace gsp::cvt::detail
