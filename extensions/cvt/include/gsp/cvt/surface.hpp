#pragma once
// Remeshing a whole input, whatever it is: every connected component on its own (after the
// caller's welding, after joining boundary vertices at the same position: seams,
// stitch_boundary_vertices; after leaving out doubled faces and faces with a repeated vertex,
// drop_duplicate_faces, and after splitting vertices where fans of faces only touch, which
// makes such a component the manifold surface it describes: split_nonmanifold_vertices),
// with a share of the vertex budget proportional to its area. What cannot
// be remeshed as a surface is kept as it is and reported, per component, with the reason:
// components too small for the budget, non-manifold or non-orientable ones, and those whose
// remesh did not come out a manifold with their Euler characteristic and boundary loops.
// Inconsistently oriented components are oriented first (the majority's orientation kept).
//
//   gsp::cvt::SurfaceRemeshOptions o;
//   o.cvt.sites = 5000;
//   gsp::cvt::SurfaceRemeshResult r = gsp::cvt::remesh_surface(mesh, o);
//   r.mesh; for (auto& c : r.components) if (c.outcome != ComponentOutcome::remeshed) ... c.reason
#include <gsp/cvt/cvt.hpp>
#include <gsp/cvt/remesh.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gsp::cvt {

// How each component is remeshed (docs/cvt.md, "Two methods").
enum class RemeshMethod {
  // The CVT's restricted Delaunay dual (regions, sites and energy reported); edge operations
  // only where no dual has the component's topology (SurfaceRemeshOptions::edge_operations).
  cvt,
  // Edge operations first (splits, collapses, flips, tangential smoothing, projection; then the
  // dual's post-pass), several times faster than the CVT; the CVT where that remesh is not
  // kept, or is below 20 degrees (then the one with the larger smallest angle is kept). No
  // regions for components remeshed by edge operations.
  edges,
};

const char* method_name(RemeshMethod m);   // "cvt", "edges"
RemeshMethod remesh_method(const std::string& name);   // the inverse; InvalidInput for other names

struct SurfaceRemeshOptions {
  CvtOptions cvt;   // sites: the budget of the whole mesh; or edge_length, for every component
  RemeshOptions remesh;
  RemeshMethod method = RemeshMethod::cvt;
  // The fewest sites a component is remeshed with: the dual of fewer regions cannot be trusted
  // to have the component's topology (a closed surface needs at least 4, a torus many more).
  // A component whose share of the budget is smaller gets this many when it has at least as
  // many vertices (kept, it would add all of them to the output), and one with fewer vertices
  // and an angle below 20 degrees while the sites so added stay within max_small_raise_fraction
  // of the budget (the largest first; added to the budget, the other components keep their
  // shares); the others are kept as they are. A component remeshed above its share is kept as it was where its remesh's
  // smallest angle is below 20 degrees and below its own.
  std::size_t min_component_sites = 20;
  double max_small_raise_fraction = 0.05;
  // A component whose remesh lacks its topology at a few places only (at most
  // retry_defect_fraction of its sites, at least one, are non-manifold or otherwise wrong, or
  // only its Euler characteristic or loops differ) is remeshed again from other initial sites
  // (CvtOptions::seed + 1, + 2, ...) up to `retries` times before it is kept as it was: such a
  // dual went wrong at a few regions whose shape depends on where the sites started (and, on
  // two threads, on the order in which ties in the propagation fell). A dual broken all over
  // a region (a CAD part's flat face fanned into slivers) breaks again from any start, and
  // each try costs a whole CVT, so those are not tried again.
  std::size_t retries = 2;
  double retry_defect_fraction = 0.01;
  // A component's CVT stops after this many Lloyd steps where its dual is wrong at more than
  // max(hopeless_defects, hopeless_fraction * sites) places (CvtOptions::hopeless_check_iteration;
  // the component is then kept, its reason says so). On the corpus no dual that far off came
  // right: the boiler section was wrong at 1,282 places after 5 steps and 832 after 12, the
  // tank tread's parts at 308 and 332, the gear wheel at 224, and all were kept in the end after
  // 6-13 s of Lloyd steps; the duals that came right were wrong at 27 places at most then
  // (docs/cvt.md, "Hopeless duals"). 0: every CVT runs to the end.
  int hopeless_check_iteration = 5;
  std::size_t hopeless_defects = 50;
  double hopeless_fraction = 0.02;
  // A component none of whose CVT duals has its topology is remeshed by edge operations
  // instead (long edges split, short ones collapsed, flips towards valence 6, tangential
  // smoothing and projection onto the input, edge_iterations rounds, at the spacing of its
  // share of the sites): those keep the topology by construction. Kept as it is only where
  // that fails too. Off: such components are kept (docs/cvt.md, "Edge operations where the
  // dual fails").
  bool edge_operations = true;
  int edge_iterations = 10;
  // Creases of the input sharper than this (degrees between the faces' normals) stay chains
  // of edges in a remesh by edge operations (CvtOptions::feature_angle instead where that is
  // set): a CAD part's corners and edges kept instead of rounded off.
  double edge_feature_angle = 40;
  // Edges of a remesh by edge operations shorter where the input bends tighter than the spacing
  // can follow: an edge spans at most this many degrees of a bend, down to a quarter of the
  // spacing (fingers and rods thinner than an edge, which one spacing folds onto one side
  // of themselves). 0: one spacing everywhere (docs/cvt.md, "A sizing field for the edge
  // remesh").
  double edge_sizing_angle = 0;
};

