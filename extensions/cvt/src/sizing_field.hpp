#pragma once
// A sizing field for the remesh by edge operations (internal to gsp::cvt): per input vertex, the
// share of the uniform spacing L that an edge there should have, smaller where the surface bends
// tighter than L can follow (fingers, thin rods and handles narrower than an edge), 1
// elsewhere. With one spacing everywhere such parts fold onto one side of themselves and the
// remesh is refused (docs/cvt.md, "A sizing field for the edge remesh").
//
// The curvature across an input edge e is its dihedral angle over the width of its two faces,
// theta_e |e| / (A1 + A2) (exact for a cylinder tessellated in strips); an edge on a kept feature
// line is a crease, not a bend, and is left out. A vertex takes the largest of its edges', then
// the area-weighted mean over the input within L / 2 (so that a scan's noise at a scale far
// below L does not count, and a bend narrower than L does), and the size
// clamp(radians_per_edge / (kappa L), min_share, 1): an edge spans at most that angle of a
// bend. Then graded: no vertex's share exceeds a neighbour's by more than `gradation` times
// their distance over L (slowly varying sizes keep the triangles' angles). A part thinner than
// L with flat sides (an ear, a fin) reads as flat: it would need its thickness, not its bend.
#include <gsp/mesh.hpp>

#include <utility>
#include <vector>

namespace gsp::cvt::detail {

struct SizingOptions {
  double radians_per_edge = 1.0;   // an edge spans at most this angle of a bend
  double min_share = 0.25;         // of the spacing, at the tightest bends
  double gradation = 0.2;          // largest change of the share per spacing of distance
};

// `features`: the input's edges on kept feature lines (vertex pairs, either order). Returns one
// share per input vertex, in [min_share, 1].
std::vector<double> curvature_sizing(const TriangleMesh& input, const std::vector<std::pair<Index, Index>>& features,
                                     double spacing, const SizingOptions& options = {});

// Where a remesh folded onto one side of a part thinner than the spacing (an ear, a finger, a
// small handle: input vertices left far from it), the shares around the input vertices `far`
// are cut to `factor` times theirs and graded back at `gradation` per spacing of straight-line
// distance (both sides of a thin part are refined, as both need it); never below min_share.
// `share`: one per input vertex, an empty vector standing for 1 everywhere.
void refine_around(const TriangleMesh& input, const std::vector<Index>& far, double spacing, double factor,
                   double gradation, double min_share, std::vector<double>& share);

}  // namespace gsp::cvt::detail
