// The restricted Delaunay dual of face-labelled Voronoi regions (see remesh.hpp).
#include "boundary_collapse.hpp"
#include "boundary_fit.hpp"
#include "flips.hpp"
#include "junctions.hpp"
#include "refine.hpp"
#include "smoothing.hpp"

#include <gsp/cvt/closest_point_index.hpp>
#include <gsp/cvt/remesh.hpp>
#include <gsp/errors.hpp>

#include <algorithm>

namespace gsp::cvt {

namespace {

// Vertices no triangle uses any more (collapsed) are dropped; the rest keep their order.
void drop_unused_vertices(RemeshResult& r) {
  std::vector<Index> remap(r.mesh.num_vertices(), kInvalidIndex);
  for (const Triangle& t : r.mesh.triangles)
    for (Index v : t) remap[v] = 0;
  Index next = 0;
  for (std::size_t v = 0; v < remap.size(); ++v)
    if (remap[v] == 0) {
      remap[v] = next;
      r.mesh.positions[next] = r.mesh.positions[v];
      r.vertex_site[next] = r.vertex_site[v];
      ++next;
    }
  r.mesh.positions.resize(next);
  r.vertex_site.resize(next);
  for (Triangle& t : r.mesh.triangles)
    for (Index& v : t) v = remap[v];
}

}  // namespace

RemeshResult restricted_delaunay(const CvtResult& cvt, const RemeshOptions& options) {
  const TriangleMesh& m = cvt.working.mesh;
  const std::vector<Index>& label = cvt.working_face_label;
  if (label.size() != m.num_faces()) throw InvalidInput("restricted_delaunay: labels do not match the working mesh");
  detail::DualTriangles d = detail::dual_triangles(m, build_connectivity(m), label, cvt.working_site_position);
  RemeshResult r;
  r.stats = d.stats;
  std::vector<Index> remap(cvt.sites.size(), kInvalidIndex);
  for (Triangle& t : d.triangles)
    for (Index& x : t) {
      if (remap[x] == kInvalidIndex) {
        remap[x] = Index(r.vertex_site.size());
        r.vertex_site.push_back(x);
        r.mesh.positions.push_back(cvt.sites[x].position);
      }
      x = remap[x];
    }
  r.mesh.triangles = std::move(d.triangles);
  r.stats.unused_sites = cvt.sites.size() - r.vertex_site.size();
  if (options.accept_dual && !options.accept_dual(r.mesh)) return r;
  // The feature curves' samples and the edges between them stay as the dual made them.
  std::vector<bool> locked(r.vertex_site.size(), false);
  for (std::size_t v = 0; v < locked.size(); ++v) locked[v] = cvt.sites[r.vertex_site[v]].fixed;
  const std::vector<bool>* lock = std::count(locked.begin(), locked.end(), true) ? &locked : nullptr;
  if (options.flip_edges) r.stats.flips = detail::improve_by_flips(r.mesh, options.flip_max_normal_angle, 20, lock);
  if (options.smooth && !r.mesh.triangles.empty()) {
    detail::SmoothParams sp;
    sp.passes = options.smooth_passes;
    sp.below_angle = options.smooth_below_angle;
    sp.max_deviation = options.smooth_max_deviation * cvt.diagonal;
    sp.flip_max_normal_angle = options.flip_edges ? options.flip_max_normal_angle : -1.0;
    sp.pull_distance = options.pull_distance * cvt.diagonal;
    sp.locked = lock;
    // The working mesh is the input's surface; projecting onto the input itself (rebuilt from
    // the working faces' parents, far fewer faces) is faster but ends in lower minimum angles
    // (docs/cvt.md, the post-pass's cost).
    const TriangleMesh& surface = cvt.working.mesh;
    const detail::BoundaryCurves curves(surface);
    r.stats.boundary_snaps = detail::snap_boundary_vertices(r.mesh, curves, 25.0, lock);
    r.stats.boundary_collapses =
        detail::collapse_boundary_edges(r.mesh, curves, std::min(options.smooth_below_angle, 30.0), sp.max_deviation, 3, lock);
    r.stats.boundary_splits =
        detail::split_boundary_edges(r.mesh, curves, options.boundary_chord * cvt.diagonal, 30.0, 3, lock);
    r.vertex_site.resize(r.mesh.num_vertices(), kInvalidIndex);
    // One index over the surface for all the steps below (the working mesh: 0.3-0.8 M faces).
    const ClosestPointIndex surface_index(surface);
    sp.surface_index = &surface_index;
    const detail::SmoothCounts c = detail::smooth_vertices(r.mesh, surface, cvt.working.mesh, curves, sp);
    r.stats.smoothing_moves = c.moves;
    r.stats.smoothing_boundary_moves = c.boundary_moves;
    r.stats.flips += c.flips;
    r.stats.pulls = c.pulls;
    // Insertions at input points far from the output, then the moves around them.
    detail::RefineParams rp;
    rp.bound = options.refine_distance * cvt.diagonal;
    rp.max_inserted = std::size_t(options.refine_max_fraction * double(cvt.sites.size()));
    rp.max_deviation = sp.max_deviation;
    rp.surface_index = &surface_index;
    rp.locked = lock;
    const detail::SettledRefinement added = detail::refine_and_settle(r.mesh, surface, curves, sp, rp);
    r.stats.far_point_insertions = added.inserted;
    r.stats.far_point_attempts = added.attempts;
    r.stats.flips += added.flips;
    r.stats.smoothing_moves += added.moves;
    r.stats.smoothing_boundary_moves += added.boundary_moves;
    r.vertex_site.resize(r.mesh.num_vertices(), kInvalidIndex);
    if (r.stats.boundary_collapses) drop_unused_vertices(r);
  }
  return r;
}

}  // namespace gsp::cvt
