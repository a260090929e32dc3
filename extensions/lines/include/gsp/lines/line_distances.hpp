#pragma once
// Geodesic distances from line sources (line_source.hpp): the propagated primitive is the
// segment, not its sample points, so on a plane the distance is exactly the distance to the
// nearest segment. Computed in double precision. See docs/lines.md for the method.
//
//   const auto src = gsp::lines::boundary_source(mesh);
//   const auto r = gsp::lines::line_distances(mesh, src);
//   r.vertex_distance[v], r.vertex_segment[v]   // per input vertex
#include <gsp/heuristic.hpp>
#include <gsp/lines/line_source.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace gsp::lines {

struct LineOptions {
  // Faces whose distance exceeds this are not expanded; vertices beyond it are +inf.
  double max_distance = std::numeric_limits<double>::infinity();
  // Decides when a carried segment stops being visible through an edge (then the wave bends
  // at the edge's end vertex). The same probe as the core's (gsp/heuristic.hpp).
  VisibilityHeuristic heuristic = VisibilityHeuristic::published();
  // The straight-line bound (docs/lines.md): no value below the 3D distance to the nearest
  // straight piece of the source; values below are raised to it, last.
  bool straight_line_bound = true;
};

struct LineStats {
  std::uint64_t segments = 0;         // source segments
  std::uint64_t pieces = 0;           // straight pieces (a segment crossing k faces has k)
  std::uint64_t faces_seeded = 0;     // faces holding a piece at the start
  std::uint64_t candidates = 0;       // waves carried into a face and evaluated
  std::uint64_t waves_accepted = 0;   // candidates kept (shorter at a corner or the centroid)
  std::uint64_t bends = 0;            // accepted waves that bent at a vertex (not visible)
  std::uint64_t expansions = 0;       // waves carried over their face's edges
  std::uint64_t stale_skipped = 0;    // queue entries of waves dropped before their turn
  std::uint64_t faces_reached = 0;
  std::uint64_t max_waves_per_face = 0;
  std::uint64_t raised_to_line = 0;   // vertices raised to the straight-line bound (by > 1e-6)
  // The core's vertex relaxation (gsp/intrinsic/edge_relaxation.hpp): values lowered along
  // the edges, rounds that seeded point sources, and those sources.
  std::uint64_t relaxed_vertices = 0;
  std::uint64_t relaxation_rounds = 0;
  std::uint64_t pseudo_sources = 0;
};

struct LineResult {
  std::vector<double> vertex_distance;   // per input vertex; +inf where unreachable
  std::vector<Index> vertex_segment;     // nearest source segment; kInvalidIndex if unreached
  LineStats stats;
};

// Throws InvalidInput for a piece naming a missing face or with bad barycentric weights
// (negative, or not summing to 1 within 1e-6).
LineResult line_distances(const TriangleMesh& mesh, const LineSource& source, const LineOptions& options = {});

}  // namespace gsp::lines