enum class ComponentOutcome {
  remeshed,
  kept_small,          // share of the budget and vertex count below min_component_sites
  kept_nonmanifold,    // non-manifold edges or vertices
  kept_nonorientable,  // no consistent orientation exists
  kept_topology,       // the remesh was not a manifold with the component's topology
  kept_error,          // the CVT or the dual threw (reason: its message)
};
const char* outcome_name(ComponentOutcome o);

struct ComponentReport {
  std::size_t input_vertices = 0, input_faces = 0;
  double area = 0;
  std::int64_t euler_characteristic = 0;   // of the input component
  std::size_t boundary_loops = 0;
  std::size_t sites = 0;                   // asked for (0 when kept before the CVT)
  std::size_t faces_flipped = 0;           // by the orientation fix
  // The remesh with fixed sites (CvtOptions::feature_angle's curves, cone_angle's spike tips)
  // did not have the component's topology, so it was remeshed without them (sharp edges
  // chamfered and tips cut as with feature_angle = 0 and cone_angle = 0).
  bool features_dropped = false;
  std::size_t retries = 0;                 // remeshes from other initial sites (SurfaceRemeshOptions::retries)
  // Remeshes with twice the sites of the one before (a component raised to min_component_sites
  // whose dual lacked its topology: too thin for so few regions; at most 2, within its vertex
  // count).
  std::size_t grown = 0;
  std::size_t output_vertices = 0, output_faces = 0;
  // Remeshed by edge operations: first (RemeshMethod::edges), or after the CVT, whose failure
  // (or smaller smallest angle) cvt_failure then says. No regions then.
  bool by_edge_operations = false;
  std::string cvt_failure;
  // With RemeshMethod::edges: why the remesh by edge operations was not kept (the component
  // then had the CVT); empty where it was, or was not tried first.
  std::string edge_failure;
  ComponentOutcome outcome = ComponentOutcome::remeshed;
  std::string reason;                      // empty when remeshed
  double cvt_seconds = 0, remesh_seconds = 0;
};

struct SurfaceRemeshResult {
  TriangleMesh mesh;                       // remeshed components, then kept ones, in component order
  std::vector<ComponentReport> components; // by first input face, of the input with its fans split
  std::vector<Index> vertex_label;         // per input vertex: its region (index into all sites), or kInvalidIndex
  std::size_t sites = 0;                   // over all remeshed components
  double energy = 0;
  // The total energy per iteration; a component that stopped earlier counts with its last
  // energy (so the curve stays non-increasing, like each component's).
  std::vector<double> energy_curve;
  double area = 0;                         // of the whole input
  std::size_t boundary_vertices_stitched = 0;   // joined into another at the same position (stitch_boundary_vertices)
  std::size_t vertices_split = 0;          // input vertices where fans only touched (split_nonmanifold_vertices)
  // Input faces left out (drop_duplicate_faces): on the same three vertices as an earlier
  // face, or with a vertex repeated.
  std::size_t duplicate_faces_removed = 0, repeated_vertex_faces_removed = 0;
  // Summed over the remeshed components (iterations: the largest; converged: all); its timings
  // over every attempt of every component tried, the ones that ended kept too.
  CvtStats cvt_stats;
  RemeshStats remesh_stats;                // summed
  double remesh_seconds = 0;               // the duals and their post-passes, every attempt
  std::size_t remeshed() const;
};

// "component I (N faces): reason" for each component kept as it was, in component order; how
// the app's notes and the Python package's warning name them (empty when all were remeshed).
std::vector<std::string> kept_components(const SurfaceRemeshResult& r);

// Throws InvalidInput for contradictory options (as compute_cvt) or a mesh without area.
SurfaceRemeshResult remesh_surface(const TriangleMesh& mesh, const SurfaceRemeshOptions& options);

}  // namespace gsp::cvt
