#pragma once
// Vertices added where the remesh is far from the input (see remesh.hpp,
// RemeshOptions::refine_distance): the input-to-output half of the Hausdorff distance comes from
// features narrower than an edge (talon tips, spikes, sharp ridges) that no site sits on, and
// moving the vertices around them cannot reach far enough without ruining their angles.
#include "smoothing.hpp"

#include <gsp/mesh.hpp>

#include <cstddef>
#include <vector>

namespace gsp::cvt {
class ClosestPointIndex;
}

namespace gsp::cvt::detail {

struct RefineParams {
  double bound = 0;               // model units: input points farther than this get a vertex
  std::size_t max_inserted = 0;   // cap on the vertices added
  double floor_angle_deg = 30.0;  // no changed triangle below min(the mesh's minimum angle, this)
  double max_deviation = 0;       // model units: the surface checks' bound (as the moves')
  int rounds = 8;
  // Degrees: insertions may go this far below the floor (the caller moves the vertices around
  // them and checks the floor after). Points marked in `skip` (per surface vertex) are left out.
  double slack_deg = 0;
  const std::vector<bool>* skip = nullptr;
  const std::vector<bool>* locked = nullptr;   // no split or flip of an edge between two (locked_vertices.hpp)
  const ClosestPointIndex* surface_index = nullptr;   // over `surface`, or nullptr: built here
};

struct RefineResult {
  std::size_t inserted = 0, flips = 0;
  std::vector<bool> touched;      // per vertex of the result: a new vertex or a corner of a changed triangle
  std::vector<Index> points;      // the surface vertex each new vertex sits on, in order (they follow the old ones)
  double floor = 0;               // radians: min(the mesh's minimum angle as it came, floor_angle_deg)
};

// `surface`: the input's surface (the working mesh); its vertices are the input points checked.
// The worst first, each point farther than `bound` from `mesh` becomes a vertex: the nearest
// triangle is split at it (or the nearest interior edge, when the point lies near one), then the
// edges around the new vertex are flipped where that raises the smaller angle of their pair. An
// insertion is kept only if no changed triangle has an angle below the floor or faces away from
// the triangles it replaced, their centroids and edge midpoints stay within
// max(max_deviation, before) of the surface, and no input point near them ends up farther than
// max(bound, before) from the mesh. Manifold, Euler characteristic and boundary are kept
// (interior splits and flips only).
RefineResult insert_at_far_points(TriangleMesh& mesh, const TriangleMesh& surface, const RefineParams& params);

struct SettledRefinement {
  std::size_t inserted = 0, flips = 0, moves = 0, boundary_moves = 0;
  std::size_t attempts = 0;   // insertion rounds made (those put back included)
};

// insert_at_far_points with 10 degrees of slack, then the vertex moves within two rings of the
// new vertices (`smooth` without cap flips or pulls, same surface checks, so they do not give
// the distance back) to win the slack back. Where a new vertex still has a triangle below the
// floor within one ring, the mesh is put back and the insertions made again without those
// points (twice at most), the last time without slack: the floor always holds. Last, one
// pass of the same moves over every vertex.
SettledRefinement refine_and_settle(TriangleMesh& mesh, const TriangleMesh& surface, const BoundaryCurves& curves,
                                    const SmoothParams& smooth, RefineParams params);

}  // namespace gsp::cvt::detail
