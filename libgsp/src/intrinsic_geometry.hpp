#pragma once
// Intrinsic geometry the solver prepares once per mesh (internal): edge lengths, vertex kinds,
// canonical face frames. Every face has a canonical 2D frame: corner 0 at the origin, corner 1
// on the +x axis, corner 2 above it (y >= 0); a face's virtual source is a point of that frame.
// Lengths are divided by the mean edge length so the speed-limiter step f = 1 is one mean edge.
#include <gsp/heuristic.hpp>
#include <gsp/intrinsic/face_frame.hpp>
#include <gsp/intrinsic/vertex_kinds.hpp>
#include <gsp/mesh.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace gsp::detail {

// Vertex kinds (flat, saddle, convex) live in the shared layer.
using intrinsic::kConvexVertex;
using intrinsic::kFlatVertex;
using intrinsic::kPlainVertex;
using intrinsic::kSaddleExcess;
using intrinsic::kSaddleVertex;
using intrinsic::vertex_kinds;

// Corner positions of face f in its canonical frame (scaled lengths), in double.
void canonical_corners(const std::vector<double>& length, Index f, double scale, double out[3][2]);

// Per halfedge, the 3D length of its edge.
std::vector<double> halfedge_lengths(const TriangleMesh& mesh);

// Caller-supplied per-halfedge lengths (input face order), checked: one per halfedge, finite,
// >= 0 (zero-length edges of coincident vertices are legal mesh data), and each face's three
// lengths satisfy the triangle inequality within 1e-6 of its longest edge. Throws InvalidInput.
void validate_halfedge_lengths(const TriangleMesh& mesh, const std::vector<double>& length);

// An edge as long as nothing next to its face's longest edge (relative kZeroEdge, below double
// resolution): its ends are one point of the surface, and it has no direction. The face frames
// take their x axis from corner 0 to corner 1 and divide by that length; a length of 1e-16
// there gave a frame of rounding noise (distances of 0 far from the source on a compound STL
// whose two parts share a centre). snap_zero_lengths() makes such lengths exactly 0, which
// every frame and unfolding handles as coincident corners (face_record.hpp).
inline constexpr double kZeroEdge = 1e-12;
void snap_zero_lengths(std::vector<double>& length);
inline bool zero_length_edge(const std::vector<double>& length, Index h) { return !(length[h] > 0); }

// True where some face's shape is not held by single-precision lengths. Rounding each length
// to float (relative 2^-24) moves the apex of a face by about eps (L/h)^2 of its height h over
// its longest edge L; past L/h = kFloatAspectLimit that is more than 1% of the height, and the
// unfolding of a needle or cap in float lands beside the face itself (CAD STLs: distances far
// below the straight line). Zero-area faces with a non-zero edge count as unresolved.
inline constexpr double kFloatAspectLimit = 400;
bool needs_double_lengths(const std::vector<double>& length, const std::vector<bool>& skipped_face);

// Mean of `length` over the halfedges of faces not skipped (each interior edge counted from
// both sides, which weights it like the faces see it). 1 if there is none. Summed in face
// order, so 3D lengths give the same bits whichever way they were obtained.
double mean_edge_length(const std::vector<double>& length, const std::vector<bool>& skipped_face);

}  // namespace gsp::detail
