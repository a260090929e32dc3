#pragma once
// Per-halfedge constants of the update step (paper Section 4.1), precomputed once per mesh.
//
// For halfedge g = 3T + j of face T, the frame puts A = corner j at the origin, B = corner j+1
// at (e1, 0) and the opposite corner P = corner j+2 at (px, py) with py >= 0. (qx, qy) is the
// visibility probe of the heuristic for T entered through g. Lengths are divided by the mean
// edge length so the speed-limiter step f = 1 means one mean edge.
#include <gsp/heuristic.hpp>
#include <gsp/mesh.hpp>

#include <vector>

namespace gsp::detail {

template <class Real>
struct HalfedgeGeometry {
  Real e1;        // |AB|
  Real inv_2e1;   // 1 / (2 e1), or 0 for a zero-length edge (then the update bends at A)
  Real px, py;    // opposite corner
  Real qx, qy;    // visibility probe
};

// Builds the table for every halfedge of `mesh` (edge lengths scaled by `scale`).
template <class Real>
std::vector<HalfedgeGeometry<Real>> build_halfedge_geometry(const TriangleMesh& mesh, double scale,
                                                            const VisibilityHeuristic& heuristic);

// Mean length over the halfedges of faces with three distinct corners (each interior edge
// counted from both sides, which weights it like the faces see it). 1 if there is none.
double mean_edge_length(const TriangleMesh& mesh);

}  // namespace gsp::detail
