#pragma once
// Where a smoothing move takes one vertex: the point of the surface that raises the smallest
// angle of its triangles most among those the checks of move_checks.hpp allow.
#include "smoothing_context.hpp"

namespace gsp::cvt::detail {

struct Move {
  Vec3 x;
  double s = 0;   // x's arc length on the vertex's boundary curve (boundary vertices)
};

// Interior vertices move towards the mean of their neighbours in the tangent plane, then by a
// pattern search on the smallest angle of their triangles, every point projected onto the
// surface; boundary vertices slide along their boundary curve the same way, never past a
// neighbour. Tried only when v's worst angle is below `below`; false when no point raises it
// without lowering the plain worst angle or failing the surface checks (bound: max_deviation).
bool find_move(const SmoothingContext& c, Index v, double below, double max_deviation, Move& move);

}  // namespace gsp::cvt::detail
