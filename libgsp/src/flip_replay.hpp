#pragma once
// Where a point of an input face lies on the intrinsic Delaunay triangulation. The flips keep
// the surface but not the faces, so a source given in an input face (Source::in_face) has no
// face of the flipped triangulation to be seeded in; GSP ran such queries on the input's own
// faces, and on a CAD export's slivers that cost accuracy: a source placed exactly at a vertex
// as a face point was up to 57% farther at some vertices than the same vertex as a vertex
// source (docs/benchmarks.md, "Sources inside faces"). Replaying the flips that touched the
// point's face, each in the plane of its two triangles (intrinsic_delaunay.hpp, FlipRecord),
// finds its face and weights there exactly (up to rounding). The solver runs the flips again
// with the log on at the first face-point query (GeodesicSolver::Impl::flip_replay), so vertex
// queries pay nothing for it.
#include "intrinsic_delaunay.hpp"

#include <gsp/types.hpp>

#include <array>
#include <vector>

namespace gsp::detail {

class FlipReplay {
 public:
  // `log`: make_intrinsic_delaunay's flips in order, on `num_faces` faces.
  FlipReplay(std::vector<FlipRecord> log, std::size_t num_faces);
  // The point with weights w at the corners of `face` (its corners as they were before any
  // flip: `corners`): its face after all flips, and its weights at that face's corners
  // (`flipped` gives them), >= 0 and summing to 1.
  std::pair<Index, std::array<double, 3>> locate(Index face, const Triangle& corners, const double w[3],
                                                 const std::vector<Triangle>& flipped) const;
  // Where input face `face` (corners as before any flip: `corners`) lies on the flipped faces:
  // the flipped face holding its point with weights `w`, and the face's own corners in that
  // face's plane as weights on its corners (`flipped` gives their order), of any sign, summing
  // to 1. Maps a point of that face's frame (a virtual source) back into the input face's plane.
  struct Frame {
    Index face;
    double corner[3][3];   // input corner c = sum_i corner[c][i] * flipped corner i
  };
  Frame frame(Index face, const Triangle& corners, const double w[3], const std::vector<Triangle>& flipped) const;
  // Whether a flip rewrote input face `face` (else it is a face of the flipped triangulation too).
  bool rewritten(Index face) const { return begin_[face] != begin_[face + 1]; }
  std::size_t bytes() const;

 private:
  // Follows `points` points of `face` (weights on `vert`) through the flips that rewrote it,
  // point 0 choosing the face; returns the last face, `vert` and `weight` rewritten for it.
  Index walk(Index face, Index vert[3], double (*weight)[3], int points) const;
  std::vector<FlipRecord> log_;
  std::vector<Index> begin_, flips_;   // per face: the flips that rewrote it, in order (CSR)
};

}  // namespace gsp::detail
