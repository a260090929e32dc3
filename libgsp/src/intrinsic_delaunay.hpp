#pragma once
// Intrinsic Delaunay flips (internal): edge flips that keep the surface's metric exactly (the
// two triangles are unfolded into the plane and the other diagonal measured), until every
// flippable edge is Delaunay. Slivers and fans become well-shaped triangles on the same
// surface with the same vertices, so one virtual source per face fits them far better.
//
// Orientation plays no part: soups wind their faces either way, and a flip only needs the
// six lengths of the two triangles. Before flipping, the faces are wound consistently across
// every two-face edge, so a soup with flipped faces yields the same intrinsic triangulation —
// and the same propagation — as the consistently wound mesh (tests/pointcloud_soup_test.cpp).
// Which of a patch's two windings: lengths cannot tell (the metric is mirror-symmetric), yet
// GSP's float rounding and near-tie decisions are not, so the choice shows in the distances
// (docs/gsp-core.md, "Intrinsic Delaunay flips"). With positions, a closed patch is wound outwards
// (positive signed volume, how benign meshes come); otherwise the winding most of its input
// faces have; on a tie, the signed volume about the patch's centroid, then its first face's.
#include <gsp/types.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace gsp::detail {

// One flip, as make_intrinsic_delaunay did it: faces f1 = (a, b, c) and f2 = (b, a, d) (as
// vertex sets) became (c, a, d) and (d, b, c), unfolded with a = (0, 0), b = (lab, 0), c =
// (cx, cy) above and d = (dx, dy) below. A point of f1 or f2 is found again in the new faces
// from this alone (flip_replay.hpp).
struct FlipRecord {
  Index f1, f2;
  Index a, b, c, d;
  double lab, cx, cy, dx, dy;
};

struct IntrinsicTriangulation {
  std::vector<Triangle> triangles;   // corner vertices
  std::vector<double> length;        // per halfedge 3f+i: |corner i -> corner i+1|
  std::vector<Index> ring;           // per halfedge: next halfedge on its edge (plain index)
  std::vector<bool> skipped;         // faces left out of the propagation
  const std::vector<Vec3>* positions = nullptr;   // optional: picks each patch's winding (above)
  std::size_t reoriented = 0;        // out: faces whose winding make_intrinsic_delaunay reversed
  std::vector<char> flipped;         // out: per face, whether a flip rewrote it (its lengths are new)
  std::vector<FlipRecord>* log = nullptr;   // out, when given: every flip in order
};

// Winds the faces consistently (see above; reversing keeps corner 0: (a, b, c) -> (a, c, b)),
// then flips in place; returns the number of flips. Only edges with exactly two non-skipped
// faces and two distinct opposite vertices are flipped, whatever the faces' winding.
std::size_t make_intrinsic_delaunay(IntrinsicTriangulation& t, std::size_t max_flips);

// The same result on two threads: the flips start on the faces as wound while the winding's
// last step (which patches face inwards: a pass or two over the positions) runs beside them.
// Where a patch is to be turned after all (a mesh wound inwards, or inconsistently wound: then
// everything as make_intrinsic_delaunay, on one thread), `again()` gives the unflipped
// triangulation once more and it is wound and flipped again. `wound`: the faces t was made
// with, read by the thread beside while the flips rewrite t's.
std::size_t make_intrinsic_delaunay_beside(IntrinsicTriangulation& t, std::size_t max_flips,
                                           const std::vector<Triangle>& wound,
                                           const std::function<IntrinsicTriangulation()>& again);

// The winding step alone; returns the number of faces reversed (also in t.reoriented).
std::size_t orient_consistently(IntrinsicTriangulation& t);

}  // namespace gsp::detail
