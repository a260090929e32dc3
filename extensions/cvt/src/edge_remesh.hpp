#pragma once
// A remesh of one component by edge operations: long edges split, short ones collapsed, edges
// flipped towards valence 6, vertices moved in their tangent planes and put back onto the
// input (Botsch and Kobbelt, "A remeshing approach to multiresolution modeling", 2004; the
// scheme of CGAL's isotropic_remeshing and pmp-library). remesh_component's last resort for a
// component whose CVT dual does not come out a manifold with its topology: the operations keep
// the topology by construction (a collapse only where OpenMesh's link-condition check allows
// it), so handles and walls thinner than a CVT region survive, at the cost of the CVT's even
// spacing (docs/cvt.md, "Edge operations where the dual fails").
//
// Why not CGAL's isotropic_remeshing: gsp::cvt is in the permissive part of the toolkit (CGAL
// is GPL and stays in gsp-cvt-compare). The connectivity operations and their checks are
// OpenMesh's (BSD); the loop around them, the geometric checks and the projection are ours.
#include "sizing_field.hpp"

#include <gsp/cvt/closest_point_index.hpp>
#include <gsp/mesh.hpp>

#include <cstddef>

namespace gsp::cvt::detail {

struct EdgeRemeshStats {
  std::size_t feature_edges = 0;   // crease edges of the input kept as feature lines (boundaries not counted)
  std::size_t splits = 0, collapses = 0, flips = 0;   // of the last pass
  std::size_t fold_refinements = 0;   // passes made again, refined where the one before folded
};

// `input`: a manifold, consistently oriented component; `surface` indexes `input` (the
// vertices are projected onto it). Edges are brought into [4/5, 4/3] x target_length over
// `iterations` rounds. Feature lines (boundaries, and crease curves, their faces' normals more
// than feature_angle_deg apart, at least two spacings long) stay chains of edges: their vertices move and collapse only along
// them, corners (where lines meet, end or turn by more than the feature angle) stay, and no
// feature edge is flipped. Returns an empty mesh where OpenMesh refuses one of the input's
// faces, the splits would pass max_vertices, or an input vertex ends farther than two
// spacings from the remesh (a fold onto one side of a thin part); the caller then keeps what
// it had. target_vertices > 0: the spacing is corrected in the first rounds so that the remesh
// ends near that many vertices. sizing: edges shorter where the input bends tightly
// (sizing_field.hpp); null: one spacing everywhere. A remesh that folds is made again up to
// `fold_refinements` times with the spacing halved around the input vertices it left farther
// than their spacing away (refine_around), and while such vertices are left after a pass that
// did not fold; the last pass that did not fold is returned.
TriangleMesh remesh_by_edge_operations(const TriangleMesh& input, const ClosestPointIndex& surface,
                                       double target_length, double feature_angle_deg, int iterations,
                                       std::size_t max_vertices, std::size_t target_vertices = 0,
                                       EdgeRemeshStats* stats = nullptr, const SizingOptions* sizing = nullptr,
                                       int fold_refinements = 2);

}  // namespace gsp::cvt::detail
