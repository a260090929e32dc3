#pragma once
// Fitting the dual's boundary to the input's: boundary vertices off the boundary curve are
// snapped onto it, boundary edges that cut the curve are split (see remesh.hpp,
// RemeshOptions::boundary_chord).
#include "boundary_curves.hpp"

#include <gsp/mesh.hpp>

#include <cstddef>
#include <vector>

namespace gsp::cvt::detail {

// A boundary vertex of the dual that lies off the surface's boundary curve by more than 1e-3
// of its boundary edges' length (a site whose region touches the boundary only at a corner
// of the working mesh stays inside) moves to the nearest point of the curve when nothing
// folds and no angle of its triangles falls below min(before, `min_angle_deg`). Returns the
// number of vertices moved.
std::size_t snap_boundary_vertices(TriangleMesh& mesh, const BoundaryCurves& curves, double min_angle_deg,
                                   const std::vector<bool>* locked = nullptr);

// A boundary edge whose chord is farther than `max_chord` from the stretch of the surface's
// boundary curve it spans is split at the curve's point farthest from the chord (a new vertex,
// appended; its triangle becomes two), when both new triangles keep the old one's orientation
// and have a smallest angle of at least min(the old triangle's, `min_angle_deg`). Sites on a
// jagged boundary (a scan's hole) are an edge apart and the chords between them cut the
// corners of the outline: that is where the bunny's Hausdorff distance was. An edge with an end
// the snaps left inside the surface (less than the edge's length from the curve: a dent in the
// dual's boundary) is split too, with a floor of min(the old triangle's, kDentFloorDeg) since the
// moves after it take the angles back up. Returns the number of splits.
inline constexpr double kDentFloorDeg = 20.0;   // issue 22's quality floor
std::size_t split_boundary_edges(TriangleMesh& mesh, const BoundaryCurves& curves, double max_chord, double min_angle_deg,
                                 int passes = 3, const std::vector<bool>* locked = nullptr);

}  // namespace gsp::cvt::detail
