#pragma once
// Shortening a surface path to a locally shortest geodesic: the faces the path runs through
// (its sleeve) are unfolded into the plane, the funnel algorithm gives the shortest path inside
// them (straight, bending only at sleeve vertices), and every bend at a vertex whose angle on
// the other side is below pi is rerouted through that side's fan of faces, which strictly
// shortens the path; repeated until no bend can be undone (paper Section 5.8 traces the path,
// this makes it taut; the approach is the classic sleeve + funnel iteration).
#include <gsp/connectivity.hpp>
#include <gsp/pathfinding/path.hpp>

#include <vector>

namespace gsp::pathfinding::detail {

struct SleeveOptions {
  std::size_t max_reroutes = 0;   // 0: 4 * faces of the first sleeve + 256
};

// A path from `start` to `end` (surface points: face + barycentric) running through
// `segment_faces` in order (consecutive ones share an edge, or a vertex the path runs through).
// On success writes the shortened path (same end points, each point's face again holds its
// incoming segment, barycentric weights >= 0) and returns true; returns false, leaving `out`
// alone, when the walk cannot be turned into a sleeve (it passes a non-manifold vertex or edge
// in a way the fan walk cannot follow): the caller keeps its own path then.
bool shorten_in_sleeve(const TriangleMesh& mesh, const Connectivity& conn, const PathPoint& start, const PathPoint& end,
                       const std::vector<Index>& segment_faces, std::vector<PathPoint>& out,
                       const SleeveOptions& options = {});

}  // namespace gsp::pathfinding::detail
