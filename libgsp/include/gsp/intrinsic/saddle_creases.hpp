#pragma once
// The flat-corner rule's crease limits (internal layer shared by the core and the line sources'
// kernel; not a stable API; docs/gsp-core.md, rule 4).
//
// A vertex whose angle sum is 2 pi is flat however its faces are bent, so a straight crease
// line of such vertices (an edge of the original mesh after midpoint splits, a fold of a
// developable part) unfolds flat along its length. Where such a crease ends at a saddle, lines
// carried straight past the crease's flat vertices (rule 4) come out on the far side of the
// crease and go on to pass the saddle at its end on a side no surface path takes: on the bunny
// split twice at edge midpoints (557k vertices) GSP was 1.36% below exact on average. The
// flat vertices of such a crease are plain. Found from the 3D creases, so for meshes with 3D
// lengths only; flat vertices in the middle of a plane (no crease) and creases that end
// elsewhere keep the rule (planar CAD faces, developable parts: their exactness).
//
// A flat vertex alone on its crease, between two curved vertices (the midpoint of an edge of
// a mesh split once), with no neighbour a path may turn at, is treated as convex (rule 6: a
// bend there only over-estimates, and the line to the centroid is checked, not carried past).
// The vertices of longer creases (a mesh split twice) lost accuracy that way and stay plain
// (the measurements: docs/gsp-core.md, rule 4, "Alone on a crease").
#include <gsp/intrinsic/vertex_kinds.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace gsp::intrinsic {

// Makes plain (kPlainVertex) every kFlatVertex of `kind` on a crease that ends at a saddle,
// and convex (kConvexVertex) each vertex of `lone` (flat vertices the caller made plain for a
// curved neighbour, none of whose neighbours is a saddle or plain) that is alone on its
// crease: exactly two crease edges, neither of whose other ends is flat.
// A crease edge: an edge whose faces do not lie in one plane (kCoplanarDegrees,
// gsp/intrinsic/coplanar_faces.hpp); a crease line: intrinsically flat vertices (angle sum 2 pi
// within kFlatAngleTolerance) with exactly two crease edges each, joined by those edges; it
// ends at the first vertex that is not one of them, a saddle if that vertex's angle sum exceeds
// 2 pi by more than the same tolerance (any saddle: on midpoint-split scans the smallest ones
// bend lines too). Only `interior` vertices (used, not on the boundary, not joining several
// fans) are flat or saddles here. `links`: per halfedge, the core's radial link
// (libgsp/src/ring_links.hpp: the next halfedge of its edge, kRingPair where the edge joins
// exactly two faces that take part, and both halfedges' direction bits); only the pairs are
// read. `face_normal`: per face its unit normal (unit_normal() of face_normal(),
// gsp/intrinsic/coplanar_faces.hpp), as CornerAngleSums::normal holds it, or empty: then
// computed here. vertex_kinds() runs it when given the links; it costs nothing on a mesh
// without flat vertices.
void apply_crease_rules(const TriangleMesh& mesh, const std::vector<double>& angle,
                        const std::vector<std::uint8_t>& interior, const std::vector<bool>& skipped_face,
                        const std::vector<Index>& links, const std::vector<std::array<float, 3>>& face_normal,
                        const std::vector<Index>& lone, std::vector<std::uint8_t>& kind);

}  // namespace gsp::intrinsic
