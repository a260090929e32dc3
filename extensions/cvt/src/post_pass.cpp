#include "post_pass.hpp"

#include "boundary_collapse.hpp"
#include "boundary_fit.hpp"
#include "flips.hpp"
#include "refine.hpp"
#include "smoothing.hpp"

#include <gsp/cvt/closest_point_index.hpp>

#include <algorithm>
#include <memory>

namespace gsp::cvt::detail {

namespace {

// Vertices no triangle uses any more (collapsed) are dropped; the rest keep their order.
void drop_unused_vertices(TriangleMesh& mesh, std::vector<Index>& vertex_site) {
  std::vector<Index> remap(mesh.num_vertices(), kInvalidIndex);
  for (const Triangle& t : mesh.triangles)
    for (Index v : t) remap[v] = 0;
  Index next = 0;
  for (std::size_t v = 0; v < remap.size(); ++v)
    if (remap[v] == 0) {
      remap[v] = next;
      mesh.positions[next] = mesh.positions[v];
      vertex_site[next] = vertex_site[v];
      ++next;
    }
  mesh.positions.resize(next);
  vertex_site.resize(next);
  for (Triangle& t : mesh.triangles)
    for (Index& v : t) v = remap[v];
}

}  // namespace

void improve_remesh(TriangleMesh& mesh, std::vector<Index>& vertex_site, const TriangleMesh& surface, double diagonal,
                    std::size_t sites, const RemeshOptions& options, const std::vector<bool>* lock, RemeshStats& stats,
                    const ClosestPointIndex* given_index) {
  if (options.flip_edges) stats.flips = improve_by_flips(mesh, options.flip_max_normal_angle, 20, lock);
  if (!options.smooth || mesh.triangles.empty()) return;
  SmoothParams sp;
  sp.passes = options.smooth_passes;
  sp.below_angle = options.smooth_below_angle;
  sp.max_deviation = options.smooth_max_deviation * diagonal;
  sp.flip_max_normal_angle = options.flip_edges ? options.flip_max_normal_angle : -1.0;
  sp.pull_distance = options.pull_distance * diagonal;
  sp.locked = lock;
  const BoundaryCurves curves(surface);
  stats.boundary_snaps = snap_boundary_vertices(mesh, curves, 25.0, lock);
  stats.boundary_collapses =
      collapse_boundary_edges(mesh, curves, std::min(options.smooth_below_angle, 30.0), sp.max_deviation, 3, lock);
  stats.boundary_splits = split_boundary_edges(mesh, curves, options.boundary_chord * diagonal, 30.0, 3, lock);
  vertex_site.resize(mesh.num_vertices(), kInvalidIndex);
  // One index over the surface for all the steps below (the working mesh: 0.3-0.8 M faces).
  std::unique_ptr<ClosestPointIndex> own_index;
  if (!given_index) own_index = std::make_unique<ClosestPointIndex>(surface);
  const ClosestPointIndex& surface_index = given_index ? *given_index : *own_index;
  sp.surface_index = &surface_index;
  const SmoothCounts c = smooth_vertices(mesh, surface, surface, curves, sp);
  stats.smoothing_moves = c.moves;
  stats.smoothing_boundary_moves = c.boundary_moves;
  stats.flips += c.flips;
  stats.pulls = c.pulls;
  // Insertions at input points far from the output, then the moves around them.
  RefineParams rp;
  rp.bound = options.refine_distance * diagonal;
  rp.max_inserted = std::size_t(options.refine_max_fraction * double(sites));
  rp.max_deviation = sp.max_deviation;
  rp.surface_index = &surface_index;
  rp.locked = lock;
  const SettledRefinement added = refine_and_settle(mesh, surface, curves, sp, rp);
  stats.far_point_insertions = added.inserted;
  stats.far_point_attempts = added.attempts;
  stats.flips += added.flips;
  stats.smoothing_moves += added.moves;
  stats.smoothing_boundary_moves += added.boundary_moves;
  vertex_site.resize(mesh.num_vertices(), kInvalidIndex);
  if (stats.boundary_collapses) drop_unused_vertices(mesh, vertex_site);
}

}  // namespace gsp::cvt::detail
