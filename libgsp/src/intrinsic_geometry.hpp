#pragma once
// Intrinsic geometry the solver prepares once per mesh (internal): edge lengths, vertex kinds,
// canonical face frames. Every face has a canonical 2D frame: corner 0 at the origin, corner 1
// on the +x axis, corner 2 above it (y >= 0); a face's virtual source is a point of that frame.
// Lengths are divided by the mean edge length so the speed-limiter step f = 1 is one mean edge.
#include <gsp/heuristic.hpp>
#include <gsp/mesh.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace gsp::detail {

// Per vertex, what the visibility test does at it (propagation.hpp):
// - kFlatVertex where no shortest path can bend — interior vertices whose angle sum is 2 pi
//   and boundary vertices whose angle sum is at most pi (within a relative 1e-6). Unfolding
//   around such a vertex is the same from either side, so a source that the visibility probe
//   sees just past the vertex is still exact when carried straight on. This makes GSP exact on
//   flat and developable regions (planar CAD faces, fans) whatever the heuristic says.
// - kSaddleVertex for interior vertices whose angle sum exceeds 2 pi by more than
//   kSaddleExcess (relative): unfolded round such a vertex, a straight line passing it on the
//   wrong side is shorter than any path on the surface, so the probe is moved towards the
//   opposite corner there (stricter).
// - kConvexVertex for the other interior vertices whose angle sum is below 2 pi (positive
//   curvature). No shortest path turns at such a vertex, and bending a source there is never
//   shorter than carrying it straight on: the propagation keeps a source straight past one
//   wherever the probe says "bend" but the centroid is still seen through the edge.
// The corner angles come from the 3D positions, or from `length` (per halfedge) when it is
// given: with caller-supplied intrinsic lengths (a metric) the 3D angles mean nothing.
inline constexpr std::uint8_t kPlainVertex = 0, kFlatVertex = 1, kSaddleVertex = 2, kConvexVertex = 3;
inline constexpr double kSaddleExcess = 0.01;
std::vector<std::uint8_t> vertex_kinds(const TriangleMesh& mesh, const std::vector<Index>& ring,
                                       const std::vector<bool>& skipped_face,
                                       const std::vector<Index>& nonmanifold_vertices,
                                       const std::vector<double>* length = nullptr);

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
