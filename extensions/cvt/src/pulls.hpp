#pragma once
// The smoothing's last step: where the dual's chords cut the surface, the vertices are pulled
// towards it, since the moves only raise angles and can leave the mesh far from a tip or crease.
#include "smoothing_context.hpp"

#include <cstddef>

namespace gsp::cvt::detail {

// A sample vertex of the surface farther than pull_distance from the mesh pulls a corner of
// the triangle nearest to it part of the way towards it (on the surface; the position that
// brings it closest), if the corner is interior, nothing folds, no angle falls below
// min(before, max(30 degrees, the mesh's minimum angle)) and the surface checks of
// move_checks.hpp hold with pull_distance as the bound (nothing else ends up farther than that
// unless it already was). Two rounds; moved vertices and their neighbours are locked within a
// round. Returns the number of pulls.
std::size_t pull_towards_far_samples(SmoothingContext& c, double pull_distance);

}  // namespace gsp::cvt::detail
