#pragma once
// Collapses of the dual's short boundary edges (see remesh.hpp, RemeshOptions::smooth).
#include "boundary_curves.hpp"

#include <gsp/mesh.hpp>

#include <cstddef>
#include <vector>

namespace gsp::cvt::detail {

// A boundary edge opposite the smallest angle of its triangle, when that angle is below
// `below_angle_deg`, is collapsed to one vertex on the surface's boundary curve (the arc-length
// midpoint of the two, or one of them, whichever gives the best angles) when that raises the
// smallest angle of the triangles around the two vertices, nothing folds, the link condition
// holds (the mesh stays manifold with the same Euler characteristic), the boundary loop keeps
// at least three vertices, and the new boundary chords stay within max(max_deviation, before)
// of the boundary curve. Boundary sites placed by face-granular regions sometimes come a
// fraction of an edge apart; sliding them apart only moves the bad angle to the next triangle.
// The removed vertex is left unreferenced (the caller drops it). Returns the number of
// collapses.
std::size_t collapse_boundary_edges(TriangleMesh& mesh, const BoundaryCurves& curves, double below_angle_deg,
                                    double max_deviation, int passes = 3, const std::vector<bool>* fixed = nullptr);

}  // namespace gsp::cvt::detail
