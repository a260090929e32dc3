#pragma once
// Remeshing by the restricted Delaunay triangulation: the dual of a CVT's Voronoi regions.
// Sites become vertices; every place where three or more regions meet (a working-mesh
// vertex whose faces carry three or more labels) becomes a triangle (a polygon fan for more
// than three), ordered the way the regions turn around that vertex, so each dual triangle has
// the orientation of the input faces under it. At the boundary, the outside counts as one
// more region that is then left out: the dual's boundary edges join the regions that follow
// each other along the input's boundary loops.
//
//   auto cvt = gsp::cvt::compute_cvt(mesh, options);
//   gsp::cvt::RemeshResult r = gsp::cvt::restricted_delaunay(cvt);
//   r.mesh   // sites as vertices (sites no triangle uses are dropped)
#include <gsp/cvt/cvt.hpp>

#include <functional>

namespace gsp::cvt {

struct RemeshOptions {
  // Flip edges of the dual that are not locally Delaunay when that raises the smaller of the
  // two triangles' smallest angles, across nearly flat pairs only (normals within
  // `flip_max_normal_angle` degrees). The restricted Delaunay dual of face-granular regions
  // has such edges where four regions meet at two nearby vertices instead of one. Vertices
  // and topology are unchanged.
  bool flip_edges = true;
  double flip_max_normal_angle = 20.0;
  // The post-pass (docs/cvt.md), in this order: boundary vertices off the input's boundary
  // curve are snapped onto it; boundary edges opposite a triangle's smallest angle (below
  // min(`smooth_below_angle`, 30)) are collapsed where that raises the angles around them;
  // boundary edges whose chord cuts the input's boundary curve by more than `boundary_chord`
  // are split; edges opposite an angle above 120 degrees are flipped where the surface stays
  // close (caps across thin folds); then vertices whose triangles have an angle below
  // `smooth_below_angle` degrees move: interior ones on the input surface (Embree closest
  // point), boundary ones along the input's boundary curve, by a search on the smallest angle
  // of their triangles. A move is kept only if it raises that angle, folds nothing, and keeps
  // the triangles within max(smooth_max_deviation * diagonal, before) of the input and the
  // input within the same bound of the triangles. Flips again after every pass; last the
  // pulls (`pull_distance`) and the insertions (`refine_distance`). Every vertex stays on the
  // input surface and the topology is unchanged; the vertex count changes by the collapses,
  // splits and insertions (reported).
  bool smooth = true;
  int smooth_passes = 8;
  double smooth_below_angle = 40.0;
  double smooth_max_deviation = 4e-3;   // fraction of the bounding-box diagonal
  // Boundary edges whose chord is farther than this fraction of the diagonal from the input's
  // boundary curve are split at the curve's farthest point (a new vertex without a site) when
  // that makes no angle below min(the triangle's, 30 degrees). 0: no splits.
  double boundary_chord = 2.5e-3;
  // Last: points of the input (the working mesh's vertices) farther than this fraction of the
  // diagonal from the output pull the best corner of their nearest triangle onto them, under
  // the same checks with this bound and without lowering the mesh's minimum angle. 0: off.
  double pull_distance = 3e-3;
  // Then points of the input still farther than this fraction of the diagonal from the output
  // become vertices, the worst first: the nearest triangle (or interior edge) is split at the
  // point and the edges around it flipped, if no changed triangle has an angle below
  // min(the mesh's minimum angle, 30 degrees), folds, or leaves the surface (the checks of the
  // moves, both ways); then the moves try the new vertices' neighbourhoods. At most
  // `refine_max_fraction` times the site count. Features narrower than an edge (falconstatue's
  // talon tips) are cut by the dual, and no move of the vertices around them reaches that far
  // without ruining their angles. 0: off.
  double refine_distance = 4e-3;
  double refine_max_fraction = 0.02;
  // Called with the dual as the regions give it, before the flips and the post-pass; when it
  // returns false the dual is returned as it is, without them. remesh_surface uses it to skip
  // the post-pass of a dual wrong in more places than its retries would try to mend: on the
  // corpus no such dual came out right after the post-pass (docs/cvt.md, "A dual beyond
  // repair"), and the post-pass was most of the time lost on it. Empty: always go on.
  std::function<bool(const TriangleMesh&)> accept_dual;
};

struct RemeshStats {
  std::size_t junctions = 0;            // working vertices where >= 3 regions meet
  std::size_t junctions_over_three = 0; // of which more than three (fanned polygons)
  std::size_t duplicate_triangles = 0;  // the same three regions meeting again (dropped)
  std::size_t skipped_junctions = 0;    // a region met twice around one vertex, or a non-manifold vertex
  std::size_t unused_sites = 0;         // sites without a triangle (not in the output)
  std::size_t flips = 0;                // edges flipped (RemeshOptions::flip_edges, and during smoothing)
  std::size_t smoothing_moves = 0;      // vertex moves kept by the smoothing (of which along the boundary:)
  std::size_t smoothing_boundary_moves = 0;
  std::size_t boundary_collapses = 0;   // short boundary edges collapsed (one vertex fewer each)
  std::size_t boundary_splits = 0;      // boundary edges split (one vertex more each)
  std::size_t boundary_snaps = 0;       // boundary vertices moved onto the input's boundary curve
  std::size_t pulls = 0;                // vertices pulled onto input points far from the output
  std::size_t far_point_insertions = 0; // vertices added at input points far from the output (one more each)
  std::size_t far_point_attempts = 0;   // rounds of those insertions; all but the last were put back
  std::size_t fold_refinements = 0;     // remeshes by edge operations made again, refined where one folded
};

struct RemeshResult {
  TriangleMesh mesh;
  std::vector<Index> vertex_site;   // output vertex -> index into cvt.sites (kInvalidIndex: a boundary split or an insertion)
  RemeshStats stats;
};

RemeshResult restricted_delaunay(const CvtResult& cvt, const RemeshOptions& options = {});

}  // namespace gsp::cvt
