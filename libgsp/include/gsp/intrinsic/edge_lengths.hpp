#pragma once
// Edge lengths as the propagation sees them (internal layer shared by the core and the
// extensions; not a stable API): one per halfedge in face order, the faces that take part,
// and the mean edge length, the unit of every tolerance the propagation states in "mean
// edges". An extension that scales by this mean scales as the core does.
#include <gsp/connectivity.hpp>
#include <gsp/mesh.hpp>

#include <array>
#include <vector>

namespace gsp::intrinsic {

// Per face, whether it takes no part: it names a vertex twice (gsp::repeats_vertex).
std::vector<bool> skipped_faces(const TriangleMesh& mesh);

// Copies of a face (the same three vertices, in any order or orientation: an STL with doubled
// triangles) take no part either: the surface holds each face once. Glued to all three edges
// of its original, a copy unfolds as the original mirrored across each edge, and sources
// bounced between the two (a 9,874-vertex CAD part with 5% of its faces doubled: 22 GB, then
// out of memory; docs/gsp-core.md, "Doubled faces"). Marks every copy but the lowest-indexed
// face of its vertex set in `skipped` (faces skipped already are not counted as originals);
// reads only conn.nonmanifold_edges, where every copy's edges are. Returns how many it marked.
std::size_t skip_duplicate_faces(const TriangleMesh& mesh, const Connectivity& conn, std::vector<bool>& skipped);
// skipped_faces() with the copies too.
std::vector<bool> skipped_faces(const TriangleMesh& mesh, const Connectivity& conn);

// A point of face f (barycentric `bary`, in f's corner order) where f is a copy skipped by
// skip_duplicate_faces(): the same point in the face kept for its vertex set, whose index is
// returned and whose corner order `bary` then follows. f itself where it is not such a copy.
// corner_begin / corners: the vertex -> corner table (Connectivity::vertex_corner_begin, ...).
Index kept_copy(const std::vector<Triangle>& triangles, const std::vector<Index>& corner_begin, const std::vector<Index>& corners,
                const std::vector<bool>& skipped, Index f, std::array<double, 3>& bary);

// Per halfedge 3 f + i, the 3D length of its edge (corner i to corner i+1 of face f).
std::vector<double> halfedge_lengths(const TriangleMesh& mesh);

// An edge as long as nothing next to its face's longest edge (relative kZeroEdge, below double
// resolution): its ends are one point of the surface, and it has no direction. The face frames
// take their x axis from corner 0 to corner 1 and divide by that length; a length of 1e-16
// there gave a frame of rounding noise (distances of 0 far from the source on a compound STL
// whose two parts share a centre). snap_zero_lengths() makes such lengths exactly 0, which
// every frame and unfolding handles as coincident corners (face_record.hpp).
inline constexpr double kZeroEdge = 1e-12;
// only_faces: snap these faces alone (non-zero entries); the others are snapped already.
void snap_zero_lengths(std::vector<double>& length, const std::vector<char>* only_faces = nullptr);
inline bool zero_length_edge(const std::vector<double>& length, Index h) { return !(length[h] > 0); }

// The member of h's radial ring that the propagation crosses to next: members in skipped faces
// are passed over. h itself where no other is left, and for a halfedge of a skipped face, a
// loop (both ends one vertex) or a zero-length edge: no unfolding crosses those.
inline Index next_crossed(const Connectivity& conn, const std::vector<bool>& skipped_face,
                          const std::vector<double>& length, Index h) {
  const Index e = conn.halfedge_edge[h];
  if (e == kInvalidIndex || skipped_face[face_of(h)] || zero_length_edge(length, conn.edge_halfedge[e])) return h;
  Index next = conn.radial_next[h];
  while (next != h && skipped_face[face_of(next)]) next = conn.radial_next[next];
  return next;
}

// Mean of `length` over the halfedges of faces not skipped (each interior edge counted from
// both sides, which weights it like the faces see it). 1 if there is none. Summed in face
// order, so 3D lengths give the same bits whichever way they were obtained.
double mean_edge_length(const std::vector<double>& length, const std::vector<bool>& skipped_face);

}  // namespace gsp::intrinsic
