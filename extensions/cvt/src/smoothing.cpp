#include "smoothing.hpp"

#include "cap_flips.hpp"
#include "flips.hpp"
#include "locked_vertices.hpp"
#include "pulls.hpp"
#include "smoothing_context.hpp"
#include "vertex_search.hpp"

#include <gsp/cvt/closest_point_index.hpp>

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

namespace gsp::cvt::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

// One sweep of moves over the vertices still to try. A vertex is tried again only when its
// triangles changed since its last try (a neighbour moved, a flip): the search is
// deterministic, it would find nothing new.
std::size_t move_pass(SmoothingContext& c, const SmoothParams& p, std::vector<bool>& dirty, std::vector<bool>& moved_now,
                      SmoothCounts& counts) {
  const double below = p.below_angle * kPi / 180.0;
  std::size_t moved = 0;
  for (Index v = 0; v < c.m.num_vertices(); ++v) {
    if (c.rings.empty(v) || !dirty[v] || is_locked(c.locked, v)) continue;
    if (p.movable && (v >= p.movable->size() || !(*p.movable)[v])) continue;
    dirty[v] = false;
    Move move;
    if (!find_move(c, v, below, p.max_deviation, move)) continue;
    c.move(v, move.x);
    moved_now[v] = true;
    if (c.rings.on_boundary(v)) c.arc[v] = move.s, ++counts.boundary_moves;
    ++moved;
    c.rings.mark_ring(c.m, v, dirty);
  }
  return moved;
}

// The flips after each sweep open up angles the moves cannot; the corners of the flipped
// triangles are tried again. After a pass that converged, the next examines only the quads
// the sweep's moves changed (`moved`, cleared here): the flips examining every edge after every
// sweep were 18% of a demosthenes remesh's instructions.
std::size_t flip_pass(SmoothingContext& c, double flip_max_normal_angle, std::vector<bool>& dirty, std::vector<bool>& moved,
                      bool& converged, std::optional<DirectedEdges>& edges) {
  if (flip_max_normal_angle < 0) return 0;
  if (!edges) edges.emplace(c.m);
  const std::vector<Triangle> before_flips = c.m.triangles;
  const std::size_t flips = improve_by_flips(c.m, flip_max_normal_angle, 20, c.locked, converged ? &moved : nullptr,
                                             &converged, edges->unique ? &*edges : nullptr);
  std::fill(moved.begin(), moved.end(), false);
  for (std::size_t f = 0; f < c.m.num_faces(); ++f)
    if (c.m.triangles[f] != before_flips[f])
      for (Index w : c.m.triangles[f]) dirty[w] = true;
  return flips;
}

}  // namespace

SmoothCounts smooth_vertices(TriangleMesh& m, const TriangleMesh& surface, const TriangleMesh& samples,
                             const BoundaryCurves& curves, const SmoothParams& p) {
  SmoothCounts counts;
  std::unique_ptr<ClosestPointIndex> own_index;
  if (!p.surface_index) own_index = std::make_unique<ClosestPointIndex>(surface);
  SmoothingContext c(m, surface, p.surface_index ? *p.surface_index : *own_index, samples, curves);
  c.locked = p.locked;
  std::vector<bool> dirty(m.num_vertices(), true), moved(m.num_vertices(), false);
  bool flips_converged = false;   // the first flip pass examines every edge
  std::optional<DirectedEdges> edges;   // built at the first flip pass, after the cap flips
  if (p.only) dirty = *p.only, dirty.resize(m.num_vertices(), false);
  if (p.flip_max_normal_angle >= 0 && p.cap_flips) counts.flips += remove_caps_keeping_surface(c, p.max_deviation);
  for (int pass = 0; pass < p.passes; ++pass) {
    const std::size_t moves = move_pass(c, p, dirty, moved, counts);
    counts.moves += moves;
    const std::size_t flips = flip_pass(c, p.flip_max_normal_angle, dirty, moved, flips_converged, edges);
    counts.flips += flips;
    if (moves == 0 && flips == 0) break;
    // Flips change no boundary link where no directed edge is in two faces (VertexRings).
    if (flips) edges && edges->unique ? c.rings.rebuild_rings(m) : c.rings.rebuild(m);
  }
  if (p.pull_distance > 0) counts.pulls += pull_towards_far_samples(c, p.pull_distance);
  return counts;
}

}  // namespace gsp::cvt::detail
