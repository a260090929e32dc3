#pragma once
// The straight-line bound for line sources (the counterpart of the core's, libgsp/src/
// straight_line_bound.hpp, with segments for points): no curve on the surface from a vertex x
// to the source is shorter than the 3D distance from x to the nearest straight piece of the
// source (each piece is straight inside one face, so it is a 3D segment), so a value below that
// is raised to it, last. Returns the vertices raised by more than 1e-6 of their bound.
#include <gsp/lines/line_distances.hpp>

namespace gsp::lines {

std::size_t raise_to_segments(const TriangleMesh& mesh, const LineSource& source, std::vector<double>& distance,
                              std::vector<Index>& segment);

}  // namespace gsp::lines
