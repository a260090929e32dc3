#pragma once
// Line sources: polylines on the surface of a triangle mesh, cut into straight pieces that each
// lie inside one face. Every piece remembers which source segment it belongs to, so a distance
// field can report the nearest segment per vertex.
//
//   auto src = gsp::lines::edge_source(mesh, {{0, 1}, {1, 2}});       // mesh edges
//   auto src = gsp::lines::boundary_source(mesh);                     // every boundary edge
//   auto src = gsp::lines::polyline_source(mesh, {points});           // 3D polylines, snapped
//   auto r = gsp::lines::line_distances(mesh, src);                   // line_distances.hpp
#include <gsp/mesh.hpp>

#include <array>
#include <utility>
#include <vector>

namespace gsp::lines {

// A straight piece of a source segment inside face `face`, from `start` to `end` (barycentric
// weights of the face's corners 0, 1, 2). Straight in the face's plane, so also straight in any
// unfolding that contains the face.
//
// Pieces that continue one another straight in the unfolding of their faces form a run (on a
// plane: the whole segment). The propagation starts from the whole run, not from the piece:
// `before` and `after` say how far the run extends beyond the piece's start and end (model
// units, along the piece's direction). Otherwise a piece's wave would only be kept where that
// piece is nearest, a thin band normal to it, and distances would come from the wrong piece.
struct SegmentPiece {
  Index face = kInvalidIndex;
  std::array<double, 3> start{1, 0, 0};
  std::array<double, 3> end{1, 0, 0};
  Index segment = 0;   // index into LineSource::segments
  double before = 0, after = 0;
};

struct LineSource {
  std::vector<SegmentPiece> pieces;
  // Per source segment: its two ends in 3D (on the surface). Segment i is what
  // LineResult::vertex_segment reports.
  std::vector<std::array<Vec3, 2>> segments;
  double max_snap_distance = 0;   // polyline_source: how far a polyline point was from the surface

  std::size_t num_segments() const { return segments.size(); }
};

// Mesh edges given as vertex pairs; segment i is edges[i]. The piece is placed in every face
// that has the edge (both sides of a manifold edge, every face of a non-manifold one). Throws
// InvalidInput when a vertex does not exist, a pair repeats a vertex, or a pair is not an edge.
LineSource edge_source(const TriangleMesh& mesh, const std::vector<std::array<Index, 2>>& edges);

// A chain of vertices v0 - v1 - ... whose consecutive vertices are mesh edges (closed: the
// last vertex connects back to the first). Segment i is (chain[i], chain[i+1]).
LineSource vertex_chain_source(const TriangleMesh& mesh, const std::vector<Index>& chain, bool closed);

// Every boundary edge (an edge with one face), in the order of the faces' halfedges.
// Throws InvalidInput("mesh has no boundary") when there is none.
LineSource boundary_source(const TriangleMesh& mesh);

// 3D polylines laid onto the surface (polyline_snap.cpp): every point is snapped to its closest
// surface point (gsp::closest_surface_point); two consecutive snapped points in the same face
// are joined by a straight piece, in faces sharing an edge by the straight line of their
// unfolding; farther apart the 3D segment's midpoint is snapped too and both halves are joined
// the same way (recursively), so the source is the closest-point projection of the polyline.
// A polyline is closed when its last point equals its first. Segment numbers run over all
// polylines in order: polyline 0's segments first. Throws InvalidInput for a polyline of fewer
// than two points, a non-finite coordinate, a mesh without faces, or a segment whose
// projection jumps (the polyline runs far from the surface, across a gap).
using Polyline = std::vector<Vec3>;
LineSource polyline_source(const TriangleMesh& mesh, const std::vector<Polyline>& polylines);

// Appends b's pieces and segments to a (b's segment numbers follow a's).
void append(LineSource& a, const LineSource& b);

}  // namespace gsp::lines
