#pragma once
// Which vertices bound carried windows (window_bounds.hpp; docs/gsp-core.md, rule 10): the
// saddle and reflex boundary vertices on a planar region's rim, and each face's flags, found at
// preparation. Internal header of libgsp.
#include <gsp/mesh.hpp>

#include <cstdint>
#include <vector>

namespace gsp::detail {

// Per vertex 1 where a line can pass the vertex on a side no surface path takes, so that it
// hides part of what lies beyond: saddle vertices (vertex_kind kSaddleVertex) and reflex
// boundary vertices (a boundary vertex whose angle sum `angle` exceeds pi by more than
// kSaddleExcess: a concave corner of a sheet's rim, the rim of a hole through an open sheet).
// Vertices joining several fans (`nonmanifold`) have no angle sum to judge by: not candidates.
std::vector<std::uint8_t> window_candidates(const TriangleMesh& mesh, const std::vector<std::uint8_t>& vertex_kind,
                                            const std::vector<double>& angle,
                                            const std::vector<std::uint8_t>& boundary_halfedge,
                                            const std::vector<bool>& skipped_face,
                                            const std::vector<Index>& nonmanifold);

// Per vertex 1 where a candidate (window_candidates()) has an edge whose two faces lie in one
// plane (intrinsic::coplanar_across: normals within kCoplanarDegrees, orientations reconciled along the
// edge): a corner of a planar region where the region turns round a hole or a concave corner.
// Empty where no vertex is one (scans, and their subdivisions: a midpoint split makes
// coplanar faces only round the new, flat vertices), so such meshes pay nothing for the
// windows. `ring`: the radial links of the input faces (ring_links.hpp).
std::vector<std::uint8_t> window_corners(const TriangleMesh& mesh, const std::vector<Index>& ring,
                                         const std::vector<std::uint8_t>& candidate,
                                         const std::vector<bool>& skipped_face);

// Per face of a triangulation the propagation runs on (the input's or the intrinsic Delaunay
// one: `triangles`, `ring`, its vertex corners `corner_begin` / `corners`), what the update
// step asks of carried windows: bit i (kWindowEdge0 << i), edge i (corner i -> i + 1) lies in
// one plane with the face across it (two faces on the edge, normals of the corners' 3D
// triangles in one plane, intrinsic::coplanar_across); bit 4 + i (kWindowCorner0 << i), corner i bounds
// windows (`window_corner`). Only the planar regions round the window corners are looked at
// (the faces reached from them over coplanar edges): a window is carried over coplanar edges
// only, so no other face can hold one, and a scan with a few coplanar faces costs a few
// faces. Zero: the face holds no window.
inline constexpr std::uint8_t kWindowEdge0 = 1, kWindowCorner0 = 16;
std::vector<std::uint8_t> window_face_flags(const std::vector<Triangle>& triangles, const std::vector<Index>& ring,
                                            const std::vector<Index>& corner_begin, const std::vector<Index>& corners,
                                            const std::vector<Vec3>& positions,
                                            const std::vector<std::uint8_t>& window_corner,
                                            const std::vector<bool>& skipped_face);

}  // namespace gsp::detail
