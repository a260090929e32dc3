#pragma once
// Per-halfedge constants of the update step, precomputed once per mesh from edge lengths alone
// (the intrinsic parametrization of the paper's Section 4.1).
//
// Every face has a canonical 2D frame: corner 0 at the origin, corner 1 on the +x axis, corner 2
// above it (y >= 0). A face's virtual source is stored as a point of that frame. For halfedge
// g = 3T + j the edge frame puts A = corner j at the origin and B = corner j+1 at (e1, 0), with
// T on the +y side; `frame` maps canonical coordinates to edge coordinates and back.
// Lengths are divided by the mean edge length so the speed-limiter step f = 1 is one mean edge.
#include <gsp/heuristic.hpp>
#include <gsp/mesh.hpp>

#include <cstdint>
#include <vector>

namespace gsp::detail {

// Edge frame of a halfedge inside its face's canonical frame: origin (ax, ay), x axis (c, s).
template <class Real>
struct EdgeFrame {
  Real ax, ay, c, s;
};

// What the update step needs of the face entered through a halfedge, in that edge's frame.
template <class Real>
struct EdgeEntry {
  Real e1;             // |AB|
  Real cx, cy;         // centroid of the face
  Real qx, qy;         // visibility probe of the heuristic
  std::uint32_t straight_at;   // bit 0: A, bit 1: B cannot be a corner of a geodesic (flat)
};

template <class Real>
struct HalfedgeTables {
  std::vector<EdgeFrame<Real>> frame;
  std::vector<EdgeEntry<Real>> entry;
};

// Per vertex: true where no shortest path can bend — interior vertices whose angle sum is 2 pi
// and boundary vertices whose angle sum is at most pi (within a relative 1e-6). Unfolding
// around such a vertex is the same from either side, so a source that the visibility probe
// sees past the vertex is still exact when carried straight on. This makes GSP exact on flat
// and developable regions (planar CAD faces, fans) whatever the heuristic says.
std::vector<std::uint8_t> flat_vertices(const TriangleMesh& mesh, const std::vector<Index>& ring,
                                        const std::vector<bool>& skipped_face,
                                        const std::vector<Index>& nonmanifold_vertices);

// Builds the tables for every halfedge of `mesh` (edge lengths scaled by `scale`).
// `length` holds, per halfedge 3f+i, the length from corner i to corner i+1 (model units):
// the geometry is intrinsic, the 3D positions are not needed.
template <class Real>
HalfedgeTables<Real> build_halfedge_tables(const std::vector<Triangle>& triangles,
                                           const std::vector<double>& length, double scale,
                                           const VisibilityHeuristic& heuristic,
                                           const std::vector<std::uint8_t>& flat);

// Corner positions of face f in its canonical frame (scaled lengths), in double.
void canonical_corners(const std::vector<double>& length, Index f, double scale, double out[3][2]);

// Per halfedge, the 3D length of its edge.
std::vector<double> halfedge_lengths(const TriangleMesh& mesh);

// Mean length over the halfedges of faces with three distinct corners (each interior edge
// counted from both sides, which weights it like the faces see it). 1 if there is none.
double mean_edge_length(const TriangleMesh& mesh);

}  // namespace gsp::detail
