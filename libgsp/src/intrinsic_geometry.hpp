#pragma once
// Intrinsic geometry the solver prepares once per mesh (internal): edge lengths, vertex kinds,
// canonical face frames. Every face has a canonical 2D frame: corner 0 at the origin, corner 1
// on the +x axis, corner 2 above it (y >= 0); a face's virtual source is a point of that frame.
// Lengths are divided by the mean edge length so the speed-limiter step f = 1 is one mean edge.
#include <gsp/heuristic.hpp>
#include <gsp/intrinsic/edge_lengths.hpp>
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

// Caller-supplied per-halfedge lengths (input face order), checked: one per halfedge, finite,
// >= 0 (zero-length edges of coincident vertices are legal mesh data), and each face's three
// lengths satisfy the triangle inequality within 1e-6 of its longest edge. Throws InvalidInput.
void validate_halfedge_lengths(const TriangleMesh& mesh, const std::vector<double>& length);

// Zero-length edges (snap_zero_lengths, zero_length_edge) live in the shared layer too.
using intrinsic::kZeroEdge;
using intrinsic::snap_zero_lengths;
using intrinsic::zero_length_edge;

// True where some face's shape is not held by single-precision lengths. Rounding each length
// to float (relative 2^-24) moves the apex of a face by about eps (L/h)^2 of its height h over
// its longest edge L; past L/h = kFloatAspectLimit that is more than 1% of the height, and the
// unfolding of a needle or cap in float lands beside the face itself (CAD STLs: distances far
// below the straight line). Zero-area faces with a non-zero edge count as unresolved.
inline constexpr double kFloatAspectLimit = 400;
// only_faces: look at these faces alone (non-zero entries), the others known to be fine.
bool needs_double_lengths(const std::vector<double>& length, const std::vector<bool>& skipped_face,
                          const std::vector<char>* only_faces = nullptr);

// Halfedge lengths and their mean live in the shared layer.
using intrinsic::halfedge_lengths;
using intrinsic::mean_edge_length;

}  // namespace gsp::detail
